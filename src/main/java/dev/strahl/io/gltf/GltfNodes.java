package dev.strahl.io.gltf;

import dev.strahl.scene.SceneException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import org.joml.Matrix4d;
import org.joml.Quaterniond;

/**
 * The node hierarchy of the default scene (or the first, or every root node when the asset has
 * no scenes): each node's world matrix (its {@code matrix}, or translation · rotation · scale,
 * after its parent's), and the meshes, cameras and punctual lights placed by the nodes. A node
 * reached twice (a cycle, or two parents) is an error: glTF's nodes form disjoint trees.
 */
final class GltfNodes {
    /** A node that places something: the node's index, its world matrix and the placed element. */
    record Placed(int node, Matrix4d world, int element) {}

    /** A node still to visit, with its parent's world matrix. */
    private record Pending(int node, Matrix4d parentWorld) {}

    final List<Placed> meshes = new ArrayList<>();
    final List<Placed> cameras = new ArrayList<>();
    final List<Placed> lights = new ArrayList<>();

    private final GltfDocument doc;
    private final boolean[] visited;

    private GltfNodes(GltfDocument doc) throws SceneException {
        this.doc = doc;
        this.visited = new boolean[doc.root.array("nodes").size()];
    }

    /** Walks the scene's trees, each root under {@code placement}. */
    static GltfNodes walk(GltfDocument doc, Matrix4d placement) throws SceneException {
        GltfNodes nodes = new GltfNodes(doc);
        List<GltfJson> scenes = doc.root.array("scenes");
        int count = nodes.visited.length;
        if (scenes.isEmpty()) {
            if (count > 0) {
                doc.noteOnce("the asset has no scenes: every root node is shown");
            }
            boolean[] child = new boolean[count];
            for (GltfJson n : doc.root.array("nodes")) {
                for (GltfJson c : n.array("children")) {
                    child[c.index(count)] = true;
                }
            }
            for (int i = 0; i < count; i++) {
                if (!child[i]) {
                    nodes.visit(i, placement);
                }
            }
            return nodes;
        }
        int index = doc.root.has("scene") ? doc.root.get("scene").index(scenes.size()) : 0;
        if (scenes.size() > 1) {
            doc.noteOnce("the asset has " + scenes.size() + " scenes: showing scene " + index
                    + (doc.root.has("scene") ? " (its default)" : " (the first; it names no default)"));
        }
        for (GltfJson root : scenes.get(index).array("nodes")) {
            nodes.visit(root.index(count), placement);
        }
        return nodes;
    }

    /**
     * Walks the tree under node {@code root} depth first, with a stack of its own: a hierarchy may be
     * as deep as the asset has nodes (a chain of 100 000 is a few megabytes of JSON), which recursion
     * would answer with a StackOverflowError. Children are visited in their order, as before.
     */
    private void visit(int root, Matrix4d placement) throws SceneException {
        Deque<Pending> stack = new ArrayDeque<>();
        stack.push(new Pending(root, placement));
        while (!stack.isEmpty()) {
            Pending top = stack.pop();
            int index = top.node();
            GltfJson node = doc.root.array("nodes").get(index);
            if (visited[index]) {
                throw node.error("is reached twice in the node hierarchy (a cycle, or more than one parent)");
            }
            visited[index] = true;
            Matrix4d world = new Matrix4d(top.parentWorld()).mul(local(node));
            GltfJson ext = node.get("extensions");
            if (node.has("mesh")) {
                int mesh = node.get("mesh").index(doc.root.array("meshes").size());
                if (ext != null && ext.has("EXT_mesh_gpu_instancing")) {
                    gpuInstances(ext.get("EXT_mesh_gpu_instancing"), index, world, mesh);
                } else {
                    meshes.add(new Placed(index, world, mesh));
                }
            }
            if (node.has("camera")) {
                cameras.add(new Placed(index, world, node.get("camera").index(doc.root.array("cameras").size())));
            }
            if (ext != null && ext.has("KHR_lights_punctual")) {
                GltfJson light = ext.get("KHR_lights_punctual").require("light");
                lights.add(new Placed(index, world, light.index(GltfLights.definitions(doc).size())));
            }
            if (node.has("skin")) {
                doc.noteOnce("skins are ignored (meshes are rendered in their bind pose)");
            }
            List<GltfJson> children = node.array("children");
            for (int c = children.size() - 1; c >= 0; c--) {      // pushed last first: visited first to last
                stack.push(new Pending(children.get(c).index(visited.length), world));
            }
        }
    }

