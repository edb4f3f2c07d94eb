package dev.strahl.accel;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.InstanceTransforms;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.testing.MeshGeometry;
import dev.strahl.testing.Meshes;
import java.util.List;
import java.util.SplittableRandom;
import org.joml.Matrix4d;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The two-level BVH answers as a loop over every instance and every primitive does, on the same
 * rays moved into each instance's coordinates: the same instance, primitive, distance and
 * barycentrics to the last bit, with and without culling, and the same occlusion answers; with
 * the SIMD kernel and its scalar twin alike. The instances are moved, rotated, scaled unequally
 * along the axes and mirrored, and overlap.
 */
class TwoLevelBvhTest {
    private static final int RAYS = 6000;

    /** A closed icosphere, a soup of small triangles, and two spheres (ellipsoids once scaled unequally). */
    static List<Geometry> groups() {
        Geometry ball = new MeshGeometry().addMesh(Meshes.icosphere(3, 1, false), new int[1280], true).build();
        SplittableRandom r = new SplittableRandom(5);
        int n = 200;
        float[] p = new float[9 * n];
        for (int i = 0; i < p.length; i++) {
            p[i] = (float) r.nextDouble(-1, 1);
        }
        int[] idx = new int[3 * n];
        for (int i = 0; i < idx.length; i++) {
            idx[i] = i;
        }
        MeshGeometry soup = new MeshGeometry().addMesh(new TriangleMesh(p, idx, null, null), new int[n], false);
        soup.addSphere(new Vector3d(0.3, 0.2, -0.1), 0.4, 0).addSphere(new Vector3d(-0.5, -0.4, 0.2), 0.25, 0);
        return List.of(ball, soup.build());
    }

    /** Instances on a grid with random rotations, unequal scales and mirrors; some overlap their neighbours. */
    static InstanceTransforms placements(int count, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        int[] group = new int[count];
        double[] m = new double[12 * count];
        for (int i = 0; i < count; i++) {
            group[i] = r.nextInt(2);
            double sx = r.nextDouble(0.3, 1.6), sy = r.nextDouble(0.3, 1.6), sz = r.nextDouble(0.3, 1.6);
            if (r.nextInt(3) == 0) {
                sx = -sx;                                    // a mirror
            }
            Matrix4d t = new Matrix4d().translation(2.2 * (i % 6) + r.nextDouble(-0.5, 0.5), r.nextDouble(-1, 1), 2.2 * (i / 6))
                    .rotate(Math.toRadians(r.nextDouble(360)), new Vector3d(r.nextGaussian(), r.nextGaussian(), r.nextGaussian()).normalize())
                    .scale(sx, sy, sz);
            for (int row = 0; row < 3; row++) {
                for (int col = 0; col < 4; col++) {
                    m[12 * i + 4 * row + col] = t.get(col, row);
                }
            }
        }
        return new InstanceTransforms(group, m);
    }

    static Geometry floor() {
        float[] p = {-5, -2, -5, 20, -2, -5, 20, -2, 20, -5, -2, 20};
        return new MeshGeometry().addMesh(new TriangleMesh(p, new int[] {0, 2, 1, 0, 3, 2}, null, null), new int[2], false).build();
    }

    @Test
    void treeAndLoopOverEveryInstanceGiveTheSameBits() {
        TwoLevelBvh tree = TwoLevelBvh.build(floor(), groups(), placements(36, 1));
        TwoLevelBvh brute = (TwoLevelBvh) tree.bruteForce();
        int hits = compare(tree, brute, 11);
        assertThat(hits).as("rays that hit an instance").isGreaterThan(RAYS / 4);
    }

    @Test
    void simdAndScalarKernelsGiveTheSameBitsThroughInstances() {
        BvhTest.assumeSimd();
        TwoLevelBvh tree = TwoLevelBvh.build(floor(), groups(), placements(36, 2));
        compare(tree.withSimd(true), tree.withSimd(false), 12);
    }

