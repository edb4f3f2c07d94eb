package dev.strahl.accel;

import dev.strahl.testing.MeshGeometry;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.Sphere;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.scene.TriangleMesh;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.joml.Vector3d;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The BVH must answer exactly what a loop over all primitives answers: the same closest hit (same
 * t, same primitive unless two tie), the same any-hit answer, with culling on and off, on random
 * soups and on the shapes that break binning (slivers, coincident and coplanar triangles).
 */
class BvhTest {
    private static final int RAYS = 3000;

    record Scene(String name, Geometry geometry) {
        @Override
        public String toString() {
            return name + " (" + geometry.triangleCount() + " triangles, " + geometry.sphereCount() + " spheres)";
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Scenes

    static Stream<Scene> scenes() {
        List<Scene> scenes = new ArrayList<>();
        for (int n : new int[] {1, 2, 5, 100, 5000}) {
            scenes.add(soup("random soup", n, 0, n, r -> smallTriangle(r, 0.15)));
        }
        scenes.add(soup("long thin slivers", 300, 0, 30, BvhTest::sliver));
        scenes.add(soup("coincident triangles", 400, 0, 31, coincident()));
        scenes.add(soup("coplanar, axis-aligned plane", 500, 0, 32, r -> inPlaneZ(r, 0.5f)));
        scenes.add(soup("coplanar, tilted plane", 500, 0, 33, BvhTest::inTiltedPlane));
        scenes.add(soup("grid of quads sharing edges", 0, 0, 34, null));
        scenes.add(soup("triangles and spheres", 300, 60, 35, r -> smallTriangle(r, 0.2)));
        scenes.add(soup("spheres only", 0, 40, 36, null));
        return scenes.stream();
    }

    @FunctionalInterface
    interface TriangleMaker {
        /** Nine floats: one triangle. */
        float[] make(SplittableRandom random);
    }

    /**
     * A soup of n triangles (the first half in a mesh flagged closed, so culling has something to
     * cull) and s spheres inside the unit cube. The grid scene is built when {@code maker} is null
     * and n = 0 and s = 0.
     */
    private static Scene soup(String name, int n, int s, long seed, TriangleMaker maker) {
        SplittableRandom random = new SplittableRandom(seed);
        MeshGeometry builder = new MeshGeometry();
        if (maker == null && n == 0 && s == 0) {
            addGrid(builder);
        }
        int closed = n / 2;
        for (int part = 0; part < 2; part++) {
            int count = part == 0 ? closed : n - closed;
            if (count == 0) {
                continue;
            }
            float[] xyz = new float[9 * count];
            for (int t = 0; t < count; t++) {
                System.arraycopy(maker.make(random), 0, xyz, 9 * t, 9);
            }
            builder.addMesh(mesh(xyz), new int[count], part == 0);
        }
        for (int i = 0; i < s; i++) {
            double r = i == 0 ? 0.45 : random.nextDouble(0.005, 0.1);      // one big sphere overlapping the rest
            builder.addSphere(new Vector3d(random.nextDouble(), random.nextDouble(), random.nextDouble()), r, 0);
        }
        return new Scene(name, builder.build());
    }

    private static TriangleMesh mesh(float[] xyz) {
        int[] idx = new int[xyz.length / 3];
        for (int i = 0; i < idx.length; i++) {
            idx[i] = i;
        }
        return new TriangleMesh(xyz, idx, null);
    }

    private static float[] smallTriangle(SplittableRandom random, double size) {
        double cx = random.nextDouble(), cy = random.nextDouble(), cz = random.nextDouble();
        float[] t = new float[9];
        for (int k = 0; k < 3; k++) {
            t[3 * k] = (float) (cx + size * random.nextDouble(-1, 1));
            t[3 * k + 1] = (float) (cy + size * random.nextDouble(-1, 1));
            t[3 * k + 2] = (float) (cz + size * random.nextDouble(-1, 1));
        }
        return t;
    }

    /** A triangle with one edge across the cube and a width of 1e-4. */
    private static float[] sliver(SplittableRandom random) {
        double ax = random.nextDouble(), ay = random.nextDouble(), az = random.nextDouble();
        double bx = random.nextDouble(), by = random.nextDouble(), bz = random.nextDouble();
        return new float[] {(float) ax, (float) ay, (float) az, (float) bx, (float) by, (float) bz,
            (float) (ax + 1e-4), (float) (ay + 1e-4 * random.nextDouble()), (float) (az - 1e-4)};
    }

    /** Mostly copies of three triangles, a few random ones. */
    private static TriangleMaker coincident() {
        float[][] copies = {
            {0.1f, 0.1f, 0.1f, 0.9f, 0.2f, 0.3f, 0.4f, 0.8f, 0.6f},
            {0.3f, 0.3f, 0.3f, 0.3f, 0.6f, 0.3f, 0.3f, 0.3f, 0.6f},
            {0.5f, 0.5f, 0.5f, 0.51f, 0.5f, 0.5f, 0.5f, 0.51f, 0.5f}};
        return random -> random.nextInt(10) == 0 ? smallTriangle(random, 0.1) : copies[random.nextInt(copies.length)].clone();
    }

    private static float[] inPlaneZ(SplittableRandom random, float z) {
        float[] t = smallTriangle(random, 0.1);
        t[2] = t[5] = t[8] = z;
        return t;
    }

    /** Float vertices on the plane x + 2y + 3z = 2 (up to rounding to float). */
    private static float[] inTiltedPlane(SplittableRandom random) {
        float[] t = smallTriangle(random, 0.1);
        for (int k = 0; k < 3; k++) {
            t[3 * k + 2] = (float) ((2.0 - t[3 * k] - 2.0 * t[3 * k + 1]) / 3);
        }
        return t;
    }

    /** A 16 × 16 grid of unit-fraction quads in the plane y = 0.25, vertices shared, like a tessellated floor. */
    private static void addGrid(MeshGeometry builder) {
        int cells = 16, side = cells + 1;
        float[] xyz = new float[3 * side * side];
        for (int i = 0; i < side; i++) {
            for (int j = 0; j < side; j++) {
                int v = 3 * (i * side + j);
                xyz[v] = (float) i / cells;
                xyz[v + 1] = 0.25f;
                xyz[v + 2] = (float) j / cells;
            }
        }
        int[] idx = new int[6 * cells * cells];
        int k = 0;
        for (int i = 0; i < cells; i++) {
            for (int j = 0; j < cells; j++) {
                int a = i * side + j, b = a + 1, c = a + side, d = c + 1;
                idx[k++] = a;
                idx[k++] = b;
                idx[k++] = d;
                idx[k++] = a;
                idx[k++] = d;
                idx[k++] = c;
            }
        }
        builder.addMesh(new TriangleMesh(xyz, idx, null), new int[2 * cells * cells], true);
    }

    // ---------------------------------------------------------------------------------------------
    // Rays

    /**
     * Random rays of several kinds: from inside and outside the bounds with random directions,
     * aimed at points on random primitives, and with zero direction components (axis-aligned or
     * in a coordinate plane, origins sometimes exactly on a vertex's coordinate plane).
     */
    static Ray randomRay(SplittableRandom random, Geometry g, Aabb box, SurfacePoint sp) {
        double ex = Math.max(box.extent(0), 0.1), ey = Math.max(box.extent(1), 0.1), ez = Math.max(box.extent(2), 0.1);
        Vector3d o;
        if (random.nextBoolean()) {
            o = new Vector3d(box.minX + ex * random.nextDouble(), box.minY + ey * random.nextDouble(), box.minZ + ez * random.nextDouble());
        } else {
            o = new Vector3d(box.minX + ex * random.nextDouble(-1, 2), box.minY + ey * random.nextDouble(-1, 2), box.minZ + ez * random.nextDouble(-1, 2));
        }
        Vector3d d;
        switch (random.nextInt(4)) {
            case 0 -> d = new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            case 1 -> {
                g.samplePoint(random.nextInt(g.primitiveCount()), random.nextDouble(), random.nextDouble(), sp);
                d = new Vector3d(sp.p).sub(o);
            }
            case 2 -> {
                double[] c = {0, 0, 0};
                int axis = random.nextInt(3);
                c[axis] = random.nextBoolean() ? 1 : -1;
                if (random.nextBoolean()) {
                    c[(axis + 1) % 3] = random.nextGaussian();       // in a coordinate plane
                }
                if (random.nextInt(4) == 0) {
                    c[(axis + 2) % 3] = -0.0;
                }
                d = new Vector3d(c[0], c[1], c[2]);
                // Put the origin on a primitive's bounding plane across a zero component, to provoke 0·∞ in the slabs.
                Aabb pb = new Aabb();
                g.includeBounds(random.nextInt(g.primitiveCount()), pb);
                int zero = (axis + 2) % 3;
                double plane = random.nextBoolean() ? pb.min(zero) : pb.max(zero);
                o.setComponent(zero, plane);
            }
            default -> {
                // Aim along a zero-component direction at a point on a primitive.
                g.samplePoint(random.nextInt(g.primitiveCount()), random.nextDouble(), random.nextDouble(), sp);
                int axis = random.nextInt(3);
                d = new Vector3d();
                d.setComponent(axis, random.nextBoolean() ? 1 : -1);
                o.set(sp.p).sub(new Vector3d(d).mul(random.nextDouble(0.01, 2)));
            }
        }
        if (d.lengthSquared() == 0) {
            d.set(0, 0, 1);
        }
        return new Ray().set(o, d.normalize(), Double.POSITIVE_INFINITY);
    }

    private static Ray copy(Ray r, double tMax) {
        return new Ray().set(r.o, r.d, tMax);
    }

    private static boolean bruteIntersect(Geometry g, Ray ray, Hit hit, boolean cull) {
        boolean found = false;
        for (int i = 0; i < g.primitiveCount(); i++) {
            found |= g.intersect(i, ray, hit, cull);
        }
        return found;
    }

    private static boolean bruteOccluded(Geometry g, Ray ray) {
        for (int i = 0; i < g.primitiveCount(); i++) {
            if (g.occludes(i, ray)) {
                return true;
            }
        }
        return false;
    }

    // ---------------------------------------------------------------------------------------------
    // Agreement with brute force

    /** The tests run with the Vector API module (surefire's argLine), to cover the SIMD kernel too; it needs 256-bit vectors. */
    static void assumeSimd() {
        assertThat(ModuleLayer.boot().findModule("jdk.incubator.vector")).as("the tests run with the Vector API module").isPresent();
        Assumptions.assumeTrue(Simd.AVAILABLE, "the processor has no 256-bit vectors: the SIMD kernel does not run here");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void closestHitEqualsBruteForce(Scene scene) {
        closestHitEqualsBruteForce(scene, false);
        assumeSimd();
        closestHitEqualsBruteForce(scene, true);
    }

    private void closestHitEqualsBruteForce(Scene scene, boolean simd) {
        Bvh bvh = Bvh.build(scene.geometry()).withSimd(simd);
        Geometry g = bvh.geometry();
        TraversalStack stack = Bvh.newStack();
        SplittableRandom random = new SplittableRandom(scene.name().hashCode() + g.primitiveCount());
        Aabb box = g.bounds();
        SurfacePoint sp = new SurfacePoint();
        int hits = 0;
        for (int i = 0; i < RAYS; i++) {
            Ray r = randomRay(random, g, box, sp);
            for (boolean cull : new boolean[] {false, true}) {
                Ray rb = copy(r, r.tMax), rf = copy(r, r.tMax);
                Hit hb = new Hit().reset(), hf = new Hit().reset();
                boolean expected = bruteIntersect(g, rf, hf, cull);
                boolean actual = bvh.intersect(rb, hb, stack, cull);
                String what = "%s, simd %s, cull %s, ray %d %s";        // formatted only on failure
                Object[] args = {scene, simd, cull, i, r};
                assertThat(actual).as(what, args).isEqualTo(expected);
                assertThat(rb.o).isEqualTo(r.o);
                assertThat(rb.d).isEqualTo(r.d);
                if (!expected) {
                    assertThat(rb.tMax).as(what, args).isEqualTo(r.tMax);
                    assertThat(hb.prim).isEqualTo(-1);
                    continue;
                }
                hits++;
                assertThat(rb.tMax).as(what, args).isEqualTo(hb.t);
                if (hb.t != hf.t) {
                    assertThat(hb.t).as(what + ": t differs from brute force beyond round-off", args).isCloseTo(hf.t, within(1e-12 * hf.t));
                }
                if (hb.prim != hf.prim) {
                    // A tie: the BVH's primitive alone must be hit at the same distance.
                    Hit alone = new Hit().reset();
                    assertThat(g.intersect(hb.prim, copy(r, r.tMax), alone, cull)).as(what, args).isTrue();
                    assertThat(alone.t).as(what + ": prim %d vs brute force prim %d", scene, simd, cull, i, r, hb.prim, hf.prim).isCloseTo(hf.t, within(1e-12 * hf.t));
                } else {
                    assertThat(hb.b1).as(what, args).isEqualTo(hf.b1);
                    assertThat(hb.b2).as(what, args).isEqualTo(hf.b2);
                }
            }
        }
        assertThat(hits).as("the rays must exercise hits, not only misses").isGreaterThan(RAYS / 4);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void anyHitEqualsBruteForceForFiniteTMax(Scene scene) {
        anyHitEqualsBruteForceForFiniteTMax(scene, false);
        assumeSimd();
        anyHitEqualsBruteForceForFiniteTMax(scene, true);
    }

    private void anyHitEqualsBruteForceForFiniteTMax(Scene scene, boolean simd) {
        Bvh bvh = Bvh.build(scene.geometry()).withSimd(simd);
        Geometry g = bvh.geometry();
        TraversalStack stack = Bvh.newStack();
        SplittableRandom random = new SplittableRandom(~scene.name().hashCode() + g.primitiveCount());
        Aabb box = g.bounds();
        SurfacePoint sp = new SurfacePoint();
        int occluded = 0;
        for (int i = 0; i < RAYS; i++) {
            Ray r = randomRay(random, g, box, sp);
            double tMax = random.nextInt(8) == 0 ? Double.POSITIVE_INFINITY : random.nextDouble(0, 2 * Math.max(box.diagonal(), 0.1));
            boolean expected = bruteOccluded(g, copy(r, tMax));
            Ray rb = copy(r, tMax);
            assertThat(bvh.occluded(rb, stack)).as("%s, simd %s, ray %d %s, tMax %s", scene, simd, i, r, tMax).isEqualTo(expected);
            assertThat(rb.tMax).as("occlusion queries leave the ray alone").isEqualTo(tMax);
            occluded += expected ? 1 : 0;
        }
        assertThat(occluded).isGreaterThan(RAYS / 10);
    }

    // ---------------------------------------------------------------------------------------------
    // Structure

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void nodesBoundTheirPrimitivesAndLeavesAreSmall(Scene scene) {
        Bvh bvh = Bvh.build(scene.geometry());
        Geometry g = bvh.geometry();
        Bvh.Layout layout = bvh.layout();
        int n = g.primitiveCount();
        assertThat(bvh.nodeCount()).isBetween(1, Math.max(1, n - 1));
        assertThat(layout.nodes()).hasSize(BvhLayout.NODE * bvh.nodeCount());
        boolean[] visited = new boolean[bvh.nodeCount()];
        int[] primSeen = new int[n];
        boolean[] blockSeen = new boolean[layout.blocks().length / BvhLayout.BLOCK];
        Aabb all = new Aabb();
        int maxDepth = checkNode(g, layout, 0, 1, visited, primSeen, blockSeen, all);
        assertThat(maxDepth).as("depth within the limit the traversal stack is sized for").isLessThanOrEqualTo(BvhLayout.MAX_DEPTH);
        for (int i = 0; i < visited.length; i++) {
            assertThat(visited[i]).as("node %d reachable", i).isTrue();
        }
        for (int p = 0; p < n; p++) {
            assertThat(primSeen[p]).as("primitive %d in exactly one leaf", p).isEqualTo(1);
        }
        for (int b = 0; b < blockSeen.length; b++) {
            assertThat(blockSeen[b]).as("block %d in a leaf", b).isTrue();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void reorderedGeometryHoldsTheSamePrimitives(Scene scene) {
        Geometry original = scene.geometry();
        Geometry g = Bvh.build(original).geometry();
        assertThat(g.triangleCount()).isEqualTo(original.triangleCount());
        assertThat(g.sphereCount()).isEqualTo(original.sphereCount());
        List<String> before = new ArrayList<>(), after = new ArrayList<>();
        for (int p = 0; p < original.primitiveCount(); p++) {
            before.add(describe(original, p));
            after.add(describe(g, p));
        }
        assertThat(after).containsExactlyInAnyOrderElementsOf(before);
    }

    private static String describe(Geometry g, int prim) {
        Aabb b = new Aabb();
        g.includeBounds(prim, b);
        return g.isTriangle(prim) + " " + b + " " + g.area(prim) + " " + g.material(prim) + " " + g.isClosed(prim);
    }

    /**
     * Checks the subtree of node {@code node}: every child box encloses its subtree (the
     * primitives of leaves), leaves are small, homogeneous ranges, and a triangle leaf's blocks
     * hold exactly its triangles' vertices (NaN in unused lanes); returns the subtree's depth and
     * grows {@code dest} by its primitives.
     */
    private static int checkNode(Geometry g, Bvh.Layout layout, int node, int depth, boolean[] visited, int[] primSeen,
                                 boolean[] blockSeen, Aabb dest) {
        assertThat(visited[node]).as("node %d visited twice", node).isFalse();
        visited[node] = true;
        int deepest = depth;
        int used = 0;
        for (int c = 0; c < BvhLayout.WIDTH; c++) {
            int child = layout.child(node, c);
            Aabb subtree = new Aabb();
            if (child == BvhLayout.EMPTY) {
                for (int k = 0; k < 3; k++) {
                    assertThat(layout.box(node, k, c)).as("empty slot min").isEqualTo(Float.POSITIVE_INFINITY);
                    assertThat(layout.box(node, 3 + k, c)).as("empty slot max").isEqualTo(Float.NEGATIVE_INFINITY);
                }
                continue;
            }
            used++;
            if (child < 0 && BvhLayout.isSphereLeaf(child)) {
                int first = BvhLayout.firstSphere(child), count = BvhLayout.sphereCount(child);
                assertThat(count).as("leaf size").isBetween(1, BvhBuilder.MAX_LEAF);
                for (int p = first; p < first + count; p++) {
                    assertThat(g.isTriangle(p)).as("sphere leaf of spheres").isFalse();
                    primSeen[p]++;
                    g.includeBounds(p, subtree);
                }
            } else if (child < 0) {
                int blocks = BvhLayout.blockCount(child), prims = 0;
                for (int b = BvhLayout.firstBlock(child); b < BvhLayout.firstBlock(child) + blocks; b++) {
                    assertThat(blockSeen[b]).as("block %d in one leaf", b).isFalse();
                    blockSeen[b] = true;
                    prims += checkBlock(g, layout, b, primSeen, subtree);
                }
                assertThat(prims).as("leaf size").isBetween(1, BvhBuilder.MAX_LEAF).isGreaterThan(BvhLayout.LANES * (blocks - 1));
            } else {
                assertThat(child).as("children follow their parent").isGreaterThan(node).isLessThan(visited.length);
                deepest = Math.max(deepest, checkNode(g, layout, child, depth + 1, visited, primSeen, blockSeen, subtree));
            }
            for (int k = 0; k < 3; k++) {
                assertThat((double) layout.box(node, k, c)).as("node %d child %d min[%d]", node, c, k).isLessThanOrEqualTo(subtree.min(k));
                assertThat((double) layout.box(node, 3 + k, c)).as("node %d child %d max[%d]", node, c, k).isGreaterThanOrEqualTo(subtree.max(k));
            }
            dest.include(subtree);
        }
        assertThat(used).as("children of node %d", node).isGreaterThanOrEqualTo(node == 0 ? 1 : 2);
        return deepest;
    }

    /** One block: consecutive triangles, their vertices in the lanes, NaN beyond; returns its triangle count. */
    private static int checkBlock(Geometry g, Bvh.Layout layout, int b, int[] primSeen, Aabb dest) {
        int first = layout.blockPrim(b), count = layout.blockCount(b);
        assertThat(count).as("block %d count", b).isBetween(1, BvhLayout.LANES);
        float[] pos = g.positionArray();
        int[] tri = g.indexArray();
        for (int lane = 0; lane < BvhLayout.LANES; lane++) {
            for (int v = 0; v < 3; v++) {
                for (int k = 0; k < 3; k++) {
                    float x = layout.blocks()[BvhLayout.BLOCK * b + BvhLayout.LANES * (3 * v + k) + lane];
                    if (lane < count) {
                        assertThat(x).isEqualTo(pos[3 * tri[3 * (first + lane) + v] + k]);
                    } else {
                        assertThat(x).as("unused lane").isNaN();
                    }
                }
            }
        }
        for (int p = first; p < first + count; p++) {
            assertThat(g.isTriangle(p)).as("triangle leaf of triangles").isTrue();
            primSeen[p]++;
            g.includeBounds(p, dest);
        }
        return count;
    }

    @Test
    void emptyGeometryHasNoNodesAndNoHits() {
        Geometry empty = new MeshGeometry().build();
        Geometry onlyDegenerate = new MeshGeometry()
                .addMesh(mesh(new float[] {0, 0, 0, 1, 1, 1, 2, 2, 2}), new int[1], false).build();
        for (Geometry g : new Geometry[] {empty, onlyDegenerate}) {
            Bvh bvh = Bvh.build(g);
            assertThat(bvh.nodeCount()).isZero();
            Ray r = new Ray().set(new Vector3d(0.5, 0.5, -1), new Vector3d(0, 0, 1), Double.POSITIVE_INFINITY);
            Hit hit = new Hit().reset();
            assertThat(bvh.intersect(r, hit, Bvh.newStack(), false)).isFalse();
            assertThat(hit.prim).isEqualTo(-1);
            assertThat(bvh.occluded(r, Bvh.newStack())).isFalse();
        }
    }
}
