package dev.strahl.io.json;

import dev.strahl.image.Rgb;
import dev.strahl.io.json.SceneDescription.ColorParam;
import dev.strahl.io.json.SceneDescription.MaterialSpec;
import dev.strahl.io.json.SceneDescription.NumberParam;
import dev.strahl.io.json.SceneDescription.TextureRef;
import dev.strahl.scene.Material;
import dev.strahl.scene.SceneException;
import java.nio.file.Path;
import java.util.Map;
import java.util.Set;

/**
 * The {@code materials} of a scene file, one {@link MaterialSpec} each: the material types and
 * their keys, colours and numbers that may be textures, and every check, with errors naming the
 * file, the line and the key (as {@link JsonSceneReader} does for the rest of the file).
 */
final class JsonMaterials {
    /** The material types of the scene file and the keys each accepts (its schema: docs/scene.schema.json). */
    static final Map<String, Set<String>> MATERIAL_KEYS = Map.of(
            "diffuse", Set.of("type", "albedo", "emission"),
            "mirror", Set.of("type", "reflectance"),
            "dielectric", Set.of("type", "ior", "alpha"),
            "glossy", Set.of("type", "diffuse", "specular", "exponent", "emission"),
            "conductor", Set.of("type", "preset", "eta", "k", "alpha"),
            "principled", Set.of("type", "baseColor", "metallic", "roughness", "specular", "specularColor", "transmission", "ior", "emission",
                    "emissionStrength"), "null", Set.of("type"));
    /** The keys of a texture that stands in for a colour or a number. */
    static final Set<String> TEXTURE_KEYS = Set.of("texture", "uvScale", "linear");

    private final Path file;
    private final JsonValues v;

    JsonMaterials(Path file, JsonValues v) {
        this.file = file;
        this.v = v;
    }

    MaterialSpec material(String name, JsonNode node) throws SceneException {
        String key = "materials." + name;
        Map<String, JsonNode> m = v.object(node, key);
        String type = v.type(m, node, key, MATERIAL_KEYS.keySet(), "material", " for '" + key + "'", "");
        Set<String> keys = MATERIAL_KEYS.get(type);
        if (m.containsKey("emission") && !keys.contains("emission")) {
            throw new SceneException(file, m.get("emission").line, "'" + key + ".emission': a " + type
                    + " material cannot emit light; emission is allowed on diffuse, glossy and principled materials (a one-sided area light)");
        }
        v.allowOnly(m, key + " of type " + type, keys);
        switch (type) {
            case "null":
                return new SceneDescription.Null();
            case "mirror":
                return new SceneDescription.Mirror(m.containsKey("reflectance") ? v.unitColor(m.get("reflectance"), key + ".reflectance") : Rgb.WHITE);
            case "dielectric":
                return new SceneDescription.Dielectric(ior(m, key), numberParam(m, "alpha", key, 0, 0, Double.POSITIVE_INFINITY));
            case "conductor": {
                NumberParam alpha = numberParam(m, "alpha", key, 0, 0, Double.POSITIVE_INFINITY);
                if (m.containsKey("preset")) {
                    if (m.containsKey("eta") || m.containsKey("k")) {
                        throw new SceneException(file, m.get("preset").line, "'" + key + "': give either 'preset' or 'eta' and 'k', not both");
                    }
                    String preset = v.string(m.get("preset"), key + ".preset");
                    if (!Material.conductorPresets().contains(preset)) {
                        throw new SceneException(file, m.get("preset").line, "'" + key + ".preset': unknown conductor '" + preset + "' (known: "
                                + JsonValues.sorted(Material.conductorPresets()) + ")");
                    }
                    return new SceneDescription.Conductor(preset, null, null, alpha);
                }
                if (!m.containsKey("eta") || !m.containsKey("k")) {
                    throw new SceneException(file, node.line, "'" + key + "' needs a 'preset' (" + JsonValues.sorted(Material.conductorPresets())
                            + ") or both 'eta' and 'k'");
                }
                Rgb eta = v.color(m.get("eta"), key + ".eta");
                if (!(eta.r() > 0 && eta.g() > 0 && eta.b() > 0)) {
                    throw new SceneException(file, m.get("eta").line, "'" + key + ".eta' must be positive in every channel, got " + eta);
                }
                return new SceneDescription.Conductor(null, eta, v.color(m.get("k"), key + ".k"), alpha);
            }
            case "principled":
                return new SceneDescription.Principled(colorParam(m, "baseColor", key, Rgb.WHITE, true),
                        numberParam(m, "metallic", key, 1, 0, 1), numberParam(m, "roughness", key, 1, 0, 1),
                        numberParam(m, "specular", key, 1, 0, 1), colorParam(m, "specularColor", key, Rgb.WHITE, false),
                        numberParam(m, "transmission", key, 0, 0, 1), ior(m, key), emission(m, key),
                        m.containsKey("emissionStrength") ? nonNegative(m.get("emissionStrength"), key + ".emissionStrength") : 1);
            case "glossy": {
                Rgb kd = m.containsKey("diffuse") ? v.unitColor(m.get("diffuse"), key + ".diffuse") : Rgb.BLACK;
                Rgb ks = v.unitColor(v.require(m, "specular", node), key + ".specular");
                double ns = v.number(v.require(m, "exponent", node), key + ".exponent");
                if (!(ns >= 0)) {
                    throw new SceneException(file, m.get("exponent").line, "'" + key + ".exponent' must be >= 0, got " + JsonValues.format(ns));
                }
                return new SceneDescription.Glossy(kd, ks, ns, emission(m, key));
            }
            default:
                return new SceneDescription.Diffuse(colorParam(m, "albedo", key, Rgb.gray(0.8), true), emission(m, key));
        }
    }

