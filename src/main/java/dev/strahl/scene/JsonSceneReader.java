package dev.strahl.scene;

import dev.strahl.camera.Camera;
import dev.strahl.geometry.Sphere;
import dev.strahl.material.Dielectric;
import dev.strahl.material.Glossy;
import dev.strahl.material.Material;
import dev.strahl.material.Mirror;
import dev.strahl.math.Rgb;
import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.joml.Vector3d;

/**
 * Reads a strahl scene file (JSON; documented in docs/scene-format.md). Strict: unknown keys,
 * wrong types and missing required keys are errors naming the file, line and key.
 */
final class JsonSceneReader {
    /** The material types of the scene file and the keys each accepts. */
    private static final Map<String, Set<String>> MATERIAL_KEYS = Map.of(
            "diffuse", Set.of("type", "albedo", "emission"),
            "mirror", Set.of("type", "reflectance"),
            "dielectric", Set.of("type", "ior"),
            "glossy", Set.of("type", "diffuse", "specular", "exponent", "emission"));

    private final Path file;
    private final Map<String, Material> materials = new HashMap<>();

    private JsonSceneReader(Path file) {
        this.file = file;
    }

    static Scene read(Path file) throws SceneException {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (CharacterCodingException e) {
            throw new SceneException(file, ObjReader.TextLines.lineOfInvalidUtf8(file, 1), "not a text scene file (invalid UTF-8)");
        } catch (IOException e) {
            throw SceneLoader.cannotRead(file, e);
        }
        return new JsonSceneReader(file).scene(JsonNode.parse(file, text));
    }

    private Scene scene(JsonNode root) throws SceneException {
        Map<String, JsonNode> top = object(root, "scene");
        allowOnly(top, "scene", Set.of("camera", "materials", "shapes", "environment"));
        Scene.Builder builder = Scene.builder();
        if (top.containsKey("materials")) {
            for (var e : object(top.get("materials"), "materials").entrySet()) {
                materials.put(e.getKey(), material(e.getKey(), e.getValue()));
            }
        }
        JsonNode shapes = require(top, "shapes", root);
        List<JsonNode> list = array(shapes, "shapes");
        if (list.isEmpty()) {
            throw new SceneException(file, shapes.line, "'shapes' is empty: the scene has no geometry");
        }
        for (JsonNode shape : list) {
            shape(shape, builder);
        }
        if (top.containsKey("camera")) {
            builder.camera(camera(top.get("camera")));
        }
        if (top.containsKey("environment")) {
            builder.environment(color(top.get("environment"), "environment"));
        }
        return builder.build();
    }

    private Material material(String name, JsonNode node) throws SceneException {
        String key = "materials." + name;
        Map<String, JsonNode> m = object(node, key);
        String type = string(require(m, "type", node), key + ".type");
        Set<String> keys = MATERIAL_KEYS.get(type);
        if (keys == null) {
            throw new SceneException(file, m.get("type").line, "unknown material type '" + type + "' for '" + key
                    + "' (known: " + String.join(", ", MATERIAL_KEYS.keySet().stream().sorted().toList()) + ")");
        }
        if (m.containsKey("emission") && !keys.contains("emission")) {
            throw new SceneException(file, m.get("emission").line, "'" + key + ".emission': a " + type
                    + " material cannot emit light; emission is allowed on diffuse and glossy materials (a one-sided area light)");
        }
        allowOnly(m, key + " of type " + type, keys);
        switch (type) {
            case "mirror": {
                Rgb reflectance = m.containsKey("reflectance") ? unitColor(m.get("reflectance"), key + ".reflectance") : Rgb.WHITE;
                return new Material(name, new Mirror(reflectance), Rgb.BLACK);
            }
            case "dielectric": {
                double ior = 1.5;
                if (m.containsKey("ior")) {
                    ior = number(m.get("ior"), key + ".ior");
                    if (!(ior > 0)) {
                        throw new SceneException(file, m.get("ior").line, "'" + key + ".ior' must be positive, got " + format(ior));
                    }
                }
                return new Material(name, new Dielectric(ior), Rgb.BLACK);
            }
            case "glossy": {
                Rgb kd = m.containsKey("diffuse") ? unitColor(m.get("diffuse"), key + ".diffuse") : Rgb.BLACK;
                Rgb ks = unitColor(require(m, "specular", node), key + ".specular");
                double ns = number(require(m, "exponent", node), key + ".exponent");
                if (!(ns >= 0)) {
                    throw new SceneException(file, m.get("exponent").line, "'" + key + ".exponent' must be >= 0, got " + format(ns));
                }
                return new Material(name, Glossy.fromPhongExponent(kd, ks, ns), emission(m, key));
            }
            default: {
                Rgb albedo = m.containsKey("albedo") ? unitColor(m.get("albedo"), key + ".albedo") : Rgb.gray(0.8);
                return Material.emissive(name, albedo, emission(m, key));
            }
        }
    }

    private Rgb emission(Map<String, JsonNode> m, String key) throws SceneException {
        return m.containsKey("emission") ? color(m.get("emission"), key + ".emission") : Rgb.BLACK;
    }

    /** A colour with every channel in [0, 1] (a reflectance). */
    private Rgb unitColor(JsonNode node, String key) throws SceneException {
        Rgb c = color(node, key);
        if (c.max() > 1) {
            throw new SceneException(file, node.line, "'" + key + "' must lie in [0, 1], got " + c);
        }
        return c;
    }

