package dev.strahl.io.json;

import dev.strahl.io.json.SceneDescription.EnvironmentSpec;
import dev.strahl.io.json.SceneDescription.MaterialSpec;
import dev.strahl.io.json.SceneDescription.ShapeSpec;
import dev.strahl.io.text.InputErrors;
import dev.strahl.io.text.TextLines;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.PhotonParameters;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Transform;
import dev.strahl.scene.TriangleMesh;
import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.joml.Vector3d;

/**
 * Reads a strahl scene file (JSON; every key is documented in docs/scene-format.md and described
 * by docs/scene.schema.json) into a {@link SceneDescription}, then builds the scene. Strict:
 * unknown keys, wrong types, missing required keys, out-of-range values, unknown material names
 * and missing mesh files are errors naming the file, the line and the key.
 */
public final class JsonSceneReader {
    /** This reader's errors, as io.text makes them. */
    static final InputErrors<SceneException> ERRORS = InputErrors.of(SceneException::new, SceneException::new);
    /** The material types of the scene file and the keys each accepts. */
    static final Map<String, Set<String>> MATERIAL_KEYS = JsonMaterials.MATERIAL_KEYS;
    /** The shape types and the keys each accepts. */
    static final Map<String, Set<String>> SHAPE_KEYS = Map.of(
            "sphere", Set.of("type", "center", "radius", "material", "transform", "interior", "exterior"),
            "mesh", Set.of("type", "file", "material", "transform", "interior", "exterior"), "gltf", Set.of("type", "file", "transform", "interior", "exterior"),
            "triangles", Set.of("type", "positions", "indices", "normals", "uvs", "material", "transform", "interior", "exterior"),
            "instance", Set.of("type", "group", "transform"));
    static final Set<String> TOP_KEYS = Set.of("camera", "film", "integrator", "materials", "groups", "shapes", "environment", "lights", "media");
    static final Set<String> CAMERA_KEYS = Set.of("lookFrom", "lookAt", "up", "fov", "aperture", "focusDistance", "medium");
    /** The environment types (the object form; an array is a constant radiance) and their keys. */
    static final Map<String, Set<String>> ENVIRONMENT_KEYS = Map.of("envmap", Set.of("type", "file", "scale", "rotate"));
    static final Set<String> FILM_KEYS = Set.of("width", "height", "aovs");
    static final Set<String> INTEGRATOR_KEYS = Set.of("type", "spp", "maxDepth", "seed", "lightSamples", "hemisphere", "photons",
            "photonRadius", "noiseThreshold");

    private final Path file;
    private final JsonValues v;
    /** The groups read so far (instances name them), and the one being read (null outside groups). */
    private final Map<String, List<ShapeSpec>> groups = new LinkedHashMap<>();
    private String inGroup;
    /** Material names used by shapes, with the line of the use, checked once all materials are known. */
    private final List<Map.Entry<String, Integer>> materialUses = new ArrayList<>();

    private JsonSceneReader(Path file) {
        this.file = file;
        this.v = new JsonValues(file);
    }

    /** Reads and builds the scene in {@code file}, with what it says about rendering. */
    public static SceneFile read(Path file) throws SceneException {
        SceneDescription d = parse(file);
        return new SceneFile(d.build(file, folder(file)), d.settings());
    }

