package dev.strahl.bench;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.scene.TriangleMesh;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The benchmark's generated meshes: their sizes, bit-for-bit reproducible, closed and wound outwards. */
class BenchMeshesTest {

    @Test
    void theDefaultsHaveTheScannedModelsSizesOneOfThemOverAMillion() {
        List<BenchMeshes.Generated> meshes = BenchMeshes.defaults();
        assertThat(meshes).extracting(BenchMeshes.Generated::name).doesNotHaveDuplicates().hasSize(3);
        assertThat(BenchMeshes.displacedSphere(76).triangleCount()).isEqualTo(69_312);
        assertThat(BenchMeshes.torusKnot(1000, 50).triangleCount()).isEqualTo(100_000);
        assertThat(BenchMeshes.displacedSphere(303).triangleCount()).isEqualTo(1_101_708);
    }

    @Test
    void theSameMeshComesOutBitForBit() {
        assertThat(BenchMeshes.displacedSphere(20)).isEqualTo(BenchMeshes.displacedSphere(20));
        assertThat(BenchMeshes.torusKnot(120, 12)).isEqualTo(BenchMeshes.torusKnot(120, 12));
        assertThat(BenchMeshes.displacedSphere(20).positions()).isNotEqualTo(BenchMeshes.displacedSphere(21).positions());
    }

    @Test
    void theMeshesAreClosedAndWoundOutwards() {
        for (TriangleMesh mesh : List.of(BenchMeshes.displacedSphere(24), BenchMeshes.torusKnot(200, 16))) {
            assertThat(undirectedEdgeUses(mesh).values()).as("every edge between exactly two triangles").containsOnly(2);
            assertThat(directedEdges(mesh)).as("each edge once in each direction: consistent winding").isEqualTo(3 * mesh.triangleCount());
            assertThat(signedVolume(mesh)).as("positive volume: wound outwards").isPositive();
        }
    }

    @Test
    void theSphereIsBumpyNotRound() {
        float[] p = BenchMeshes.displacedSphere(60).positions();
        double min = Double.MAX_VALUE, max = 0;
        for (int v = 0; v < p.length; v += 3) {
            double r = Math.sqrt(p[v] * p[v] + p[v + 1] * p[v + 1] + p[v + 2] * p[v + 2]);
            min = Math.min(min, r);
            max = Math.max(max, r);
        }
        assertThat(max - min).as("radial relief").isGreaterThan(0.2);
        assertThat(min).isGreaterThan(0.5);
    }

    private static Map<Long, Integer> undirectedEdgeUses(TriangleMesh mesh) {
        int[] idx = mesh.indices();
        Map<Long, Integer> uses = new HashMap<>();
        for (int t = 0; t < idx.length; t += 3) {
            for (int k = 0; k < 3; k++) {
                int a = idx[t + k], b = idx[t + (k + 1) % 3];
                uses.merge(((long) Math.min(a, b) << 32) | Math.max(a, b), 1, Integer::sum);
            }
        }
        return uses;
    }

    private static int directedEdges(TriangleMesh mesh) {
        int[] idx = mesh.indices();
        java.util.Set<Long> edges = new java.util.HashSet<>();
        for (int t = 0; t < idx.length; t += 3) {
            for (int k = 0; k < 3; k++) {
                edges.add(((long) idx[t + k] << 32) | idx[t + (k + 1) % 3]);
            }
        }
        return edges.size();
    }

    private static double signedVolume(TriangleMesh mesh) {
        float[] p = mesh.positions();
        int[] idx = mesh.indices();
        double volume = 0;
        for (int t = 0; t < idx.length; t += 3) {
            int a = 3 * idx[t], b = 3 * idx[t + 1], c = 3 * idx[t + 2];
            volume += p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1])
                    - p[a + 1] * (p[b] * p[c + 2] - p[b + 2] * p[c])
                    + p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c]);
        }
        return volume / 6;
    }
}
