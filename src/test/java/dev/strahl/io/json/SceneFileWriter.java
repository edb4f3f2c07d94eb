package dev.strahl.io.json;

import dev.strahl.scene.TestScenes;
import dev.strahl.scene.Transform;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.util.DefaultPrettyPrinter;
import dev.strahl.scene.Camera;
import dev.strahl.image.Rgb;
import dev.strahl.io.json.SceneDescription.MaterialSpec;
import dev.strahl.io.json.SceneDescription.ShapeSpec;
import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import org.joml.Vector3dc;

/**
 * Writes a {@link SceneDescription} as a scene file that {@link JsonSceneReader} reads back to an
 * equal description: every key the description holds, and no default it does not.
 */
final class SceneFileWriter {
    private final JsonGenerator g;

    private SceneFileWriter(JsonGenerator g) {
        this.g = g;
    }

    static String write(SceneDescription d) {
        StringWriter out = new StringWriter();
        try (JsonGenerator g = new JsonFactory().createGenerator(out)) {
            g.setPrettyPrinter(new DefaultPrettyPrinter());
            new SceneFileWriter(g).scene(d);
        } catch (IOException e) {
            throw new UncheckedIOException(e);              // a StringWriter does not fail
        }
        return out.append('\n').toString();
    }

    private void scene(SceneDescription d) throws IOException {
        g.writeStartObject();
        if (d.camera() != null) {
            camera(d.camera(), d.media().camera());
        }
        settings(d.settings());
        g.writeObjectFieldStart("materials");
        for (var e : d.materials().entrySet()) {
            g.writeFieldName(e.getKey());
            material(e.getValue());
        }
        g.writeEndObject();
        if (!d.groups().isEmpty()) {
            g.writeObjectFieldStart("groups");
            for (var e : d.groups().entrySet()) {
                g.writeArrayFieldStart(e.getKey());
                for (ShapeSpec s : e.getValue()) {
                    shape(s, null);
                }
                g.writeEndArray();
            }
            g.writeEndObject();
        }
        g.writeArrayFieldStart("shapes");
        for (int i = 0; i < d.shapes().size(); i++) {
            shape(d.shapes().get(i), d.media().boundary(i));
        }
        g.writeEndArray();
        if (d.environment() != null && d.environment().radiance() != null) {
            g.writeFieldName("environment");
            rgb(d.environment().radiance());
        } else if (d.environment() != null) {
            g.writeObjectFieldStart("environment");
            g.writeStringField("type", "envmap");
            g.writeStringField("file", d.environment().file());
            g.writeNumberField("scale", d.environment().scale());
            g.writeNumberField("rotate", d.environment().rotate());
            g.writeEndObject();
        }
        if (!d.lights().isEmpty()) {
            g.writeArrayFieldStart("lights");
            for (SceneLights.Light l : d.lights()) {
                light(l);
            }
            g.writeEndArray();
        }
        if (!d.media().media().isEmpty()) {
            g.writeObjectFieldStart("media");
            for (var e : d.media().media().entrySet()) {
                medium(e.getKey(), e.getValue());
            }
            g.writeEndObject();
        }
        g.writeEndObject();
    }

    private void medium(String name, SceneFileMedia.Medium m) throws IOException {
        g.writeObjectFieldStart(name);
        g.writeStringField("type", m.type());
        if (m.sigmaT() != null) {
            g.writeFieldName("sigmaT");
            rgb(m.sigmaT());
        } else {
            g.writeStringField("file", m.file());
            if (m.min() != null) {
                g.writeArrayFieldStart("bounds");
                vector(m.min());
                vector(m.max());
                g.writeEndArray();
            }
        }
        g.writeNumberField("scale", m.scale());
        g.writeFieldName("albedo");
        rgb(m.albedo());
        g.writeNumberField("g", m.g());
        g.writeEndObject();
    }

    private void light(SceneLights.Light l) throws IOException {
        g.writeStartObject();
        g.writeStringField("type", l.type());
        if (l.position() != null) {
            g.writeFieldName("position");
            vector(l.position());
        }
        if (l.direction() != null) {
            g.writeFieldName("direction");
            vector(l.direction());
        }
        g.writeFieldName(l.type().equals("directional") ? "irradiance" : "intensity");
        rgb(l.intensity());
        if (l.type().equals("spot")) {
            g.writeNumberField("innerCone", l.innerCone());
            g.writeNumberField("outerCone", l.outerCone());
        }
        g.writeEndObject();
    }

