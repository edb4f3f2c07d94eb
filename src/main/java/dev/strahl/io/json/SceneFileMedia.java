package dev.strahl.io.json;

import dev.strahl.image.Rgb;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * The scene file's participating media (docs/media.md): the {@code "media"} object, each shape's
 * {@code "interior"} and {@code "exterior"}, and {@code "camera": {"medium": ...}}, read into a
 * {@link Media} and handed to a {@code Scene.Builder}. Errors name the file, the line and the key
 * ({@code media.fog.g}, {@code shapes[2].interior}).
 */
final class SceneFileMedia {
    /** The medium types and the keys each accepts. */
    static final Map<String, Set<String>> KEYS = Map.of(
            "homogeneous", Set.of("type", "sigmaT", "scale", "albedo", "g"),
            "grid", Set.of("type", "file", "bounds", "scale", "albedo", "g"));

    /** Mitsuba 3's default single-scattering albedo (its {@code homogeneous} and {@code heterogeneous}); σt defaults to its 1. */
    static final double DEFAULT_ALBEDO = 0.75;

    private SceneFileMedia() {}

    /**
     * A medium as the file gives it: sigmaT (homogeneous; null for a grid) or the grid's file
     * (relative to the scene file's folder unless absolute) and bounds (null: the file's header),
     * then scale, albedo and g.
     */
    record Medium(String type, Rgb sigmaT, String file, Vector3dc min, Vector3dc max, double scale, Rgb albedo, double g) {}

    /** Which media a shape bounds (null: vacuum on that side). */
    record Boundary(String interior, String exterior) {}

    /**
     * Everything about media in a file.
     *
     * @param media      by name, in file order
     * @param camera     the camera's medium, or null
     * @param boundaries one per shape, in the shapes' order; null for a shape that bounds no media
     */
    record Media(Map<String, Medium> media, String camera, List<Boundary> boundaries) {
        static final Media NONE = new Media(Map.of(), null, List.of());

        Media {
            media = Collections.unmodifiableMap(new LinkedHashMap<>(media));
            // no shape bounds a medium: no list, as a description made without media has
            boundaries = boundaries.stream().allMatch(Objects::isNull) ? List.of() : Collections.unmodifiableList(new ArrayList<>(boundaries));
        }

        /** The boundary of shape {@code index}, null if it bounds no media. */
        Boundary boundary(int index) {
            return index < boundaries.size() ? boundaries.get(index) : null;
        }
    }

    /** Reads the media of a scene file while its reader goes through the shapes. */
    static final class Reader {
        private final JsonValues v;
        private final Map<String, Medium> media;
        private final List<Boundary> boundaries = new ArrayList<>();

        /** Reads the {@code "media"} object (null: none); grid files are relative to {@code folder}. */
        Reader(JsonNode node, JsonValues v, Path folder) throws SceneException {
            this.v = v;
            this.media = parse(node, v, folder);
        }

        /** Reads the next shape's {@code interior} and {@code exterior}. */
        void shape(JsonNode shape) throws SceneException {
            boundaries.add(boundary(v.object(shape, "shapes[]"), "shapes[" + boundaries.size() + "]", media, v));
        }

        /** Everything read, with the camera's {@code medium} ({@code camera} may be null). */
        Media result(JsonNode camera) throws SceneException {
            String medium = camera == null || !camera.isObject() ? null : mediumName(camera.object().get("medium"), "camera.medium", media, v);
            return new Media(media, medium, boundaries);
        }
    }

    /** Reads the {@code "media"} object (null: none). */
    static Map<String, Medium> parse(JsonNode node, JsonValues v, Path folder) throws SceneException {
        Map<String, Medium> media = new LinkedHashMap<>();
        if (node != null) {
            for (var e : v.object(node, "media").entrySet()) {
                media.put(e.getKey(), medium("media." + e.getKey(), e.getValue(), v, folder));
            }
        }
        return media;
    }

