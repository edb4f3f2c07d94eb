package dev.strahl.cli;

import com.fasterxml.jackson.core.JsonGenerator;
import dev.strahl.accel.Simd;
import dev.strahl.io.json.JsonFile;
import dev.strahl.render.Aov;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.world.World;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

/**
 * The figures of one render for tools ({@code render --stats FILE.json}). Render time excludes
 * loading and the BVH build, which are reported separately: {@code load_seconds} is reading and
 * building the scene without the BVH, {@code bvh_build_seconds} the BVH build, {@code texture_bytes}
 * the memory of the texture images (each file once). {@code spp_min}, {@code spp_mean} and {@code spp_max} are the
 * samples the pixels took (equal without a noise threshold), {@code converged_fraction} the share of pixels a noise
 * threshold found converged (0 without one), {@code passes} the passes over the image. {@code settings} holds every setting by the
 * name checkpoints and cluster members know it by ({@link RenderSettings#entries()}).
 */
final class StatsFile {
    private StatsFile() {}

    /** A cluster render's figures per member ({@link RenderStats#members()}) are an object each with numbers (docs/cluster.md). */
    static void write(Path file, RenderStats stats, RenderSettings settings, double loadSeconds, double bvhBuildSeconds, long textureBytes)
            throws IOException {
        write(file, stats, settings, loadSeconds, bvhBuildSeconds, textureBytes, null);
    }

    /**
     * With the scene's figures (null: none): its triangles stored (each group's once) and as
     * rendered (each instance's), its instances, and the bytes of its BVHs and primitives.
     */
    static void write(Path file, RenderStats stats, RenderSettings settings, double loadSeconds, double bvhBuildSeconds, long textureBytes,
                      World world) throws IOException {
        List<RenderStats.Member> members = stats.members();
        JsonFile.write(file, json -> {
            json.writeStartObject();
            json.writeNumberField("seconds", stats.seconds());
            json.writeNumberField("samples", stats.samples());
            json.writeNumberField("samples_per_second", stats.samplesPerSecond());
            json.writeNumberField("rays", stats.rays());
            json.writeNumberField("rays_per_second", stats.raysPerSecond());
            json.writeNumberField("threads", stats.threads());
            json.writeNumberField("width", settings.output().width());
            json.writeNumberField("height", settings.output().height());
            json.writeNumberField("spp", stats.samplesPerPixel());
            json.writeNumberField("spp_min", stats.minSamplesPerPixel());
            json.writeNumberField("spp_mean", stats.meanSamplesPerPixel());
            json.writeNumberField("spp_max", stats.maxSamplesPerPixel());
            json.writeNumberField("converged_fraction", stats.convergedFraction());
            json.writeNumberField("passes", stats.passes());
            json.writeNumberField("bvh_build_seconds", bvhBuildSeconds);
            json.writeNumberField("load_seconds", loadSeconds);
            if (!members.isEmpty()) {
                json.writeArrayFieldStart("members");
                for (RenderStats.Member m : members) {
                    json.writeStartObject();
                    json.writeStringField("member", m.member());
                    json.writeBooleanField("coordinator", m.coordinator());
                    json.writeNumberField("threads", m.threads());
                    json.writeNumberField("units", m.units());
                    json.writeNumberField("samples", m.samples());
                    json.writeNumberField("bytes_sent", m.bytesSent());
                    json.writeNumberField("bytes_received", m.bytesReceived());
                    json.writeNumberField("unit_seconds", m.unitSeconds());
                    json.writeNumberField("mean_unit_seconds", m.meanUnitSeconds());
                    json.writeNumberField("lost_units", m.lost());
                    json.writeEndObject();
                }
                json.writeEndArray();
            }
            json.writeNumberField("thread_idle_seconds", stats.threadIdleSeconds());
            json.writeStringField("accel", settings.execution().bruteForce() ? "none" : "bvh");
            json.writeStringField("kernel", settings.execution().bruteForce() ? "brute force" : "bvh8, " + Simd.describe(Simd.enabled()));
            json.writeStringField("schedule", settings.execution().stripes() ? "stripes" : "tiles");
            json.writeStringField("shadows", settings.transport().shadows() ? "on" : "off");
            json.writeStringField("light_selection", settings.transport().lightTree() ? "tree" : "power");
            json.writeNumberField("texture_bytes", textureBytes);
            if (world != null) {
                json.writeNumberField("triangles", world.uniqueTriangles());
                json.writeNumberField("triangles_instanced", world.instancedTriangles());
                json.writeNumberField("instances", world.instances().count());
                json.writeNumberField("bvh_bytes", world.bvh().byteSize());
                json.writeNumberField("geometry_bytes", world.byteSize() - world.bvh().byteSize());
            }
            json.writeObjectFieldStart("settings");
            for (var e : settings.entries().entrySet()) {
                writeValue(json, e.getKey(), e.getValue());
            }
            json.writeEndObject();
            json.writeEndObject();
        });
    }

    /** A setting as JSON: numbers and booleans as such, a set of feature buffers as an array of names, the rest as text. */
    private static void writeValue(JsonGenerator json, String name, Object value) throws IOException {
        if (value instanceof Integer || value instanceof Long) {
            json.writeNumberField(name, ((Number) value).longValue());
        } else if (value instanceof Double d) {
            json.writeNumberField(name, d);
        } else if (value instanceof Boolean b) {
            json.writeBooleanField(name, b);
        } else if (value instanceof Set<?> set) {
            json.writeArrayFieldStart(name);
            for (Object v : set) {
                json.writeString(((Aov) v).id());
            }
            json.writeEndArray();
        } else {
            json.writeStringField(name, String.valueOf(value));
        }
    }
}