    @Test
    void anInstanceHitLiesOnTheMovedSurface() {
        InstanceTransforms inst = placements(36, 3);
        TwoLevelBvh tree = TwoLevelBvh.build(new MeshGeometry().build(), groups(), inst);
        TraversalStack stack = new TraversalStack();
        SplittableRandom r = new SplittableRandom(4);
        SurfacePoint sp = new SurfacePoint();
        int checked = 0;
        for (int i = 0; i < 2000; i++) {
            Ray ray = aimedRay(r, tree, sp);
            Hit hit = new Hit().reset();
            if (!tree.intersect(ray, hit, stack, false)) {
                continue;
            }
            // The hit point through the instance's matrix is where the world ray is at t.
            Geometry g = tree.groupGeometry(inst.group(hit.instance));
            Vector3d onRay = ray.at(hit.t, new Vector3d());
            if (g.isTriangle(hit.prim)) {
                g.surfaceAt(hit, sp);
                inst.pointToWorld(hit.instance, sp.p);
                assertThat(sp.p.distance(onRay)).as("ray %d", i).isLessThan(1e-5 * (1 + onRay.length()));
                checked++;
            }
        }
        assertThat(checked).isGreaterThan(500);
    }

    /** Rays from around the instances' bounds, half aimed at a point on a random instance. */
    private static Ray aimedRay(SplittableRandom r, TwoLevelBvh tree, SurfacePoint sp) {
        InstanceTransforms inst = tree.instances();
        Vector3d o = new Vector3d(r.nextDouble(-4, 16), r.nextDouble(-4, 4), r.nextDouble(-4, 16));
        Vector3d d;
        if (r.nextBoolean()) {
            int i = r.nextInt(inst.count());
            Geometry g = tree.groupGeometry(inst.group(i));
            g.samplePoint(r.nextInt(g.primitiveCount()), r.nextDouble(), r.nextDouble(), sp);
            d = inst.pointToWorld(i, new Vector3d(sp.p)).sub(o);
        } else if (r.nextInt(4) == 0) {
            d = new Vector3d(0, 0, 0).setComponent(r.nextInt(3), r.nextBoolean() ? 1 : -1);   // axis-aligned: zero components
        } else {
            d = new Vector3d(r.nextGaussian(), r.nextGaussian(), r.nextGaussian());
        }
        return new Ray().set(o, d.normalize(), r.nextInt(5) == 0 ? r.nextDouble(0.5, 10) : Double.POSITIVE_INFINITY);
    }

    private static int compare(TwoLevelBvh a, TwoLevelBvh b, long seed) {
        TraversalStack stack = new TraversalStack();
        SplittableRandom r = new SplittableRandom(seed);
        SurfacePoint sp = new SurfacePoint();
        int instanceHits = 0;
        for (int i = 0; i < RAYS; i++) {
            Ray ray = aimedRay(r, a, sp);
            for (boolean cull : new boolean[] {false, true}) {
                Ray ra = new Ray().set(ray.o, ray.d, ray.tMax), rb = new Ray().set(ray.o, ray.d, ray.tMax);
                Hit ha = new Hit().reset(), hb = new Hit().reset();
                boolean fa = a.intersect(ra, ha, stack, cull), fb = b.intersect(rb, hb, stack, cull);
                String what = "ray " + i + " " + ray + ", cull " + cull;
                assertThat(fa).as(what).isEqualTo(fb);
                assertThat(ha.instance).as(what).isEqualTo(hb.instance);
                assertThat(ha.prim).as(what).isEqualTo(hb.prim);
                assertThat(Double.doubleToRawLongBits(ha.t)).as(what).isEqualTo(Double.doubleToRawLongBits(hb.t));
                assertThat(Double.doubleToRawLongBits(ra.tMax)).as(what).isEqualTo(Double.doubleToRawLongBits(rb.tMax));
                if (fa) {
                    assertThat(Double.doubleToRawLongBits(ha.b1)).as(what).isEqualTo(Double.doubleToRawLongBits(hb.b1));
                    assertThat(Double.doubleToRawLongBits(ha.b2)).as(what).isEqualTo(Double.doubleToRawLongBits(hb.b2));
                    instanceHits += !cull && ha.instance >= 0 ? 1 : 0;
                }
            }
            assertThat(a.occluded(new Ray().set(ray.o, ray.d, ray.tMax), stack)).as("ray %d", i)
                    .isEqualTo(b.occluded(new Ray().set(ray.o, ray.d, ray.tMax), stack));
        }
        return instanceHits;
    }

    @Test
    void bytesCountEachGroupOnce() {
        List<Geometry> groups = groups();
        TwoLevelBvh few = TwoLevelBvh.build(floor(), groups, placements(2, 1));
        TwoLevelBvh many = TwoLevelBvh.build(floor(), groups, placements(200, 1));
        // 198 instances more cost their matrices and the top-level tree's nodes, not their triangles.
        assertThat(many.byteSize() - few.byteSize()).isLessThan(198L * 400);
    }
}
