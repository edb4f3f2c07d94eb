package dev.strahl.io.gltf;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadFeature;
import com.fasterxml.jackson.core.exc.StreamConstraintsException;
import dev.strahl.codec.Printable;
import dev.strahl.io.text.JsonTypes;
import dev.strahl.scene.SceneException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A value of a glTF document that knows its JSON path ({@code meshes[0].primitives[1].indices}),
 * so that every error names the element at fault: a GLB's JSON is one line, where a line number
 * says nothing. (io.json's tree keeps lines and sits above this package.) Parsed with Jackson's
 * streaming parser; typed getters throw {@link SceneException} naming the file and the path.
 */
final class GltfJson {
    private final Path file;
    private final Object value;          // Map<String, GltfJson>, List<GltfJson>, Double, String, Boolean or null
    private final GltfJson parent;       // null for the root
    private final String key;            // the member's name in its parent object, or null in an array
    private final int index;             // the element's index in its parent array

    private GltfJson(Path file, Object value, GltfJson parent, String key, int index) {
        this.file = file;
        this.value = value;
        this.parent = parent;
        this.key = key;
        this.index = index;
    }

    /**
     * The JSON path, {@code meshes[0].primitives[1].indices}, made when a message needs it (a path
     * per value would take more memory than the values); a name from the file that is not a plain
     * identifier is quoted, printable.
     */
    String path() {
        if (parent == null) {
            return "";
        }
        String up = parent.path();
        if (key == null) {
            return up + "[" + index + "]";
        }
        String name = key.matches("[A-Za-z0-9_]{1,64}") ? key : Printable.quote(key);
        return up.isEmpty() ? name : up + "." + name;
    }

    /** Parses a whole document; malformed JSON is an error naming the line and column. */
    static GltfJson parse(Path file, byte[] bytes, int offset, int length) throws SceneException {
        JsonFactory factory = JsonFactory.builder().enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION)
                .disable(StreamReadFeature.INCLUDE_SOURCE_IN_LOCATION).build();
        try (JsonParser p = factory.createParser(bytes, offset, length)) {
            if (p.nextToken() == null) {
                throw new SceneException(file, "empty glTF JSON");
            }
            GltfJson root = read(p, file, null, null, 0);
            if (p.nextToken() != null) {
                throw new SceneException(file, "malformed JSON: content after the end of the root object");
            }
            return root;
        } catch (StreamConstraintsException e) {
            throw new SceneException(file, "malformed JSON: " + parserMessage(e.getOriginalMessage()));
        } catch (JsonProcessingException e) {
            int line = e.getLocation() == null ? 0 : e.getLocation().getLineNr();
            String where = line > 0 ? "line " + line + ", column " + e.getLocation().getColumnNr() + ": " : "";
            throw new SceneException(file, "malformed JSON: " + where + parserMessage(e.getOriginalMessage()));
        } catch (IOException e) {
            throw new SceneException(file, "cannot parse: " + parserMessage(e.getMessage()), e);
        }
    }

    /**
     * The parser's message, first line, printable: Jackson quotes the token it trips over, which in
     * a binary file is raw bytes (control characters among them).
     */
    private static String parserMessage(String msg) {
        String m = String.valueOf(msg);
        int nl = m.indexOf('\n');
        return Printable.text(nl >= 0 ? m.substring(0, nl) : m, 200);
    }

    private static GltfJson read(JsonParser p, Path file, GltfJson parent, String key, int index) throws IOException {
        JsonToken t = p.currentToken();
        switch (t) {
            case START_OBJECT: {
                Map<String, GltfJson> map = new LinkedHashMap<>();
                GltfJson object = new GltfJson(file, map, parent, key, index);
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String name = p.currentName();
                    p.nextToken();
                    map.put(name, read(p, file, object, name, 0));
                }
                return object;
            }
            case START_ARRAY: {
                List<GltfJson> list = new ArrayList<>();
                GltfJson array = new GltfJson(file, list, parent, key, index);
                while (p.nextToken() != JsonToken.END_ARRAY) {
                    list.add(read(p, file, array, null, list.size()));
                }
                return array;
            }
            case VALUE_NUMBER_INT:
            case VALUE_NUMBER_FLOAT:
                return new GltfJson(file, p.getDoubleValue(), parent, key, index);
            case VALUE_STRING:
                return new GltfJson(file, p.getText(), parent, key, index);
            case VALUE_TRUE:
            case VALUE_FALSE:
                return new GltfJson(file, p.getBooleanValue(), parent, key, index);
            default:
                return new GltfJson(file, null, parent, key, index);
        }
    }

    /** An error about this element: {@code file: path: message}. */
    SceneException error(String message) {
        String path = path();
        return new SceneException(file, (path.isEmpty() ? "" : path + ": ") + message);
    }

    /** The member {@code key}, or null when absent (or JSON null). */
    GltfJson get(String key) throws SceneException {
        GltfJson v = object().get(key);
        return v == null || v.value == null ? null : v;
    }

    boolean has(String key) throws SceneException {
        return get(key) != null;
    }

    /** The member {@code key}, which must be present. */
    GltfJson require(String key) throws SceneException {
        GltfJson v = get(key);
        if (v == null) {
            throw error("missing required property '" + key + "'");
        }
        return v;
    }

    @SuppressWarnings("unchecked")
    Map<String, GltfJson> object() throws SceneException {
        if (!(value instanceof Map)) {
            throw error("must be an object, got " + typeName());
        }
        return (Map<String, GltfJson>) value;
    }

    @SuppressWarnings("unchecked")
    List<GltfJson> array() throws SceneException {
        if (!(value instanceof List)) {
            throw error("must be an array, got " + typeName());
        }
        return (List<GltfJson>) value;
    }

    /** The array {@code key}, empty when absent. */
    List<GltfJson> array(String key) throws SceneException {
        GltfJson v = get(key);
        return v == null ? List.of() : v.array();
    }

    String string() throws SceneException {
        if (!(value instanceof String s)) {
            throw error("must be a string, got " + typeName());
        }
        return s;
    }

    /** This string as a message may quote it: a few characters, printable ({@link Printable#quote}). */
    String quoted() throws SceneException {
        return Printable.quote(string());
    }

    String string(String key, String otherwise) throws SceneException {
        GltfJson v = get(key);
        return v == null ? otherwise : v.string();
    }

    double number() throws SceneException {
        if (!(value instanceof Double d)) {
            throw error("must be a number, got " + typeName());
        }
        return d;
    }

    double number(String key, double otherwise) throws SceneException {
        GltfJson v = get(key);
        return v == null ? otherwise : v.number();
    }

    /** A whole number in [min, max]. */
    int integer(long min, long max) throws SceneException {
        double d = number();
        if (d != Math.rint(d) || d < min || d > max) {
            throw error("must be a whole number in [" + min + ", " + max + "], got " + format(d));
        }
        return (int) d;
    }

    int integer(String key, int otherwise, long min, long max) throws SceneException {
        GltfJson v = get(key);
        return v == null ? otherwise : v.integer(min, max);
    }

    /** An index into a top-level array of {@code size} elements. */
    int index(int size) throws SceneException {
        double d = number();
        if (d != Math.rint(d) || d < 0 || d >= size) {
            throw error("index " + format(d) + " out of range (" + size + " element" + (size == 1 ? "" : "s") + ")");
        }
        return (int) d;
    }

    boolean bool(String key, boolean otherwise) throws SceneException {
        GltfJson v = get(key);
        if (v == null) {
            return otherwise;
        }
        if (!(v.value instanceof Boolean b)) {
            throw v.error("must be true or false, got " + v.typeName());
        }
        return b;
    }

    /** The array {@code key} of exactly {@code n} numbers, or {@code otherwise} when absent. */
    double[] numbers(String key, int n, double[] otherwise) throws SceneException {
        GltfJson v = get(key);
        if (v == null) {
            return otherwise;
        }
        List<GltfJson> list = v.array();
        if (list.size() != n) {
            throw v.error("must have " + n + " numbers, got " + list.size());
        }
        double[] out = new double[n];
        for (int i = 0; i < n; i++) {
            out[i] = list.get(i).number();
        }
        return out;
    }

    String typeName() {
        return JsonTypes.name(value);
    }

    static String format(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
