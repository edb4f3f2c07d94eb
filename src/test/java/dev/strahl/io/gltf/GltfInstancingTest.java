package dev.strahl.io.gltf;

import static dev.strahl.io.gltf.GltfWriter.map;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import dev.strahl.accel.TraversalStack;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.world.World;
import java.nio.file.Path;
import java.util.List;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A glTF mesh placed by several nodes is instanced (its triangles stored once), and
 * EXT_mesh_gpu_instancing's TRANSLATION, ROTATION and SCALE place it once per element: the same
 * surfaces as separate copies of the mesh under every ray, mirrors and unequal scales included;
 * bad instancing accessors are refused naming the element.
 */
class GltfInstancingTest {
    @TempDir
    Path dir;

    /** A closed tetrahedron (4 triangles). */
    static int tetrahedron(GltfWriter w) {
        return w.mesh(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, new int[] {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}, null);
    }

    static final List<java.util.Map<String, Object>> PLACEMENTS = List.of(
            map("translation", List.of(-2, 0, 0)),
            map("translation", List.of(0, 0.2, 0), "rotation", List.of(0, 0.3826834, 0, 0.9238795), "scale", List.of(1.5, 0.5, 1)),
            map("translation", List.of(2, -0.1, 0), "rotation", List.of(0.2, 0, 0.1, 0.9746794), "scale", List.of(-0.8, 1.2, 0.9)));

    private Scene shared(boolean separateMeshes) throws Exception {
        GltfWriter w = new GltfWriter();
        int mesh = tetrahedron(w);
        for (var p : PLACEMENTS) {
            var node = new java.util.LinkedHashMap<>(p);
            node.put("mesh", separateMeshes ? tetrahedron(w) : mesh);
            w.rootNode(node);
        }
        return SceneLoader.load(w.writeGlb(dir.resolve(separateMeshes ? "copies.glb" : "shared.glb")));
    }

    private Scene gpuInstanced() throws Exception {
        GltfWriter w = new GltfWriter();
        int mesh = tetrahedron(w);
        float[] t = {-2, 0, 0, 0, 0.2f, 0, 2, -0.1f, 0};
        float[] r = {0, 0, 0, 1, 0, 0.3826834f, 0, 0.9238795f, 0.2f, 0, 0.1f, 0.9746794f};
        float[] s = {1, 1, 1, 1.5f, 0.5f, 1, -0.8f, 1.2f, 0.9f};
        w.rootNode(map("mesh", mesh, "extensions", map("EXT_mesh_gpu_instancing", map("attributes",
                map("TRANSLATION", w.floats("VEC3", t), "ROTATION", w.floats("VEC4", r), "SCALE", w.floats("VEC3", s))))));
        return SceneLoader.load(w.writeGlb(dir.resolve("gpu.glb")));
    }

    @Test
    void aMeshUsedByThreeNodesIsStoredOnceAndMeetsRaysAsItsCopiesDo() throws Exception {
        Scene shared = shared(false), copies = shared(true);
        assertThat(World.of(shared).instances().count()).isEqualTo(3);
        assertThat(World.of(shared).uniqueTriangles()).isEqualTo(4);
        assertThat(World.of(copies).instances().count()).isZero();
        assertThat(World.of(copies).uniqueTriangles()).isEqualTo(12);
        assertThat(sameHits(shared, copies)).isGreaterThan(300);
    }

    @Test
    void gpuInstancingPlacesTheMeshOncePerElement() throws Exception {
        Scene gpu = gpuInstanced();
        assertThat(World.of(gpu).instances().count()).isEqualTo(3);
        assertThat(World.of(gpu).instancedTriangles()).isEqualTo(12);
        assertThat(sameHits(gpu, shared(true))).isGreaterThan(300);
    }

    /** Rays from a grid in front of the three placements: the same hits (distance, side) in both scenes; returns the hits. */
    private static int sameHits(Scene a, Scene b) {
        World wa = World.of(a), wb = World.of(b);
        TraversalStack stack = new TraversalStack();
        int hits = 0;
        for (int i = 0; i < 80; i++) {
            for (int j = 0; j < 60; j++) {
                Vector3d o = new Vector3d(-3.5 + 7.0 * i / 80, -1 + 2.5 * j / 60, 4), d = new Vector3d(0.05, -0.03, -1).normalize();
                Ray ra = new Ray().set(o, d, Double.POSITIVE_INFINITY), rb = new Ray().set(o, d, Double.POSITIVE_INFINITY);
                Hit ha = new Hit().reset(), hb = new Hit().reset();
                boolean fa = wa.bvh().intersect(ra, ha, stack, true), fb = wb.bvh().intersect(rb, hb, stack, true);
                assertThat(fa).as("ray %d, %d", i, j).isEqualTo(fb);
                if (fa) {
                    hits++;
                    assertThat(ha.t).as("ray %d, %d", i, j).isCloseTo(hb.t, org.assertj.core.data.Offset.offset(1e-5));
                    var sa = new dev.strahl.geometry.SurfacePoint();
                    var sb = new dev.strahl.geometry.SurfacePoint();
                    wa.surface(ra, ha, sa);
                    wb.surface(rb, hb, sb);
                    assertThat(sa.ng.dot(sb.ng)).as("ray %d, %d: normals %s and %s", i, j, sa.ng, sb.ng).isGreaterThan(1 - 1e-9);
                }
            }
        }
        return hits;
    }

    @Test
    void instancingAccessorsThatDisagreeOrHaveTheWrongTypeAreRefusedNamingTheElement() throws Exception {
        GltfWriter w = new GltfWriter();
        int mesh = tetrahedron(w);
        w.rootNode(map("mesh", mesh, "extensions", map("EXT_mesh_gpu_instancing", map("attributes",
                map("TRANSLATION", w.floats("VEC3", 0, 0, 0, 1, 1, 1), "SCALE", w.floats("VEC3", 1, 1, 1))))));
        Path file = w.writeGlb(dir.resolve("disagree.glb"));
        var e = catchThrowableOfType(SceneException.class, () -> SceneLoader.load(file));
        assertThat(e.getMessage()).contains("disagree.glb").contains("EXT_mesh_gpu_instancing")
                .contains("must have as many elements each (2, -, 1)").doesNotContain("\n");

        GltfWriter v = new GltfWriter();
        int m = tetrahedron(v);
        v.rootNode(map("mesh", m, "extensions", map("EXT_mesh_gpu_instancing", map("attributes",
                map("ROTATION", v.floats("VEC3", 0, 0, 0))))));
        Path vec3 = v.writeGlb(dir.resolve("vec3.glb"));
        var f = catchThrowableOfType(SceneException.class, () -> SceneLoader.load(vec3));
        assertThat(f.getMessage()).contains("vec3.glb").contains("ROTATION must be of type VEC4");
    }
}