    /**
     * EXT_mesh_gpu_instancing: the node's mesh placed once per element of its TRANSLATION,
     * ROTATION and SCALE accessors (VEC3, VEC4 quaternion, VEC3; absent ones are 0, identity, 1),
     * each T · R · S after the node's world matrix. The accessors are checked as every accessor
     * is (type, bounds, the heap) before anything is allocated, and must agree on the count.
     */
    private void gpuInstances(GltfJson ext, int node, Matrix4d world, int mesh) throws SceneException {
        GltfJson attributes = ext.require("attributes");
        Accessors accessors = new Accessors(doc);
        float[] t = attributes.has("TRANSLATION") ? accessors.floats(attributes.get("TRANSLATION"), 3, "TRANSLATION") : null;
        float[] r = attributes.has("ROTATION") ? accessors.floats(attributes.get("ROTATION"), 4, "ROTATION") : null;
        float[] s = attributes.has("SCALE") ? accessors.floats(attributes.get("SCALE"), 3, "SCALE") : null;
        int count = t != null ? t.length / 3 : r != null ? r.length / 4 : s != null ? s.length / 3 : -1;
        if (count < 0) {
            throw attributes.error("names none of TRANSLATION, ROTATION and SCALE");
        }
        if (t != null && t.length / 3 != count || r != null && r.length / 4 != count || s != null && s.length / 3 != count) {
            throw attributes.error("TRANSLATION, ROTATION and SCALE must have as many elements each ("
                    + (t == null ? "-" : t.length / 3) + ", " + (r == null ? "-" : r.length / 4) + ", " + (s == null ? "-" : s.length / 3) + ")");
        }
        for (int i = 0; i < count; i++) {
            Quaterniond q = r == null ? new Quaterniond() : new Quaterniond(r[4 * i], r[4 * i + 1], r[4 * i + 2], r[4 * i + 3]);
            double length = Math.sqrt(q.lengthSquared());
            if (!(length > 1e-6) || !Double.isFinite(length)) {
                throw attributes.get("ROTATION").error("element " + i + " must be a unit quaternion, got length " + length);
            }
            q.normalize();
            Matrix4d local = new Matrix4d().translationRotateScale(t == null ? 0 : t[3 * i], t == null ? 0 : t[3 * i + 1], t == null ? 0 : t[3 * i + 2],
                    q.x, q.y, q.z, q.w, s == null ? 1 : s[3 * i], s == null ? 1 : s[3 * i + 1], s == null ? 1 : s[3 * i + 2]);
            Matrix4d placed = new Matrix4d(world).mul(local);
            if (!placed.isFinite() || placed.determinant3x3() == 0) {
                throw attributes.error("instance " + i + " has a non-finite or zero scale");
            }
            meshes.add(new Placed(node, placed, mesh));
        }
    }

    /** The node's local matrix: {@code matrix} (column-major) or T · R · S. */
    static Matrix4d local(GltfJson node) throws SceneException {
        double[] m = node.numbers("matrix", 16, null);
        if (m != null) {
            if (node.has("translation") || node.has("rotation") || node.has("scale")) {
                throw node.error("has both a matrix and translation/rotation/scale");
            }
            Matrix4d local = new Matrix4d(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], m[9], m[10], m[11], m[12], m[13], m[14], m[15]);
            if (!local.isFinite()) {
                throw node.get("matrix").error("must be finite");
            }
            return local;
        }
        double[] t = node.numbers("translation", 3, new double[] {0, 0, 0});
        double[] r = node.numbers("rotation", 4, new double[] {0, 0, 0, 1});
        double[] s = node.numbers("scale", 3, new double[] {1, 1, 1});
        Quaterniond q = new Quaterniond(r[0], r[1], r[2], r[3]);
        double length = Math.sqrt(q.lengthSquared());
        if (!(length > 1e-6) || !Double.isFinite(length)) {
            throw node.get("rotation").error("must be a unit quaternion, got length " + length);
        }
        q.normalize();
        Matrix4d local = new Matrix4d().translationRotateScale(t[0], t[1], t[2], q.x, q.y, q.z, q.w, s[0], s[1], s[2]);
        if (!local.isFinite()) {
            throw node.error("translation/scale must be finite");
        }
        return local;
    }
}