    private void camera(Camera c, String medium) throws IOException {
        g.writeObjectFieldStart("camera");
        g.writeFieldName("lookFrom");
        vector(c.lookFrom());
        g.writeFieldName("lookAt");
        vector(c.lookAt());
        g.writeFieldName("up");
        vector(c.up());
        g.writeNumberField("fov", c.fovDegrees());
        g.writeNumberField("aperture", c.aperture());
        g.writeNumberField("focusDistance", c.focusDistance());
        if (medium != null) {
            g.writeStringField("medium", medium);
        }
        g.writeEndObject();
    }

    private void settings(SceneSettings s) throws IOException {
        if (s.width() != null || s.height() != null || s.aovs() != null) {
            g.writeObjectFieldStart("film");
            if (s.width() != null) {
                g.writeNumberField("width", s.width());
            }
            if (s.height() != null) {
                g.writeNumberField("height", s.height());
            }
            if (s.aovs() != null) {
                g.writeArrayFieldStart("aovs");
                for (var aov : new java.util.TreeSet<>(s.aovs())) {
                    g.writeString(aov.id());
                }
                g.writeEndArray();
            }
            g.writeEndObject();
        }
        if (s.integrator() == null && s.samplesPerPixel() == null && s.maxDepth() == null && s.seed() == null
                && s.lightSamples() == null && s.hemisphere() == null && s.photons() == null && s.photonRadius() == null && s.noiseThreshold() == null) {
            return;
        }
        g.writeObjectFieldStart("integrator");
        if (s.integrator() != null) {
            g.writeStringField("type", s.integrator().id());
        }
        if (s.samplesPerPixel() != null) {
            g.writeNumberField("spp", s.samplesPerPixel());
        }
        if (s.maxDepth() != null) {
            g.writeNumberField("maxDepth", s.maxDepth());
        }
        if (s.seed() != null) {
            g.writeNumberField("seed", s.seed());
        }
        if (s.lightSamples() != null) {
            g.writeNumberField("lightSamples", s.lightSamples());
        }
        if (s.hemisphere() != null) {
            g.writeStringField("hemisphere", s.hemisphere().name().toLowerCase(java.util.Locale.ROOT));
        }
        if (s.photons() != null) {
            g.writeNumberField("photons", s.photons());
        }
        if (s.photonRadius() != null) {
            g.writeNumberField("photonRadius", s.photonRadius());
        }
        if (s.noiseThreshold() != null) {
            g.writeNumberField("noiseThreshold", s.noiseThreshold());
        }
        g.writeEndObject();
    }

    private void material(MaterialSpec m) throws IOException {
        g.writeStartObject();
        if (m instanceof SceneDescription.Null) {
            g.writeStringField("type", "null");
        } else if (m instanceof SceneDescription.Diffuse d) {
            g.writeStringField("type", "diffuse");
            g.writeFieldName("albedo");
            colour(d.albedo());
            emission(d.emission());
        } else if (m instanceof SceneDescription.Mirror r) {
            g.writeStringField("type", "mirror");
            g.writeFieldName("reflectance");
            rgb(r.reflectance());
        } else if (m instanceof SceneDescription.Dielectric d) {
            g.writeStringField("type", "dielectric");
            g.writeNumberField("ior", d.ior());
            g.writeFieldName("alpha");
            number(d.alpha());
        } else if (m instanceof SceneDescription.Conductor c) {
            g.writeStringField("type", "conductor");
            if (c.preset() != null) {
                g.writeStringField("preset", c.preset());
            } else {
                g.writeFieldName("eta");
                rgb(c.eta());
                g.writeFieldName("k");
                rgb(c.k());
            }
            g.writeFieldName("alpha");
            number(c.alpha());
        } else if (m instanceof SceneDescription.Principled p) {
            g.writeStringField("type", "principled");
            g.writeFieldName("baseColor");
            colour(p.baseColor());
            g.writeFieldName("metallic");
            number(p.metallic());
            g.writeFieldName("roughness");
            number(p.roughness());
            g.writeFieldName("specular");
            number(p.specular());
            g.writeFieldName("specularColor");
            colour(p.specularColor());
            g.writeFieldName("transmission");
            number(p.transmission());
            g.writeNumberField("ior", p.ior());
            emission(p.emission());
            g.writeNumberField("emissionStrength", p.emissionStrength());
        } else {
            SceneDescription.Glossy gl = (SceneDescription.Glossy) m;
            g.writeStringField("type", "glossy");
            g.writeFieldName("diffuse");
            rgb(gl.diffuse());
            g.writeFieldName("specular");
            rgb(gl.specular());
            g.writeNumberField("exponent", gl.exponent());
            emission(gl.emission());
        }
        g.writeEndObject();
    }

