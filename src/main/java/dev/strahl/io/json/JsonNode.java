package dev.strahl.io.json;

import dev.strahl.scene.SceneException;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParseException;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadFeature;
import dev.strahl.io.text.JsonTypes;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A JSON value that remembers the line it starts on, so that every error in a scene file can
 * name its line. Parsed with Jackson's streaming parser; duplicate keys are refused.
 */
final class JsonNode {
    final Object value;          // Map<String, JsonNode>, List<JsonNode>, Long, Double, String, Boolean or null
    final int line;

    private JsonNode(Object value, int line) {
        this.value = value;
        this.line = line;
    }

    static JsonNode parse(Path file, String text) throws SceneException {
        JsonFactory factory = JsonFactory.builder().enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION)
                .disable(StreamReadFeature.INCLUDE_SOURCE_IN_LOCATION).build();
        try (JsonParser p = factory.createParser(text)) {
            if (p.nextToken() == null) {
                throw new SceneException(file, 1, "empty scene file");
            }
            JsonNode root = read(p, file);
            if (p.nextToken() != null) {
                throw new SceneException(file, line(p), "unexpected content after the end of the scene object");
            }
            return root;
        } catch (JsonParseException e) {
            String msg = e.getOriginalMessage();
            int nl = msg.indexOf('\n');
            throw new SceneException(file, e.getLocation() == null ? 0 : e.getLocation().getLineNr(),
                    "malformed JSON: " + (nl >= 0 ? msg.substring(0, nl) : msg));
        } catch (IOException e) {
            throw new SceneException(file, "cannot parse: " + e.getMessage(), e);
        }
    }

    private static int line(JsonParser p) {
        return p.currentTokenLocation().getLineNr();
    }

    private static JsonNode read(JsonParser p, Path file) throws IOException, SceneException {
        int line = line(p);
        JsonToken t = p.currentToken();
        switch (t) {
            case START_OBJECT: {
                Map<String, JsonNode> map = new LinkedHashMap<>();
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String key = p.currentName();
                    p.nextToken();
                    map.put(key, read(p, file));
                }
                return new JsonNode(map, line);
            }
            case START_ARRAY: {
                List<JsonNode> list = new ArrayList<>();
                while (p.nextToken() != JsonToken.END_ARRAY) {
                    list.add(read(p, file));
                }
                return new JsonNode(list, line);
            }
            case VALUE_NUMBER_INT:
                // whole numbers keep all their digits (a seed may use 64 bits); beyond a long, a double
                return new JsonNode(p.getNumberType() == JsonParser.NumberType.BIG_INTEGER ? (Object) p.getDoubleValue()
                        : (Object) p.getLongValue(), line);
            case VALUE_NUMBER_FLOAT:
                return new JsonNode(p.getDoubleValue(), line);
            case VALUE_STRING:
                return new JsonNode(p.getText(), line);
            case VALUE_TRUE:
            case VALUE_FALSE:
                return new JsonNode(p.getBooleanValue(), line);
            case VALUE_NULL:
                return new JsonNode(null, line);
            default:
                throw new SceneException(file, line, "unexpected JSON token " + t);
        }
    }

    boolean isObject() {
        return value instanceof Map;
    }

    @SuppressWarnings("unchecked")
    Map<String, JsonNode> object() {
        return (Map<String, JsonNode>) value;
    }

    @SuppressWarnings("unchecked")
    List<JsonNode> array() {
        return (List<JsonNode>) value;
    }

    String typeName() {
        return JsonTypes.name(value);
    }
}
