package dev.strahl.io.json;

import dev.strahl.image.Rgb;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * The scene file's {@code "lights"}: point, spot and directional lights (glTF's
 * {@code KHR_lights_punctual}), read into {@link Light}s and added to a {@code Scene.Builder}.
 * Errors name the file, the line and the key ({@code lights[1].outerCone}).
 */
final class SceneLights {
    /** The light types and the keys each accepts. */
    static final Map<String, Set<String>> KEYS = Map.of(
            "point", Set.of("type", "position", "intensity"),
            "spot", Set.of("type", "position", "direction", "intensity", "innerCone", "outerCone"),
            "directional", Set.of("type", "direction", "irradiance"));
    /** glTF's default cone angles, in degrees. */
    static final double DEFAULT_INNER_CONE = 0, DEFAULT_OUTER_CONE = 45;

    private SceneLights() {}

    /**
     * One light as the file gives it: position (point, spot; else null), direction (spot,
     * directional; else null), intensity in W/sr (or irradiance in W/m² for a directional light),
     * cone angles in degrees (spot only).
     */
    record Light(String type, Vector3dc position, Vector3dc direction, Rgb intensity, double innerCone, double outerCone) {}

    /** Reads the {@code "lights"} array; an absent key (null) is no lights. */
    static List<Light> parse(JsonNode node, JsonValues v) throws SceneException {
        List<Light> lights = new ArrayList<>();
        if (node == null) {
            return lights;
        }
        List<JsonNode> list = v.array(node, "lights");
        for (int i = 0; i < list.size(); i++) {
            lights.add(light(list.get(i), "lights[" + i + "]", v));
        }
        return lights;
    }

    private static Light light(JsonNode node, String key, JsonValues v) throws SceneException {
        Map<String, JsonNode> m = v.object(node, key);
        String type = v.string(v.require(m, "type", node), key + ".type");
        Set<String> keys = KEYS.get(type);
        if (keys == null) {
            throw v.error(m.get("type"), "unknown light type '" + type + "' (known: " + JsonValues.sorted(KEYS.keySet()) + ")");
        }
        v.allowOnly(m, key + " of type " + type, keys);
        if (type.equals("directional")) {
            return new Light(type, null, direction(m, node, key, v), v.color(v.require(m, "irradiance", node), key + ".irradiance"), 0, 0);
        }
        Vector3d position = v.vector(v.require(m, "position", node), key + ".position");
        Rgb intensity = v.color(v.require(m, "intensity", node), key + ".intensity");
        if (type.equals("point")) {
            return new Light(type, position, null, intensity, 0, 0);
        }
        double inner = m.containsKey("innerCone") ? v.number(m.get("innerCone"), key + ".innerCone") : DEFAULT_INNER_CONE;
        double outer = m.containsKey("outerCone") ? v.number(m.get("outerCone"), key + ".outerCone") : DEFAULT_OUTER_CONE;
        if (!(outer > 0 && outer <= 90)) {
            throw v.error(m.containsKey("outerCone") ? m.get("outerCone") : node,
                    "'" + key + ".outerCone' must lie in (0, 90] degrees, got " + JsonValues.format(outer));
        }
        if (Math.cos(Math.toRadians(outer)) == 1) {          // narrower than a double's cosine tells apart from a ray
            throw v.error(m.get("outerCone"), "'" + key + ".outerCone' of " + JsonValues.format(outer) + " degrees is too narrow"
                    + " (its cosine is 1: the narrowest cone is about 1e-6 degrees)");
        }
        if (!(inner >= 0 && inner <= outer)) {
            throw v.error(m.containsKey("innerCone") ? m.get("innerCone") : node,
                    "'" + key + ".innerCone' must lie in [0, outerCone] = [0, " + JsonValues.format(outer) + "] degrees, got "
                            + JsonValues.format(inner));
        }
        return new Light(type, position, direction(m, node, key, v), intensity, inner, outer);
    }

    private static Vector3d direction(Map<String, JsonNode> m, JsonNode node, String key, JsonValues v) throws SceneException {
        JsonNode d = v.require(m, "direction", node);
        Vector3d direction = v.vector(d, key + ".direction");
        double length = direction.length();
        if (!(length > 0 && Double.isFinite(length))) {
            throw v.error(d, "'" + key + ".direction' must be a non-zero vector of finite length");
        }
        return direction;
    }

    /** Adds the lights to the scene. */
    static void addTo(List<Light> lights, Scene.Builder builder) {
        for (Light l : lights) {
            switch (l.type()) {
                case "point" -> builder.pointLight(l.position(), l.intensity());
                case "spot" -> builder.spotLight(l.position(), l.direction(), l.intensity(), Math.toRadians(l.innerCone()),
                        Math.toRadians(l.outerCone()));
                default -> builder.directionalLight(l.direction(), l.intensity());
            }
        }
    }
}