    private double ior(Map<String, JsonNode> m, String key) throws SceneException {
        if (!m.containsKey("ior")) {
            return 1.5;
        }
        double ior = v.number(m.get("ior"), key + ".ior");
        if (!(ior > 0)) {
            throw new SceneException(file, m.get("ior").line, "'" + key + ".ior' must be positive, got " + JsonValues.format(ior));
        }
        return ior;
    }

    private double nonNegative(JsonNode node, String key) throws SceneException {
        double x = v.number(node, key);
        if (!(x >= 0)) {
            throw new SceneException(file, node.line, "'" + key + "' must be >= 0, got " + JsonValues.format(x));
        }
        return x;
    }

    /** A colour (in [0, 1] if {@code unit}) or a texture object; {@code fallback} without the key. */
    private ColorParam colorParam(Map<String, JsonNode> m, String name, String key, Rgb fallback, boolean unit) throws SceneException {
        JsonNode node = m.get(name);
        if (node == null) {
            return ColorParam.of(fallback);
        }
        if (node.value instanceof Map) {
            return new ColorParam(fallback, textureRef(node, key + "." + name, true));
        }
        return ColorParam.of(unit ? v.unitColor(node, key + "." + name) : v.color(node, key + "." + name));
    }

    /** A number in [min, max] or a texture object; {@code fallback} without the key. */
    private NumberParam numberParam(Map<String, JsonNode> m, String name, String key, double fallback, double min, double max) throws SceneException {
        JsonNode node = m.get(name);
        if (node == null) {
            return NumberParam.of(fallback);
        }
        if (node.value instanceof Map) {
            return new NumberParam(fallback, textureRef(node, key + "." + name, false));
        }
        double x = v.number(node, key + "." + name);
        if (!(x >= min && x <= max)) {
            throw new SceneException(file, node.line, "'" + key + "." + name + "' must lie in [" + JsonValues.format(min) + ", "
                    + (max == Double.POSITIVE_INFINITY ? "∞)" : JsonValues.format(max) + "]") + ", got " + JsonValues.format(x));
        }
        return NumberParam.of(x);
    }

    private TextureRef textureRef(JsonNode node, String key, boolean colour) throws SceneException {
        Map<String, JsonNode> t = v.object(node, key);
        v.allowOnly(t, key, colour ? TEXTURE_KEYS : Set.of("texture", "uvScale"));
        String name = v.string(v.require(t, "texture", node), key + ".texture");       // PNG or JPEG: told by content when read
        double su = 1, sv = 1;
        if (t.containsKey("uvScale")) {
            double[] s = v.numbers(t.get("uvScale"), key + ".uvScale", 2);
            if (!Double.isFinite(s[0]) || !Double.isFinite(s[1]) || s[0] == 0 || s[1] == 0) {
                throw new SceneException(file, t.get("uvScale").line, "'" + key + ".uvScale' must be two finite, non-zero numbers");
            }
            su = s[0];
            sv = s[1];
        }
        boolean linear = false;
        if (t.containsKey("linear")) {
            if (!(t.get("linear").value instanceof Boolean b)) {
                throw new SceneException(file, t.get("linear").line, "'" + key + ".linear' must be true or false");
            }
            linear = b;
        }
        return new TextureRef(name, su, sv, linear);
    }

    private Rgb emission(Map<String, JsonNode> m, String key) throws SceneException {
        return m.containsKey("emission") ? v.color(m.get("emission"), key + ".emission") : Rgb.BLACK;
    }
}