    /** Reads the scene file into its description, checking everything but the contents of mesh files. */
    static SceneDescription parse(Path file) throws SceneException {
        String text;
        try {
            dev.strahl.files.FileReads.note(file);
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (CharacterCodingException e) {
            throw new SceneException(file, TextLines.lineOfInvalidUtf8(file, 1), "not a text scene file (invalid UTF-8)");
        } catch (IOException e) {
            throw TextLines.cannotRead(ERRORS, file, e);
        }
        return new JsonSceneReader(file).scene(JsonNode.parse(file, text));
    }

    static Path folder(Path file) {
        return file.toAbsolutePath().getParent();
    }

    /** The file {@code fileNode} names (at {@code key}), relative to the scene file's folder. */
    private Path fileAt(JsonNode fileNode, String key) throws SceneException {
        String name = v.string(fileNode, key);
        try {
            return folder(file).resolve(name);
        } catch (java.nio.file.InvalidPathException e) {
            throw new SceneException(file, fileNode.line, "'" + key + "' is not a valid path: " + name);
        }
    }

    private SceneDescription scene(JsonNode root) throws SceneException {
        Map<String, JsonNode> top = v.object(root, "scene");
        v.allowOnly(top, "scene", TOP_KEYS);
        Map<String, MaterialSpec> materials = new LinkedHashMap<>();
        if (top.containsKey("materials")) {
            for (var e : v.object(top.get("materials"), "materials").entrySet()) {
                materials.put(e.getKey(), new JsonMaterials(file, v).material(e.getKey(), e.getValue()));
            }
        }
        if (top.containsKey("groups")) {
            for (var e : v.object(top.get("groups"), "groups").entrySet()) {
                inGroup = e.getKey();
                List<ShapeSpec> members = new ArrayList<>();
                for (JsonNode shape : v.array(e.getValue(), "groups." + e.getKey())) {
                    members.add(shape(shape));
                }
                if (members.isEmpty()) {
                    throw new SceneException(file, e.getValue().line, "'groups." + e.getKey() + "' is empty: a group needs shapes");
                }
                groups.put(e.getKey(), members);
            }
            inGroup = null;
        }
        JsonNode shapesNode = v.require(top, "shapes", root);
        List<JsonNode> list = v.array(shapesNode, "shapes");
        if (list.isEmpty()) {
            throw new SceneException(file, shapesNode.line, "'shapes' is empty: the scene has no geometry");
        }
        SceneFileMedia.Reader media = new SceneFileMedia.Reader(top.get("media"), v, folder(file));
        List<ShapeSpec> shapes = new ArrayList<>();
        for (JsonNode shape : list) {
            shapes.add(shape(shape));
            media.shape(shape);
        }
        for (var use : materialUses) {
            if (!materials.containsKey(use.getKey())) {
                throw new SceneException(file, use.getValue(), "unknown material '" + use.getKey() + "' (define it under 'materials')");
            }
        }
        Camera camera = top.containsKey("camera") ? camera(top.get("camera")) : null;
        EnvironmentSpec environment = top.containsKey("environment") ? environment(top.get("environment")) : null;
        SceneSettings settings = settings(top.get("film"), top.get("integrator"));
        return new SceneDescription(camera, settings, materials, groups, shapes, environment, SceneLights.parse(top.get("lights"), v),
                media.result(top.get("camera")));
    }

    // ---- shapes --------------------------------------------------------------------------------

    private ShapeSpec shape(JsonNode node) throws SceneException {
        Map<String, JsonNode> s = v.object(node, "shapes[]");
        String type = v.type(s, node, "shapes[]", SHAPE_KEYS.keySet(), "shape", "", "");
        v.allowOnly(s, "shapes[] of type " + type, SHAPE_KEYS.get(type));
        Transform transform = s.containsKey("transform") ? TransformReader.read(v, s.get("transform")) : Transform.IDENTITY;
        if (inGroup != null && (type.equals("instance") || type.equals("gltf"))) {
            throw new SceneException(file, node.line, "'groups." + inGroup + "' holds " + (type.equals("instance")
                    ? "an instance: groups do not nest (place instances in 'shapes')" : "a glTF file: glTF instances its own meshes (place it in 'shapes')"));
        }
        if (inGroup != null && (s.containsKey("interior") || s.containsKey("exterior"))) {
            throw new SceneException(file, node.line, "'groups." + inGroup + "': a shape in a group bounds no media (place it in 'shapes')");
        }
        switch (type) {
            case "instance": {
                JsonNode groupNode = v.require(s, "group", node);
                String group = v.string(groupNode, "shapes[].group");
                if (!groups.containsKey(group)) {
                    throw new SceneException(file, groupNode.line, "unknown group '" + group + "' (define it under 'groups')");
                }
                return new SceneDescription.InstanceShape(group, transform);
            }
            case "mesh", "gltf": {
                JsonNode fileNode = v.require(s, "file", node);
                String name = v.string(fileNode, "shapes[].file");
                Path mesh = fileAt(fileNode, "shapes[].file");
                String lower = name.toLowerCase(Locale.ROOT);
                if (type.equals("gltf") ? !lower.endsWith(".gltf") && !lower.endsWith(".glb") : !lower.endsWith(".obj") && !lower.endsWith(".ply")) {
                    throw new SceneException(file, fileNode.line, "'shapes[].file' must name " + (type.equals("gltf") ? "a .gltf or .glb" : "an .obj or .ply") + " file, got '" + name + "'");
                }
                if (!Files.isRegularFile(mesh)) {
                    throw new SceneException(file, fileNode.line, "mesh file not found: " + mesh);
                }
                return new SceneDescription.MeshShape(name, s.containsKey("material") ? materialName(s.get("material")) : null, transform);
            }
            case "sphere": {
                Vector3d center = v.vector(v.require(s, "center", node), "shapes[].center");
                double radius = v.number(v.require(s, "radius", node), "shapes[].radius");
                if (!(radius > 0)) {
                    throw new SceneException(file, s.get("radius").line, "'shapes[].radius' must be positive, got " + JsonValues.format(radius));
                }
                String material = materialName(v.require(s, "material", node));
                if (!transform.isSimilarity()) {
                    var m = transform.matrix();
                    var axis = new Vector3d();
                    throw new SceneException(file, s.get("transform").line, "'shapes[].transform': a sphere can only be translated,"
                            + " rotated and scaled uniformly; this transform scales its axes by " + (float) m.getColumn(0, axis).length()
                            + ", " + (float) m.getColumn(1, axis).length() + " and " + (float) m.getColumn(2, axis).length());
                }
                return new SceneDescription.SphereShape(center, radius, material, transform);
            }
            default:
                return triangles(s, node, transform);
        }
    }

    private ShapeSpec triangles(Map<String, JsonNode> s, JsonNode node, Transform transform) throws SceneException {
        float[] positions = v.floats(v.require(s, "positions", node), "shapes[].positions");
        JsonNode indexNode = v.require(s, "indices", node);
        int[] indices = v.ints(indexNode, "shapes[].indices");
        float[] normals = s.containsKey("normals") ? v.floats(s.get("normals"), "shapes[].normals") : null;
        float[] uvs = s.containsKey("uvs") ? v.floats(s.get("uvs"), "shapes[].uvs") : null;
        String material = materialName(v.require(s, "material", node));
        if (positions.length % 3 != 0) {
            throw new SceneException(file, s.get("positions").line, "'shapes[].positions' must hold x, y, z triples, got " + positions.length + " numbers");
        }
        if (indices.length == 0 || indices.length % 3 != 0) {
            throw new SceneException(file, indexNode.line, "'shapes[].indices' must hold three vertex indices per triangle, got " + indices.length);
        }
        if (normals != null && normals.length != positions.length) {
            throw new SceneException(file, s.get("normals").line, "'shapes[].normals' must have one x, y, z triple per vertex: "
                    + normals.length + " numbers for " + positions.length / 3 + " vertices");
        }
        if (uvs != null && uvs.length != positions.length / 3 * 2) {
            throw new SceneException(file, s.get("uvs").line, "'shapes[].uvs' must have one u, v pair per vertex: "
                    + uvs.length + " numbers for " + positions.length / 3 + " vertices");
        }
        if (uvs != null) {
            for (float f : uvs) {
                if (!Float.isFinite(f)) {
                    throw new SceneException(file, s.get("uvs").line, "'shapes[].uvs' must be finite numbers that fit into floats, got " + f);
                }
            }
        }
        for (int i = 0; i < indices.length; i++) {
            if (indices[i] < 0 || indices[i] >= positions.length / 3) {
                throw new SceneException(file, indexNode.line, "'shapes[].indices[" + i + "]' = " + indices[i]
                        + " is out of range (there are " + positions.length / 3 + " vertices)");
            }
        }
        for (float p : positions) {
            if (!Float.isFinite(p)) {
                throw new SceneException(file, s.get("positions").line, "'shapes[].positions' must fit into floats, got " + p);
            }
        }
        try {
            transform.apply(new TriangleMesh(positions, indices, normals, uvs));   // the mesh itself is valid after the checks above
        } catch (IllegalArgumentException e) {
            throw new SceneException(file, s.get("transform").line, "'shapes[].transform': " + e.getMessage());
        }
        return new SceneDescription.TrianglesShape(positions, indices, normals, uvs, material, transform);
    }

    private String materialName(JsonNode node) throws SceneException {
        String name = v.string(node, "shapes[].material");
        materialUses.add(Map.entry(name, node.line));
        return name;
    }

    // ---- environment -----------------------------------------------------------------------------

    /** {@code [r, g, b]}, or {@code {"type": "envmap", "file": ..., "scale": 1, "rotate": 0}}. */
    private EnvironmentSpec environment(JsonNode node) throws SceneException {
        if (!node.isObject()) {
            return new EnvironmentSpec(v.color(node, "environment"), null, 1, 0);
        }
        Map<String, JsonNode> e = node.object();
        String type = v.type(e, node, "environment", ENVIRONMENT_KEYS.keySet(), "environment", "",
                "; or give a constant radiance as [r, g, b]");
        v.allowOnly(e, "environment of type " + type, ENVIRONMENT_KEYS.get(type));
        JsonNode fileNode = v.require(e, "file", node);
        String name = v.string(fileNode, "environment.file");
        Path map = fileAt(fileNode, "environment.file");
        if (!EnvironmentMaps.isSupported(name)) {
            throw new SceneException(file, fileNode.line, "'environment.file' must name an .hdr, .exr or .pfm image, got '" + name + "'");
        }
        if (!Files.isRegularFile(map)) {
            throw new SceneException(file, fileNode.line, "environment map not found: " + map);
        }
        double scale = 1, rotate = 0;
        if (e.containsKey("scale")) {
            scale = v.number(e.get("scale"), "environment.scale");
            if (!(scale >= 0)) {
                throw new SceneException(file, e.get("scale").line, "'environment.scale' must be >= 0, got " + JsonValues.format(scale));
            }
        }
        if (e.containsKey("rotate")) {
            rotate = v.number(e.get("rotate"), "environment.rotate");
        }
        return new EnvironmentSpec(null, name, scale, rotate);
    }

    // ---- camera, film, integrator ----------------------------------------------------------------

    private Camera camera(JsonNode node) throws SceneException {
        Map<String, JsonNode> c = v.object(node, "camera");
        v.allowOnly(c, "camera", CAMERA_KEYS);
        Vector3d from = v.vector(v.require(c, "lookFrom", node), "camera.lookFrom");
        Vector3d at = v.vector(v.require(c, "lookAt", node), "camera.lookAt");
        Vector3d up = c.containsKey("up") ? v.vector(c.get("up"), "camera.up") : new Vector3d(0, 1, 0);
        double fov = c.containsKey("fov") ? v.number(c.get("fov"), "camera.fov") : 40;
        double aperture = c.containsKey("aperture") ? v.number(c.get("aperture"), "camera.aperture") : 0;
        if (!(aperture >= 0)) {
            throw new SceneException(file, c.get("aperture").line, "'camera.aperture' (the lens radius) must be >= 0, got "
                    + JsonValues.format(aperture));
        }
        Double focus = null;
        if (c.containsKey("focusDistance")) {
            focus = v.number(c.get("focusDistance"), "camera.focusDistance");
            if (!(focus > 0)) {
                throw new SceneException(file, c.get("focusDistance").line, "'camera.focusDistance' must be positive, got "
                        + JsonValues.format(focus));
            }
        }
        try {
            Camera camera = new Camera(from, at, up, fov);
            return camera.withLens(aperture, focus != null ? focus : camera.focusDistance());
        } catch (IllegalArgumentException e) {
            throw new SceneException(file, node.line, "bad 'camera': " + e.getMessage());
        }
    }

    private SceneSettings settings(JsonNode film, JsonNode integrator) throws SceneException {
        Integer width = null, height = null, spp = null, maxDepth = null, lightSamples = null, photons = null;
        Long seed = null;
        Double photonRadius = null;
        IntegratorKind type = null;
        HemisphereSampling hemisphere = null;
        if (film != null) {
            Map<String, JsonNode> f = v.object(film, "film");
            v.allowOnly(f, "film", FILM_KEYS);
            width = f.containsKey("width") ? v.integer(f.get("width"), "film.width", 1, RenderSettings.MAX_SIZE) : null;
            height = f.containsKey("height") ? v.integer(f.get("height"), "film.height", 1, RenderSettings.MAX_SIZE) : null;
        }
        if (integrator != null) {
            Map<String, JsonNode> i = v.object(integrator, "integrator");
            v.allowOnly(i, "integrator", INTEGRATOR_KEYS);
            if (i.containsKey("type")) {
                try {
                    type = IntegratorKind.named(v.string(i.get("type"), "integrator.type"));
                } catch (IllegalArgumentException e) {
                    throw new SceneException(file, i.get("type").line, "'integrator.type': " + e.getMessage());
                }
            }
            spp = i.containsKey("spp") ? v.integer(i.get("spp"), "integrator.spp", 1, Integer.MAX_VALUE) : null;
            if (i.containsKey("maxDepth")) {
                maxDepth = v.integer(i.get("maxDepth"), "integrator.maxDepth", -1, Integer.MAX_VALUE);
                if (maxDepth == 0) {
                    throw new SceneException(file, i.get("maxDepth").line, "'integrator.maxDepth' must be -1 (unbounded) or >= 1, got 0");
                }
            }
            seed = i.containsKey("seed") ? v.longInteger(i.get("seed"), "integrator.seed") : null;
            lightSamples = i.containsKey("lightSamples") ? v.integer(i.get("lightSamples"), "integrator.lightSamples", 1, Integer.MAX_VALUE) : null;
            if (i.containsKey("hemisphere")) {
                String h = v.string(i.get("hemisphere"), "integrator.hemisphere");
                if (!h.equals("cosine") && !h.equals("uniform")) {
                    throw new SceneException(file, i.get("hemisphere").line, "'integrator.hemisphere' must be \"cosine\" or \"uniform\", got '" + h + "'");
                }
                hemisphere = h.equals("cosine") ? HemisphereSampling.COSINE : HemisphereSampling.UNIFORM;
            }
            photons = i.containsKey("photons") ? v.integer(i.get("photons"), "integrator.photons", 1, PhotonParameters.MAX_PHOTONS) : null;
            if (i.containsKey("photonRadius")) {
                photonRadius = v.number(i.get("photonRadius"), "integrator.photonRadius");
                if (!(photonRadius >= 0)) {
                    throw new SceneException(file, i.get("photonRadius").line, "'integrator.photonRadius' must be >= 0 (0 = automatic), got "
                            + JsonValues.format(photonRadius));
                }
            }
        }
        return new SceneSettings(width, height, spp, maxDepth, seed, type, lightSamples, hemisphere, photons, photonRadius,
                SceneSettings.readAovs(film, v), null, SceneSettings.readNoiseThreshold(integrator, v));
    }
}
