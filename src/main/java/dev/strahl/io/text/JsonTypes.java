package dev.strahl.io.text;

import java.util.List;
import java.util.Map;

/**
 * How an error message names the kind of a parsed JSON value ("must be a number, got a string"):
 * shared by the scene file's tree (io.json) and glTF's (io.gltf), which both hold a value as a
 * {@code Map} (object), {@code List} (array), {@code Number}, {@code String}, {@code Boolean} or
 * null.
 */
public final class JsonTypes {
    private JsonTypes() {}

    /** "an object", "an array", "a number", "a string", "a boolean" or "null". */
    public static String name(Object value) {
        if (value == null) {
            return "null";
        }
        if (value instanceof Map) {
            return "an object";
        }
        if (value instanceof List) {
            return "an array";
        }
        if (value instanceof Number) {
            return "a number";
        }
        if (value instanceof String) {
            return "a string";
        }
        return value instanceof Boolean ? "a boolean" : "a " + value.getClass().getSimpleName();
    }
}
