package dev.strahl.accel;

import dev.strahl.testing.MeshGeometry;
import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Sphere;
import dev.strahl.scene.TriangleMesh;
import java.security.MessageDigest;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** The builder's parallelism must not show in its result: the same tree and order for any thread count. */
class BvhBuilderTest {

    @Test
    void treeDoesNotDependOnTheThreadCount() throws Exception {
        // Large enough that the top splits bin in parallel chunks and subtrees are forked; a
        // cluster of coincident triangles (median splits) and spheres (mixed leaves) as well.
        Geometry g = geometry(200_000, 70_000, 500);
        Bvh one = new BvhBuilder(g, 1).build();
        for (int threads : new int[] {2, 3}) {
            Bvh many = new BvhBuilder(g, threads).build();
            assertThat(many.nodeCount()).isEqualTo(one.nodeCount());
            assertThat(bits(many.layout().nodes())).as("nodes on %d threads", threads).isEqualTo(bits(one.layout().nodes()));
            assertThat(digest(many.geometry())).as("primitive order on %d threads", threads).isEqualTo(digest(one.geometry()));
        }
    }

    private static Geometry geometry(int random, int coincident, int spheres) {
        SplittableRandom r = new SplittableRandom(7);
        int n = random + coincident;
        float[] xyz = new float[9 * n];
        for (int t = 0; t < n; t++) {
            double cx = r.nextDouble(), cy = r.nextDouble(), cz = r.nextDouble();
            SplittableRandom shape = t < random ? r : new SplittableRandom(1);
            for (int k = 0; k < 9; k++) {
                double c = t < random ? (k % 3 == 0 ? cx : k % 3 == 1 ? cy : cz) : 0.5;
                xyz[9 * t + k] = (float) (c + 0.01 * shape.nextDouble(-1, 1));
            }
        }
        int[] idx = new int[3 * n];
        for (int i = 0; i < idx.length; i++) {
            idx[i] = i;
        }
        MeshGeometry b = new MeshGeometry().addMesh(new TriangleMesh(xyz, idx, null), new int[n], false);
        for (int i = 0; i < spheres; i++) {
            b.addSphere(new Vector3d(r.nextDouble(), r.nextDouble(), r.nextDouble()), 0.01, 0);
        }
        return b.build();
    }

    private static int[] bits(float[] f) {
        int[] b = new int[f.length];
        for (int i = 0; i < f.length; i++) {
            b[i] = Float.floatToRawIntBits(f[i]);
        }
        return b;
    }

    private static byte[] digest(Geometry g) throws Exception {
        MessageDigest md = MessageDigest.getInstance("SHA-256");
        g.digest(md);
        return md.digest();
    }
}