    /** A colour, or its texture object (whose fallback value is then the reader's default). */
    private void colour(SceneDescription.ColorParam c) throws IOException {
        if (c.texture() == null) {
            rgb(c.value());
        } else {
            texture(c.texture(), true);
        }
    }

    private void number(SceneDescription.NumberParam n) throws IOException {
        if (n.texture() == null) {
            g.writeNumber(n.value());
        } else {
            texture(n.texture(), false);
        }
    }

    private void texture(SceneDescription.TextureRef t, boolean colour) throws IOException {
        g.writeStartObject();
        g.writeStringField("texture", t.file());
        if (t.scaleU() != 1 || t.scaleV() != 1) {
            g.writeFieldName("uvScale");
            g.writeArray(new double[] {t.scaleU(), t.scaleV()}, 0, 2);
        }
        if (colour && t.linear()) {
            g.writeBooleanField("linear", true);
        }
        g.writeEndObject();
    }

    private void emission(Rgb e) throws IOException {
        if (!e.isBlack()) {
            g.writeFieldName("emission");
            rgb(e);
        }
    }

    private void shape(ShapeSpec shape, SceneFileMedia.Boundary boundary) throws IOException {
        g.writeStartObject();
        if (shape instanceof SceneDescription.SphereShape s) {
            g.writeStringField("type", "sphere");
            g.writeFieldName("center");
            vector(s.center());
            g.writeNumberField("radius", s.radius());
            g.writeStringField("material", s.material());
        } else if (shape instanceof SceneDescription.InstanceShape i) {
            g.writeStringField("type", "instance");
            g.writeStringField("group", i.group());
        } else if (shape instanceof SceneDescription.MeshShape m) {
            g.writeStringField("type", "mesh");
            g.writeStringField("file", m.file());
            if (m.material() != null) {
                g.writeStringField("material", m.material());
            }
        } else {
            SceneDescription.TrianglesShape t = (SceneDescription.TrianglesShape) shape;
            g.writeStringField("type", "triangles");
            g.writeFieldName("positions");
            floats(t.positions());
            g.writeFieldName("indices");
            g.writeArray(t.indices(), 0, t.indices().length);
            if (t.normals() != null) {
                g.writeFieldName("normals");
                floats(t.normals());
            }
            if (t.uvs() != null) {
                g.writeFieldName("uvs");
                floats(t.uvs());
            }
            g.writeStringField("material", t.material());
        }
        if (!shape.transform().isIdentity()) {
            transform(shape.transform());
        }
        if (boundary != null && boundary.interior() != null) {
            g.writeStringField("interior", boundary.interior());
        }
        if (boundary != null && boundary.exterior() != null) {
            g.writeStringField("exterior", boundary.exterior());
        }
        g.writeEndObject();
    }

    private void transform(Transform t) throws IOException {
        g.writeArrayFieldStart("transform");
        for (TestScenes.Step s : TestScenes.steps(t)) {
            g.writeStartObject();
            switch (s.kind()) {
                case "translate" -> {
                    g.writeFieldName("translate");
                    g.writeArray(new double[] {s.x(), s.y(), s.z()}, 0, 3);
                }
                case "scale" -> {
                    if (s.x() == s.y() && s.y() == s.z()) {
                        g.writeNumberField("scale", s.x());
                    } else {
                        g.writeFieldName("scale");
                        g.writeArray(new double[] {s.x(), s.y(), s.z()}, 0, 3);
                    }
                }
                default -> {
                    g.writeObjectFieldStart("rotate");
                    g.writeFieldName("axis");
                    g.writeArray(new double[] {s.x(), s.y(), s.z()}, 0, 3);
                    g.writeNumberField("degrees", s.degrees());
                    g.writeEndObject();
                }
            }
            g.writeEndObject();
        }
        g.writeEndArray();
    }

    /** Floats in their shortest form where that reads back to the same float, else exactly. */
    private void floats(float[] values) throws IOException {
        g.writeStartArray();
        for (float f : values) {
            String shortest = Float.toString(f);
            if ((float) Double.parseDouble(shortest) == f) {
                g.writeNumber(shortest);
            } else {
                g.writeNumber((double) f);
            }
        }
        g.writeEndArray();
    }

    private void vector(Vector3dc v) throws IOException {
        g.writeArray(new double[] {v.x(), v.y(), v.z()}, 0, 3);
    }

    private void rgb(Rgb c) throws IOException {
        g.writeArray(new double[] {c.r(), c.g(), c.b()}, 0, 3);
    }
}
