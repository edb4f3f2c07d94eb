package dev.strahl.scene;

import dev.strahl.camera.Camera;
import dev.strahl.geometry.Sphere;
import dev.strahl.material.Material;
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
        Map<String, JsonNode> m = object(node, "materials." + name);
        allowOnly(m, "materials." + name, Set.of("type", "albedo", "emission"));
        String type = string(require(m, "type", node), "materials." + name + ".type");
        if (!type.equals("diffuse")) {
            throw new SceneException(file, m.get("type").line, "unknown material type '" + type + "' for 'materials." + name + "' (known: diffuse)");
        }
        Rgb albedo = m.containsKey("albedo") ? color(m.get("albedo"), "materials." + name + ".albedo") : Rgb.gray(0.8);
        if (albedo.max() > 1) {
            throw new SceneException(file, m.get("albedo").line, "'materials." + name + ".albedo' must lie in [0, 1], got " + albedo);
        }
        Rgb emission = m.containsKey("emission") ? color(m.get("emission"), "materials." + name + ".emission") : Rgb.BLACK;
        return Material.emissive(name, albedo, emission);
    }

    private void shape(JsonNode node, Scene.Builder builder) throws SceneException {
        Map<String, JsonNode> s = object(node, "shapes[]");
        String type = string(require(s, "type", node), "shapes[].type");
        switch (type) {
            case "obj": {
                allowOnly(s, "shapes[] of type obj", Set.of("type", "file"));
                String name = string(require(s, "file", node), "shapes[].file");
                Path obj = file.toAbsolutePath().getParent().resolve(name);
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