    private static Medium medium(String key, JsonNode node, JsonValues v, Path folder) throws SceneException {
        Map<String, JsonNode> m = v.object(node, key);
        String type = v.string(v.require(m, "type", node), key + ".type");
        Set<String> keys = KEYS.get(type);
        if (keys == null) {
            throw v.error(m.get("type"), "unknown medium type '" + type + "' for '" + key + "' (known: " + JsonValues.sorted(KEYS.keySet()) + ")");
        }
        v.allowOnly(m, key + " of type " + type, keys);
        double scale = m.containsKey("scale") ? v.nonNegative(m.get("scale"), key + ".scale") : 1;
        Rgb albedo = m.containsKey("albedo") ? colourOrNumber(m.get("albedo"), key + ".albedo", v, true) : Rgb.gray(DEFAULT_ALBEDO);
        double g = 0;
        if (m.containsKey("g")) {
            g = v.number(m.get("g"), key + ".g");
            if (!(g > -1 && g < 1)) {
                throw v.error(m.get("g"), "'" + key + ".g' (the phase function's asymmetry) must lie in (-1, 1), got " + JsonValues.format(g));
            }
        }
        if (type.equals("homogeneous")) {
            Rgb sigmaT = m.containsKey("sigmaT") ? colourOrNumber(m.get("sigmaT"), key + ".sigmaT", v, false) : Rgb.WHITE;
            if (!Double.isFinite(sigmaT.max() * scale)) {
                throw v.error(m.containsKey("sigmaT") ? m.get("sigmaT") : node, "'" + key + ".sigmaT' times 'scale' must be finite, got " + sigmaT + " x " + JsonValues.format(scale));
            }
            return new Medium(type, sigmaT, null, null, null, scale, albedo, g);
        }
        JsonNode fileNode = v.require(m, "file", node);
        String name = v.string(fileNode, key + ".file");
        Path file;
        try {
            file = folder.resolve(name);
        } catch (java.nio.file.InvalidPathException e) {
            throw v.error(fileNode, "'" + key + ".file' is not a valid path: " + name);
        }
        if (!name.toLowerCase(java.util.Locale.ROOT).endsWith(".vol")) {
            throw v.error(fileNode, "'" + key + ".file' must name a Mitsuba .vol file, got '" + name + "'");
        }
        if (!Files.isRegularFile(file)) {
            throw v.error(fileNode, "volume file not found: " + file);
        }
        Vector3d min = null, max = null;
        if (m.containsKey("bounds")) {
            JsonNode b = m.get("bounds");
            List<JsonNode> corners = v.array(b, key + ".bounds");
            if (corners.size() != 2) {
                throw v.error(b, "'" + key + ".bounds' must be two corners [[xmin, ymin, zmin], [xmax, ymax, zmax]], got " + corners.size()
                        + " entries");
            }
            min = v.vector(corners.get(0), key + ".bounds[0]");
            max = v.vector(corners.get(1), key + ".bounds[1]");
            if (!(min.x < max.x && min.y < max.y && min.z < max.z)) {
                throw v.error(b, "'" + key + ".bounds' must have min < max on every axis, got " + min + " .. " + max);
            }
        }
        return new Medium(type, null, name, min, max, scale, albedo, g);
    }

    /** A number (the same in every channel) or [r, g, b], ≥ 0, and ≤ 1 if {@code unit}. */
    private static Rgb colourOrNumber(JsonNode node, String key, JsonValues v, boolean unit) throws SceneException {
        Rgb c = node.value instanceof List ? v.color(node, key) : Rgb.gray(v.nonNegative(node, key));
        if (unit && c.max() > 1) {
            throw v.error(node, "'" + key + "' must lie in [0, 1], got " + c);
        }
        return c;
    }

    /** A shape's {@code interior} and {@code exterior} (null if it has neither), each a medium of {@code media}. */
    static Boundary boundary(Map<String, JsonNode> shape, String key, Map<String, Medium> media, JsonValues v) throws SceneException {
        String interior = mediumName(shape.get("interior"), key + ".interior", media, v);
        String exterior = mediumName(shape.get("exterior"), key + ".exterior", media, v);
        return interior == null && exterior == null ? null : new Boundary(interior, exterior);
    }

    /** A name of {@code media} (null for an absent key). */
    static String mediumName(JsonNode node, String key, Map<String, Medium> media, JsonValues v) throws SceneException {
        if (node == null) {
            return null;
        }
        String name = v.string(node, key);
        if (!media.containsKey(name)) {
            throw v.error(node, "unknown medium '" + name + "' in '" + key + "' (define it under 'media'"
                    + (media.isEmpty() ? "" : "; known: " + JsonValues.sorted(media.keySet())) + ")");
        }
        return name;
    }

    /** Defines the media on the builder (reading the grids' files, relative to {@code folder}). */
    static void define(Media m, Scene.Builder builder, Path file, Path folder) throws SceneException {
        for (var e : m.media().entrySet()) {
            Medium d = e.getValue();
            String key = "media." + e.getKey();
            try {
                if (d.type().equals("homogeneous")) {
                    builder.homogeneousMedium(e.getKey(), d.sigmaT().scale(d.scale()), d.albedo(), d.g());
                } else {
                    builder.gridMedium(e.getKey(), folder.resolve(d.file()), d.min(), d.max(), d.scale(), d.albedo(), d.g());
                }
            } catch (SceneException ex) {
                throw new SceneException(file, "'" + key + ".file': " + ex.getMessage(), ex);
            } catch (IllegalArgumentException ex) {
                throw new SceneException(file, "'" + key + "': " + ex.getMessage(), ex);
            }
        }
        if (m.camera() != null) {
            builder.cameraMedium(m.camera());
        }
    }

    /** Makes the next shapes bound the media of shape {@code index} (or none). */
    static void boundary(Media m, int index, Scene.Builder builder) {
        Boundary b = m.boundary(index);
        builder.mediumBoundary(b == null ? null : b.interior(), b == null ? null : b.exterior());
    }
}
