package dev.strahl.io.gltf;

import dev.strahl.scene.SceneException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The primitives of glTF meshes as triangle lists in the mesh's own coordinates: TRIANGLES as they
 * are, TRIANGLE_STRIP and TRIANGLE_FAN converted (the specification's §3.7.2.1 vertex orders),
 * non-indexed primitives indexed 0, 1, 2…; POINTS and LINES are skipped with one note. Texture
 * coordinates are turned to strahl's convention (v' = 1 − v: glTF's (0, 0) is an image's top-left
 * corner, strahl's its bottom-left). A primitive keeps one coordinate set, the one its material's
 * textures read ({@link GltfMaterials#uvSet}: TEXCOORD_0 unless they all read another).
 * Each mesh is read once, however many nodes use it.
 */
final class GltfMeshes {
    /**
     * One primitive's triangles.
     *
     * @param positions x, y, z per vertex, finite
     * @param normals   x, y, z per vertex, or null
     * @param uvs       u, v per vertex (strahl's convention), or null
     * @param indices   three per triangle
     * @param material  index into the document's materials, or -1 for the default material
     */
    record Primitive(float[] positions, float[] normals, float[] uvs, int[] indices, int material) {}

    private final GltfDocument doc;
    private final Accessors accessors;
    private final GltfMaterials materials;
    private final Map<Integer, List<Primitive>> read = new java.util.HashMap<>();

    GltfMeshes(GltfDocument doc) {
        this(doc, new GltfMaterials(doc));
    }

    /** Meshes whose primitives read the coordinate set that {@code materials} picks for their material. */
    GltfMeshes(GltfDocument doc, GltfMaterials materials) {
        this.doc = doc;
        this.accessors = new Accessors(doc);
        this.materials = materials;
    }

    /** The primitives of mesh {@code index} (read on first use). */
    List<Primitive> mesh(int index) throws SceneException {
        List<Primitive> done = read.get(index);
        if (done != null) {
            return done;
        }
        GltfJson mesh = doc.root.array("meshes").get(index);
        List<Primitive> out = new ArrayList<>();
        for (GltfJson p : mesh.require("primitives").array()) {
            Primitive prim = primitive(p);
            if (prim != null) {
                out.add(prim);
            }
        }
        read.put(index, out);
        return out;
    }

    private Primitive primitive(GltfJson p) throws SceneException {
        int mode = p.integer("mode", 4, 0, 6);
        if (mode < 4) {
            doc.noteOnce("POINTS and LINES primitives are skipped (strahl renders surfaces)");
            return null;
        }
        if (p.has("targets")) {
            doc.noteOnce("morph targets are ignored (the base shape is rendered)");
        }
        GltfJson attributes = p.require("attributes");
        attributes.object();
        if (attributes.has("JOINTS_0")) {
            doc.noteOnce("skins are ignored (meshes are rendered in their bind pose)");
        }
        GltfJson position = attributes.require("POSITION");
        float[] positions = accessors.floats(position, 3, "POSITION");
        int vertices = positions.length / 3;
        for (int i = 0; i < positions.length; i++) {
            if (!Float.isFinite(positions[i])) {
                throw doc.element("accessors", position).error("POSITION of vertex " + i / 3 + " is not finite (" + positions[i] + ")");
            }
        }
        float[] normals = null;
        if (attributes.has("NORMAL")) {
            normals = accessors.floats(attributes.get("NORMAL"), 3, "NORMAL");
            requireCount(attributes.get("NORMAL"), normals.length / 3, vertices);
        }
        int material = p.has("material") ? p.get("material").index(doc.root.array("materials").size()) : -1;
        String uvKey = "TEXCOORD_" + materials.uvSet(material);
        float[] uvs = null;
        if (attributes.has(uvKey)) {
            uvs = accessors.floats(attributes.get(uvKey), 2, uvKey);
            requireCount(attributes.get(uvKey), uvs.length / 2, vertices);
            for (int i = 1; i < uvs.length; i += 2) {
                uvs[i] = 1 - uvs[i];
            }
        } else if (!uvKey.equals("TEXCOORD_0")) {
            doc.noteOnce("warning: " + p.path() + " has no " + uvKey + ", which its material's textures read: it has no texture coordinates");
        }
        int[] order;
        if (p.has("indices")) {
            order = accessors.indices(p.get("indices"), vertices);
        } else {
            order = new int[vertices];
            for (int i = 0; i < vertices; i++) {
                order[i] = i;
            }
        }
        int[] triangles = triangles(order, mode);
        return new Primitive(positions, normals, uvs, triangles, material);
    }

    private static void requireCount(GltfJson accessorIndex, int count, int vertices) throws SceneException {
        if (count != vertices) {
            throw accessorIndex.error("has " + count + " elements for " + vertices + " vertices (POSITION)");
        }
    }

    /** The vertex order of a primitive as a triangle list (a trailing partial triangle is dropped). */
    static int[] triangles(int[] order, int mode) {
        if (mode == 4) {
            return order.length % 3 == 0 ? order : java.util.Arrays.copyOf(order, order.length - order.length % 3);
        }
        int n = Math.max(0, order.length - 2);
        int[] out = new int[3 * n];
        for (int i = 0; i < n; i++) {
            if (mode == 5) {                       // strip: every other triangle reversed, to keep the winding
                out[3 * i] = order[i];
                out[3 * i + 1] = order[i + 1 + i % 2];
                out[3 * i + 2] = order[i + 2 - i % 2];
            } else {                               // fan around the first vertex
                out[3 * i] = order[i + 1];
                out[3 * i + 1] = order[i + 2];
                out[3 * i + 2] = order[0];
            }
        }
        return out;
    }
}
