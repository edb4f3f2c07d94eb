package dev.strahl.geometry;

import dev.strahl.testing.MeshGeometry;
import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.scene.TriangleMesh;
import dev.strahl.testing.Meshes;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The watertight triangle test (Woop, Benthin &amp; Wald 2013) leaves no crack on shared edges and
 * vertices, where a test with independent per-triangle round-off lets rays through: a ray from
 * inside a closed convex mesh aimed at any point of its edges or vertices hits it. (The
 * Möller–Trumbore test strahl used before let about 9 % of such rays through on a UV sphere; see
 * docs/performance.md.) From inside, no edge is a silhouette, so every such ray must hit. Also:
 * reordering a geometry (as the BVH does) keeps every primitive.
 */
class WatertightTest {

    private static Geometry closed(TriangleMesh mesh) {
        return new MeshGeometry().addMesh(mesh, new int[mesh.triangleCount()], true).build();
    }

    @Test
    void raysAimedAtSharedEdgesAndVerticesOfAClosedMeshFromInsideAlwaysHit() {
        TriangleMesh mesh = Meshes.icosphere(3, 1.7, false);
        Geometry g = closed(mesh);
        float[] p = mesh.positions();
        int[] idx = mesh.indices();
        SplittableRandom random = new SplittableRandom(11);
        int rays = 0;
        for (int i = 0; i < 60_000; i++) {
            int t = random.nextInt(mesh.triangleCount()), k = random.nextInt(3);
            int a = idx[3 * t + k], b = idx[3 * t + (k + 1) % 3];
            // A point on the edge a–b (its end points included), approached from a random inside point.
            double s = random.nextInt(8) == 0 ? random.nextInt(2) : random.nextDouble();
            Vector3d target = new Vector3d(p[3 * a], p[3 * a + 1], p[3 * a + 2]).lerp(new Vector3d(p[3 * b], p[3 * b + 1], p[3 * b + 2]), s);
            Vector3d origin = new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize(random.nextDouble());
            Vector3d d = new Vector3d(target).sub(origin).normalize();
            Ray ray = new Ray().set(origin, d, Double.POSITIVE_INFINITY);
            Hit hit = new Hit().reset();
            boolean found = g.intersect(0, g.triangleCount(), ray, hit, false);
            assertThat(found).as("ray %d at edge %d-%d, s = %s: %s", i, a, b, s, ray).isTrue();
            assertThat(g.occludes(0, g.triangleCount(), new Ray().set(origin, d, Double.POSITIVE_INFINITY))).isTrue();
            rays++;
        }
        assertThat(rays).isEqualTo(60_000);
    }

    @Test
    void raysFromInsideAClosedMeshNeverEscape() {
        Geometry g = closed(Meshes.icosphere(2, 1.3, false));
        SplittableRandom random = new SplittableRandom(12);
        for (int i = 0; i < 50_000; i++) {
            Vector3d origin = new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize(random.nextDouble());
            Vector3d d = new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
            Ray ray = new Ray().set(origin, d, Double.POSITIVE_INFINITY);
            assertThat(g.intersect(0, g.triangleCount(), ray, new Hit().reset(), false)).as("ray %d %s", i, ray).isTrue();
        }
    }

    @Test
    void permutingKeepsEveryTriangleWithItsVerticesAndData() {
        TriangleMesh mesh = Meshes.icosphere(1, 1, false);
        float[] extra = java.util.Arrays.copyOf(mesh.positions(), mesh.positions().length + 3);   // one vertex no triangle uses
        int n = mesh.triangleCount();
        int[] materials = new int[n];
        byte[] flags = new byte[n];
        for (int t = 0; t < n; t++) {
            materials[t] = t % 5;
            flags[t] = (byte) (t % 2);
        }
        Geometry g = new MeshGeometry().addMesh(new TriangleMesh(extra, mesh.indices(), null), materials, flags)
                .addSphere(new Vector3d(3, 0, 0), 0.5, 7).build();
        int[] order = new int[g.primitiveCount()];
        for (int i = 0; i < n; i++) {
            order[i] = (7 * i + 3) % n;             // 7 is prime to 80 = n
        }
        order[n] = n;
        Geometry q = g.permute(order);
        assertThat(q.triangleCount()).isEqualTo(n);
        SurfacePoint a = new SurfacePoint(), b = new SurfacePoint();
        for (int i = 0; i < g.primitiveCount(); i++) {
            int old = order[i];
            assertThat(q.material(i)).isEqualTo(g.material(old));
            assertThat(q.isClosed(i)).isEqualTo(g.isClosed(old));
            assertThat(q.area(i)).isEqualTo(g.area(old));
            q.samplePoint(i, 0.3, 0.6, a);
            g.samplePoint(old, 0.3, 0.6, b);
            assertThat(a.p).isEqualTo(b.p);
            assertThat(a.ng).isEqualTo(b.ng);
        }
        assertThat(q.byteSize()).as("the unused vertex is dropped").isEqualTo(g.byteSize() - 12);
        assertThat(org.assertj.core.api.Assertions.catchThrowable(() -> g.permute(new int[] {0})))
                .isInstanceOf(IllegalArgumentException.class);
        int[] sphereFirst = order.clone();
        sphereFirst[0] = n;
        sphereFirst[n] = order[0];
        assertThat(org.assertj.core.api.Assertions.catchThrowable(() -> g.permute(sphereFirst)))
                .as("triangles must stay before spheres").isInstanceOf(IllegalArgumentException.class);
    }
}
