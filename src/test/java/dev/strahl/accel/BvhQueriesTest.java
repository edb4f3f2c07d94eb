package dev.strahl.accel;

import dev.strahl.world.World;
import dev.strahl.testing.MeshGeometry;
import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.scene.Scene;
import dev.strahl.io.SceneLoader;
import dev.strahl.testing.Meshes;
import java.nio.file.Path;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The two queries agree with each other and with brute force where the float slab tests are
 * most at risk: any-hit is exactly "the closest hit lies before tMax", on the Cornell Box and on a
 * closed mesh, for ordinary rays and for rays grazing the walls (in their planes, parallel to
 * them, a hair inside or outside), on both box-test paths.
 */
class BvhQueriesTest {

    @Test
    void anyHitIsExactlyAClosestHitBeforeTMax() throws Exception {
        Scene cornell = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        Geometry sphere = new MeshGeometry().addMesh(Meshes.icosphere(3, 1, false), new int[1280], true).build();
        for (Bvh base : new Bvh[] {(Bvh) World.of(cornell).bvh(), Bvh.build(sphere)}) {
            for (boolean simd : new boolean[] {false, true}) {
                if (simd) {
                    BvhTest.assumeSimd();
                }
                Bvh bvh = base.withSimd(simd);
                TraversalStack stack = Bvh.newStack();
                SplittableRandom random = new SplittableRandom(7);
                int hits = 0;
                for (int i = 0; i < 20_000; i++) {
                    Vector3d o = new Vector3d(random.nextDouble(-1.2, 1.2), random.nextDouble(-0.2, 2.2), random.nextDouble(-1.2, 1.2));
                    Vector3d d = new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
                    Ray closest = new Ray().set(o, d, Double.POSITIVE_INFINITY);
                    Hit hit = new Hit().reset();
                    boolean found = bvh.intersect(closest, hit, stack, false);
                    double tMax = random.nextDouble(0, 4);
                    boolean expected = found && hit.t < tMax;
                    assertThat(bvh.occluded(new Ray().set(o, d, tMax), stack)).as("simd %s, ray %d, tMax %s, closest %s", simd, i, tMax, hit.t).isEqualTo(expected);
                    if (found) {
                        // Just beyond and just short of the closest hit.
                        assertThat(bvh.occluded(new Ray().set(o, d, Math.nextUp(hit.t)), stack)).isTrue();
                        assertThat(bvh.occluded(new Ray().set(o, d, hit.t), stack)).as("tMax is exclusive").isFalse();
                        hits++;
                    }
                }
                assertThat(hits).isGreaterThan(5_000);
            }
        }
    }

    @Test
    void raysGrazingTheCornellBoxWallsAgreeWithBruteForce() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        Geometry g = World.of(scene).geometry();
        SplittableRandom random = new SplittableRandom(8);
        double[] walls = {-1.0, 0.0, 1.99, -1.04};               // x of the red wall, y of floor and ceiling, z of the back wall
        for (boolean simd : new boolean[] {false, true}) {
            if (simd) {
                BvhTest.assumeSimd();
            }
            Bvh bvh = ((Bvh) World.of(scene).bvh()).withSimd(simd);
            TraversalStack stack = Bvh.newStack();
            for (int i = 0; i < 20_000; i++) {
                int w = random.nextInt(walls.length);
                int axis = w == 0 ? 0 : w == 3 ? 2 : 1;
                double offset = switch (random.nextInt(4)) {
                    case 0 -> 0;
                    case 1 -> 1e-7;
                    case 2 -> -1e-7;
                    default -> random.nextDouble(-1e-4, 1e-4);
                };
                Vector3d o = new Vector3d(random.nextDouble(-0.9, 0.9), random.nextDouble(0.1, 1.9), random.nextDouble(-0.9, 0.9));
                o.setComponent(axis, walls[w] + offset);
                Vector3d d = new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
                d.setComponent(axis, random.nextBoolean() ? 0 : 1e-9 * random.nextGaussian());
                d.normalize();
                Ray r = new Ray().set(o, d, Double.POSITIVE_INFINITY);
                Hit hit = new Hit().reset(), brute = new Hit().reset();
                boolean found = bvh.intersect(r, hit, stack, false);
                boolean expected = g.intersect(0, g.triangleCount(), new Ray().set(o, d, Double.POSITIVE_INFINITY), brute, false);
                assertThat(found).as("simd %s, grazing ray %d %s", simd, i, r).isEqualTo(expected);
                if (found && hit.prim != brute.prim) {
                    assertThat(hit.t).as("a tie").isEqualTo(brute.t);
                }
                double tMax = random.nextDouble(0, 3);
                assertThat(bvh.occluded(new Ray().set(o, d, tMax), stack))
                        .isEqualTo(g.occludes(0, g.triangleCount(), new Ray().set(o, d, tMax)));
            }
        }
    }
}
