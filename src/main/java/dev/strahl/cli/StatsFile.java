package dev.strahl.cli;

import com.fasterxml.jackson.core.JsonGenerator;
import dev.strahl.accel.Simd;
import dev.strahl.io.json.JsonFile;
import dev.strahl.render.Aov;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

/**
 * The figures of one render for tools ({@code render --stats FILE.json}). Render time excludes
 * loading and the BVH build, which are reported separately: {@code load_seconds} is reading and
 * building the scene without the BVH, {@code bvh_build_seconds} the BVH build, {@code texture_bytes}
 * the memory of the texture images (each file once). {@code settings} holds every setting by the
 * name checkpoints and cluster members know it by ({@link RenderSettings#entries()}).
 */
final class StatsFile {
    private StatsFile() {}

    /** A cluster render's figures per member ({@link RenderStats#members()}) are an object each with numbers (docs/cluster.md). */
    static void write(Path file, RenderStats stats, RenderSettings settings, double loadSeconds, double bvhBuildSeconds, long textureBytes)
            throws IOException {
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
            json.writeNumberField("texture_bytes", textureBytes);
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
