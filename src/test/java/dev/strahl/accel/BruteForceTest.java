package dev.strahl.accel;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.io.SceneLoader;
import dev.strahl.testing.MeshGeometry;
import dev.strahl.testing.Meshes;
import dev.strahl.world.World;
import java.nio.file.Path;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The teaching option {@code --accel none} ({@link BruteForce}): every query tests every
 * primitive, and finds what the tree finds: the same closest distance on triangles and spheres,
 * with and without back-face culling, the same primitive but on exact ties, the same occlusion.
 */
class BruteForceTest {

    @Test
    void bruteForceFindsTheTreesHitsOnTrianglesAndSpheres() throws Exception {
        Geometry closedSphere = new MeshGeometry().addMesh(Meshes.icosphere(3, 1, false), new int[1280], true).build();
        Aggregate[] trees = {World.of(SceneLoader.load(Path.of("scenes/cornell-box.json"))).bvh(),
            World.of(SceneLoader.load(Path.of("scenes/cornell-sphere.json"))).bvh(), Bvh.build(closedSphere)};
        for (Aggregate bvh : trees) {
            Aggregate brute = bvh.bruteForce();
            assertThat(brute).isInstanceOf(BruteForce.class);
            assertThat(brute.kernel()).isEqualTo("brute force");
            assertThat(bvh).isInstanceOf(Bvh.class);
            assertThat(brute.geometry()).isSameAs(bvh.geometry());
            TraversalStack stack = Bvh.newStack();
            SplittableRandom random = new SplittableRandom(19);
            int hits = 0, ties = 0;
            for (int i = 0; i < 20_000; i++) {
                Vector3d o = new Vector3d(random.nextDouble(-1.2, 1.2), random.nextDouble(-0.2, 2.2), random.nextDouble(-1.2, 1.2));
                Vector3d d = new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
                boolean cull = (i & 1) == 1;
                Ray a = new Ray().set(o, d, Double.POSITIVE_INFINITY);
                Ray b = new Ray().set(o, d, Double.POSITIVE_INFINITY);
                Hit ha = new Hit().reset();
                Hit hb = new Hit().reset();
                boolean fa = bvh.intersect(a, ha, stack, cull);
                boolean fb = brute.intersect(b, hb, stack, cull);
                assertThat(fb).as("ray %d", i).isEqualTo(fa);
                if (fa) {
                    hits++;
                    assertThat(hb.t).as("ray %d", i).isEqualTo(ha.t);
                    // On an exact tie (a shared edge) the loop may name the other triangle: count those.
                    ties += hb.prim != ha.prim ? 1 : 0;
                    assertThat(b.tMax).isEqualTo(a.tMax);
                    double tMax = random.nextDouble(0, 2 * ha.t);
                    assertThat(brute.occluded(new Ray().set(o, d, tMax), stack)).isEqualTo(bvh.occluded(new Ray().set(o, d, tMax), stack));
                }
            }
            assertThat(hits).isGreaterThan(1000);
            assertThat(ties).as("ties").isLessThan(hits / 100);
        }
    }
}
