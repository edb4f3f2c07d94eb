package dev.strahl.accel;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.io.SceneLoader;
import dev.strahl.testing.MeshGeometry;
import dev.strahl.testing.Meshes;
import dev.strahl.world.World;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The SIMD kernel and its scalar twin give the same bits: for every ray the same answer, the same
 * primitive (also where two triangles tie, which a different order of visits would break), the
 * same distance and barycentrics to the last bit, with and without back-face culling, and the
 * same occlusion answers; on random soups (slivers, coincident and coplanar triangles, shared
 * edges, spheres), on the Cornell Box and on closed meshes, with rays aimed exactly at vertices
 * and edges (where the SIMD kernel hands a block to the scalar test).
 */
class KernelTwinsTest {
    private static final int RAYS = 4000;

    static Stream<BvhTest.Scene> scenes() throws Exception {
        List<BvhTest.Scene> scenes = new ArrayList<>(BvhTest.scenes().toList());
        scenes.add(new BvhTest.Scene("Cornell Box", World.of(SceneLoader.load(Path.of("scenes/cornell-box.json"))).geometry()));
        scenes.add(new BvhTest.Scene("Cornell Box with spheres", World.of(SceneLoader.load(Path.of("scenes/cornell-sphere.json"))).geometry()));
        scenes.add(new BvhTest.Scene("closed icosphere", new MeshGeometry().addMesh(Meshes.icosphere(4, 1, false), new int[5120], true).build()));
        return scenes.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void simdAndScalarKernelsGiveTheSameBits(BvhTest.Scene scene) {
        BvhTest.assumeSimd();
        Bvh simd = Bvh.build(scene.geometry()).withSimd(true), scalar = simd.withSimd(false);
        assertThat(simd.usesSimd()).isTrue();
        assertThat(scalar.usesSimd()).isFalse();
        Geometry g = simd.geometry();
        TraversalStack stack = new TraversalStack();
        SplittableRandom random = new SplittableRandom(scene.name().hashCode());
        Aabb box = g.bounds();
        SurfacePoint sp = new SurfacePoint();
        int hits = 0, edgeRays = 0;
        for (int i = 0; i < RAYS; i++) {
            Ray r = i % 4 == 3 ? throughAnEdge(random, g, box, sp) : BvhTest.randomRay(random, g, box, sp);
            edgeRays += i % 4 == 3 ? 1 : 0;
            double tMax = random.nextInt(4) == 0 ? random.nextDouble(0, 2 * Math.max(box.diagonal(), 0.1)) : Double.POSITIVE_INFINITY;
            for (boolean cull : new boolean[] {false, true}) {
                Ray ra = new Ray().set(r.o, r.d, tMax), rb = new Ray().set(r.o, r.d, tMax);
                Hit ha = new Hit().reset(), hb = new Hit().reset();
                boolean fa = simd.intersect(ra, ha, stack, cull), fb = scalar.intersect(rb, hb, stack, cull);
                String what = scene + ", ray " + i + " " + r + ", tMax " + tMax + ", cull " + cull;
                assertThat(fa).as(what).isEqualTo(fb);
                assertThat(ha.prim).as(what).isEqualTo(hb.prim);
                assertThat(Double.doubleToRawLongBits(ha.t)).as(what).isEqualTo(Double.doubleToRawLongBits(hb.t));
                assertThat(Double.doubleToRawLongBits(ra.tMax)).as(what).isEqualTo(Double.doubleToRawLongBits(rb.tMax));
                if (fa) {
                    hits++;
                    assertThat(Double.doubleToRawLongBits(ha.b1)).as(what).isEqualTo(Double.doubleToRawLongBits(hb.b1));
                    assertThat(Double.doubleToRawLongBits(ha.b2)).as(what).isEqualTo(Double.doubleToRawLongBits(hb.b2));
                }
            }
            assertThat(simd.occluded(new Ray().set(r.o, r.d, tMax), stack)).as("%s, ray %d", scene, i)
                    .isEqualTo(scalar.occluded(new Ray().set(r.o, r.d, tMax), stack));
        }
        assertThat(hits).as("the rays must exercise hits").isGreaterThan(RAYS / 4);
        assertThat(edgeRays).isPositive();
    }

    /** A ray from a random point at a vertex or at a point of an edge of a random triangle (edge functions of zero). */
    private static Ray throughAnEdge(SplittableRandom random, Geometry g, Aabb box, SurfacePoint sp) {
        if (g.triangleCount() == 0) {
            return BvhTest.randomRay(random, g, box, sp);
        }
        float[] p = g.positionArray();
        int[] tri = g.indexArray();
        int t = random.nextInt(g.triangleCount()), k = random.nextInt(3);
        int a = 3 * tri[3 * t + k], b = 3 * tri[3 * t + (k + 1) % 3];
        double s = random.nextInt(3) == 0 ? random.nextInt(2) : 0.5;
        Vector3d target = new Vector3d(p[a], p[a + 1], p[a + 2]).lerp(new Vector3d(p[b], p[b + 1], p[b + 2]), s);
        Vector3d o = new Vector3d(box.minX + random.nextDouble() * Math.max(box.extent(0), 0.1), box.minY + random.nextDouble() * Math.max(box.extent(1), 0.1),
                box.minZ + random.nextDouble() * Math.max(box.extent(2), 0.1));
        if (random.nextBoolean()) {
            // Axis-parallel through the point: exact float coordinates, so the edge functions of a ray through an edge are exactly zero.
            int axis = random.nextInt(3);
            o.set(target);
            o.setComponent(axis, target.get(axis) - 1);
        }
        Vector3d d = target.sub(o, new Vector3d());
        if (d.lengthSquared() == 0) {
            d.set(0, 0, 1);
        }
        return new Ray().set(o, d.normalize(), Double.POSITIVE_INFINITY);
    }

    /** The batch queries answer what the single-ray queries answer, ray by ray. */
    @Test
    void batchQueriesAnswerAsSingleRays() throws Exception {
        Aggregate bvh = World.of(SceneLoader.load(Path.of("scenes/cornell-sphere.json"))).bvh();
        Geometry g = bvh.geometry();
        SplittableRandom random = new SplittableRandom(3);
        int n = 500;
        RayBatch batch = new RayBatch(n + 7);
        Ray[] rays = new Ray[n];
        SurfacePoint sp = new SurfacePoint();
        for (int i = 0; i < n; i++) {
            rays[i] = BvhTest.randomRay(random, g, g.bounds(), sp);
            rays[i].tMax = i % 3 == 0 ? 1.5 : Double.POSITIVE_INFINITY;
            batch.set(i + 7, rays[i].o.x, rays[i].o.y, rays[i].o.z, rays[i].d.x, rays[i].d.y, rays[i].d.z, rays[i].tMax);
        }
        TraversalStack stack = new TraversalStack();
        for (boolean cull : new boolean[] {false, true}) {
            bvh.intersect(batch, 7, n + 7, stack, cull);
            bvh.occluded(batch, 7, n + 7, stack);
            for (int i = 0; i < n; i++) {
                Ray r = new Ray().set(rays[i].o, rays[i].d, rays[i].tMax);
                Hit hit = new Hit().reset();
                boolean found = bvh.intersect(r, hit, stack, cull);
                assertThat(batch.prim[i + 7]).as("ray %d", i).isEqualTo(found ? hit.prim : -1);
                if (found) {
                    assertThat(batch.t[i + 7]).isEqualTo(hit.t);
                    assertThat(batch.tMax[i + 7]).isEqualTo(hit.t);
                    assertThat(batch.b1[i + 7]).isEqualTo(hit.b1);
                    assertThat(batch.b2[i + 7]).isEqualTo(hit.b2);
                } else {
                    assertThat(batch.tMax[i + 7]).isEqualTo(rays[i].tMax);
                }
                assertThat(batch.occluded[i + 7]).isEqualTo(bvh.occluded(new Ray().set(rays[i].o, rays[i].d, batch.tMax[i + 7]), stack));
                batch.tMax[i + 7] = rays[i].tMax;
            }
        }
    }
}
