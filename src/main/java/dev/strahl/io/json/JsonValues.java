package dev.strahl.io.json;

import dev.strahl.scene.SceneException;
import dev.strahl.image.Rgb;
import java.nio.file.Path;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.joml.Vector3d;

/**
 * Typed access to the values of a scene file, with errors that name the file, the line and the
 * key: {@code 'camera.fov' must be a number, got a string}.
 */
final class JsonValues {
    private final Path file;

    JsonValues(Path file) {
        this.file = file;
    }

    SceneException error(JsonNode node, String message) {
        return new SceneException(file, node.line, message);
    }

    Map<String, JsonNode> object(JsonNode node, String key) throws SceneException {
        if (!node.isObject()) {
            throw error(node, "'" + key + "' must be an object, got " + node.typeName());
        }
        return node.object();
    }

    List<JsonNode> array(JsonNode node, String key) throws SceneException {
        if (!(node.value instanceof List)) {
            throw error(node, "'" + key + "' must be an array, got " + node.typeName());
        }
        return node.array();
    }

    String string(JsonNode node, String key) throws SceneException {
        if (!(node.value instanceof String s)) {
            throw error(node, "'" + key + "' must be a string, got " + node.typeName());
        }
        return s;
    }

    double number(JsonNode node, String key) throws SceneException {
        if (node.value instanceof Long l) {
            return l;
        }
        if (!(node.value instanceof Double d)) {
            throw error(node, "'" + key + "' must be a number, got " + node.typeName());
        }
        if (!Double.isFinite(d)) {
            throw error(node, "'" + key + "' must be finite, got " + d);
        }
        return d;
    }

    /** A whole number (also written as 64.0) in [min, max]. */
    int integer(JsonNode node, String key, int min, int max) throws SceneException {
        long n = longInteger(node, key);
        if (n < min || n > max) {
            throw error(node, "'" + key + "' must be " + (max == Integer.MAX_VALUE ? ">= " + min : "in [" + min + ", " + max + "]") + ", got " + n);
        }
        return (int) n;
    }

    long longInteger(JsonNode node, String key) throws SceneException {
        if (node.value instanceof Long l) {
            return l;
        }
        double d = number(node, key);
        if (d != Math.rint(d) || Math.abs(d) >= 0x1p63) {
            throw error(node, "'" + key + "' must be a whole number, got " + format(d));
        }
        return (long) d;
    }

    double[] numbers(JsonNode node, String key, int count) throws SceneException {
        List<JsonNode> list = array(node, key);
        if (list.size() != count) {
            throw error(node, "'" + key + "' must have " + count + " numbers, got " + list.size());
        }
        double[] v = new double[count];
        for (int i = 0; i < count; i++) {
            v[i] = number(list.get(i), key + "[" + i + "]");
        }
        return v;
    }

    /** An array of any length of numbers, as floats. */
    float[] floats(JsonNode node, String key) throws SceneException {
        List<JsonNode> list = array(node, key);
        float[] v = new float[list.size()];
        for (int i = 0; i < v.length; i++) {
            v[i] = (float) number(list.get(i), key + "[" + i + "]");
        }
        return v;
    }

    /** An array of any length of whole numbers that fit an int. */
    int[] ints(JsonNode node, String key) throws SceneException {
        List<JsonNode> list = array(node, key);
        int[] v = new int[list.size()];
        for (int i = 0; i < v.length; i++) {
            v[i] = integer(list.get(i), key + "[" + i + "]", Integer.MIN_VALUE, Integer.MAX_VALUE - 1);
        }
        return v;
    }

    Vector3d vector(JsonNode node, String key) throws SceneException {
        double[] v = numbers(node, key, 3);
        return new Vector3d(v[0], v[1], v[2]);
    }

    Rgb color(JsonNode node, String key) throws SceneException {
        double[] v = numbers(node, key, 3);
        if (v[0] < 0 || v[1] < 0 || v[2] < 0) {
            throw error(node, "'" + key + "' must not be negative");
        }
        return new Rgb(v[0], v[1], v[2]);
    }

    /** A finite number ≥ 0. */
    double nonNegative(JsonNode node, String key) throws SceneException {
        double x = number(node, key);
        if (!(x >= 0)) {
            throw error(node, "'" + key + "' must be >= 0, got " + format(x));
        }
        return x;
    }

    /** A colour with every channel in [0, 1] (a reflectance). */
    Rgb unitColor(JsonNode node, String key) throws SceneException {
        Rgb c = color(node, key);
        if (c.max() > 1) {
            throw error(node, "'" + key + "' must lie in [0, 1], got " + c);
        }
        return c;
    }

    JsonNode require(Map<String, JsonNode> map, String key, JsonNode parent) throws SceneException {
        JsonNode n = map.get(key);
        if (n == null) {
            throw error(parent, "missing required key '" + key + "'");
        }
        return n;
    }

    /**
     * The {@code type} of a typed object (a material, a shape, an environment) at {@code key}: one
     * of {@code types}; else an error at its line naming the known ones ({@code forKey} and
     * {@code hint} go into that message).
     */
    String type(Map<String, JsonNode> map, JsonNode node, String key, Set<String> types, String what, String forKey, String hint)
            throws SceneException {
        String type = string(require(map, "type", node), key + ".type");
        if (!types.contains(type)) {
            throw new SceneException(file, map.get("type").line, "unknown " + what + " type '" + type + "'" + forKey + " (known: "
                    + sorted(types) + hint + ")");
        }
        return type;
    }

    void allowOnly(Map<String, JsonNode> map, String where, Set<String> keys) throws SceneException {
        for (var e : map.entrySet()) {
            if (!keys.contains(e.getKey())) {
                throw error(e.getValue(), "unknown key '" + e.getKey() + "' in " + where + " (known: " + sorted(keys) + ")");
            }
        }
    }

    static String sorted(Collection<String> names) {
        return String.join(", ", names.stream().sorted().toList());
    }

    /** A number as a user wrote it: 0 rather than 0.0. */
    static String format(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
