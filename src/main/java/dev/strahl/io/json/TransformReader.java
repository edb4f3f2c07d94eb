package dev.strahl.io.json;

import dev.strahl.scene.SceneException;
import dev.strahl.scene.Transform;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The {@code transform} key of a shape: an array of steps, applied in order, each an object with
 * one key: {@code {"translate": [x, y, z]}}, {@code {"scale": s}} or {@code {"scale": [x, y, z]}},
 * {@code {"rotate": {"axis": [x, y, z], "degrees": d}}}.
 */
final class TransformReader {
    private static final Set<String> STEPS = Set.of("translate", "rotate", "scale");

    private TransformReader() {}

    static Transform read(JsonValues v, JsonNode node) throws SceneException {
        Transform transform = Transform.IDENTITY;
        String key = "shapes[].transform";
        for (JsonNode stepNode : v.array(node, key)) {
            Map<String, JsonNode> step = v.object(stepNode, key + "[]");
            if (step.size() != 1) {
                throw v.error(stepNode, "each step of '" + key + "' must have exactly one key of " + JsonValues.sorted(STEPS)
                        + ", got " + (step.isEmpty() ? "none" : JsonValues.sorted(step.keySet())));
            }
            var e = step.entrySet().iterator().next();
            v.allowOnly(step, key + "[]", STEPS);
            JsonNode value = e.getValue();
            try {
                switch (e.getKey()) {
                    case "translate" -> {
                        double[] t = v.numbers(value, key + "[].translate", 3);
                        transform = transform.translate(t[0], t[1], t[2]);
                    }
                    case "scale" -> {
                        double[] s = value.value instanceof List ? v.numbers(value, key + "[].scale", 3)
                                : new double[] {v.number(value, key + "[].scale"), 0, 0};
                        if (!(value.value instanceof List)) {
                            s[1] = s[2] = s[0];
                        }
                        transform = transform.scale(s[0], s[1], s[2]);
                    }
                    default -> {
                        Map<String, JsonNode> r = v.object(value, key + "[].rotate");
                        v.allowOnly(r, key + "[].rotate", Set.of("axis", "degrees"));
                        double[] axis = v.numbers(v.require(r, "axis", value), key + "[].rotate.axis", 3);
                        double degrees = v.number(v.require(r, "degrees", value), key + "[].rotate.degrees");
                        transform = transform.rotate(degrees, axis[0], axis[1], axis[2]);
                    }
                }
            } catch (IllegalArgumentException x) {
                throw v.error(value, "bad '" + key + "[]." + e.getKey() + "': " + x.getMessage());
            }
        }
        return transform;
    }
}