    /** A number as a user wrote it: 0 rather than 0.0. */
    private static String format(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    private void shape(JsonNode node, Scene.Builder builder) throws SceneException {
        Map<String, JsonNode> s = object(node, "shapes[]");
        String type = string(require(s, "type", node), "shapes[].type");
        switch (type) {
            case "obj": {
                allowOnly(s, "shapes[] of type obj", Set.of("type", "file"));
                String name = string(require(s, "file", node), "shapes[].file");
                Path obj;
                try {
                    obj = file.toAbsolutePath().getParent().resolve(name);
                } catch (java.nio.file.InvalidPathException e) {
                    throw new SceneException(file, s.get("file").line, "'shapes[].file' is not a valid file name: " + e.getReason());
                }
                if (!Files.isRegularFile(obj)) {
                    throw new SceneException(file, s.get("file").line, "OBJ file not found: " + obj);
                }
                SceneLoader.addObj(obj, builder);
                break;
            }
            case "sphere": {
                allowOnly(s, "shapes[] of type sphere", Set.of("type", "center", "radius", "material"));
                Vector3d center = vector(require(s, "center", node), "shapes[].center");
                double radius = number(require(s, "radius", node), "shapes[].radius");
                if (!(radius > 0)) {
                    throw new SceneException(file, s.get("radius").line, "'shapes[].radius' must be positive, got " + radius);
                }
                JsonNode mNode = require(s, "material", node);
                String mName = string(mNode, "shapes[].material");
                Material m = materials.get(mName);
                if (m == null) {
                    throw new SceneException(file, mNode.line, "unknown material '" + mName + "' (define it under 'materials')");
                }
                builder.addSphere(new Sphere(center, radius), m);
                break;
            }
            default:
                throw new SceneException(file, s.get("type").line, "unknown shape type '" + type + "' (known: obj, sphere)");
        }
    }

    private Camera camera(JsonNode node) throws SceneException {
        Map<String, JsonNode> c = object(node, "camera");
        allowOnly(c, "camera", Set.of("lookFrom", "lookAt", "up", "fov"));
        Vector3d from = vector(require(c, "lookFrom", node), "camera.lookFrom");
        Vector3d at = vector(require(c, "lookAt", node), "camera.lookAt");
        Vector3d up = c.containsKey("up") ? vector(c.get("up"), "camera.up") : new Vector3d(0, 1, 0);
        double fov = c.containsKey("fov") ? number(c.get("fov"), "camera.fov") : 40;
        try {
            return new Camera(from, at, up, fov);
        } catch (IllegalArgumentException e) {
            throw new SceneException(file, node.line, "bad 'camera': " + e.getMessage());
        }
    }

    // --- typed access with messages that name the key and line ---

    private Map<String, JsonNode> object(JsonNode node, String key) throws SceneException {
        if (!node.isObject()) {
            throw new SceneException(file, node.line, "'" + key + "' must be an object, got " + node.typeName());
        }
        return node.object();
    }

    private List<JsonNode> array(JsonNode node, String key) throws SceneException {
        if (!(node.value instanceof List)) {
            throw new SceneException(file, node.line, "'" + key + "' must be an array, got " + node.typeName());
        }
        return node.array();
    }

    private String string(JsonNode node, String key) throws SceneException {
        if (!(node.value instanceof String s)) {
            throw new SceneException(file, node.line, "'" + key + "' must be a string, got " + node.typeName());
        }
        return s;
    }

    private double number(JsonNode node, String key) throws SceneException {
        if (!(node.value instanceof Double d)) {
            throw new SceneException(file, node.line, "'" + key + "' must be a number, got " + node.typeName());
        }
        if (!Double.isFinite(d)) {
            throw new SceneException(file, node.line, "'" + key + "' must be finite, got " + d);
        }
        return d;
    }

    private double[] numbers(JsonNode node, String key, int count) throws SceneException {
        List<JsonNode> list = array(node, key);
        if (list.size() != count) {
            throw new SceneException(file, node.line, "'" + key + "' must have " + count + " numbers, got " + list.size());
        }
        double[] v = new double[count];
        for (int i = 0; i < count; i++) {
            v[i] = number(list.get(i), key + "[" + i + "]");
        }
        return v;
    }

    private Vector3d vector(JsonNode node, String key) throws SceneException {
        double[] v = numbers(node, key, 3);
        return new Vector3d(v[0], v[1], v[2]);
    }

    private Rgb color(JsonNode node, String key) throws SceneException {
        double[] v = numbers(node, key, 3);
        if (v[0] < 0 || v[1] < 0 || v[2] < 0) {
            throw new SceneException(file, node.line, "'" + key + "' must not be negative");
        }
        return new Rgb(v[0], v[1], v[2]);
    }

    private JsonNode require(Map<String, JsonNode> map, String key, JsonNode parent) throws SceneException {
        JsonNode n = map.get(key);
        if (n == null) {
            throw new SceneException(file, parent.line, "missing required key '" + key + "'");
        }
        return n;
    }

    private void allowOnly(Map<String, JsonNode> map, String where, Set<String> keys) throws SceneException {
        for (var e : map.entrySet()) {
            if (!keys.contains(e.getKey())) {
                throw new SceneException(file, e.getValue().line, "unknown key '" + e.getKey() + "' in " + where + " (known: " + String.join(", ", keys.stream().sorted().toList()) + ")");
            }
        }
    }
}
