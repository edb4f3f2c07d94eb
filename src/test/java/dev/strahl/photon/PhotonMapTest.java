package dev.strahl.photon;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.integrator.Parallel;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.SplittableRandom;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;

/** The photon map's radius and k-nearest queries against brute force. */
class PhotonMapTest {

    /** Points with their index in the red channel, so a query result names the input point. */
    private static PhotonList points(double[][] xyz) {
        PhotonList list = new PhotonList(2);
        for (int i = 0; i < xyz.length; i++) {
            list.add(xyz[i][0], xyz[i][1], xyz[i][2], 0, 1, 0, i, 0, 0, 2);
        }
        return list;
    }

    private static double[][] randomPoints(SplittableRandom rnd, int n, double extent) {
        double[][] p = new double[n][];
        for (int i = 0; i < n; i++) {
            p[i] = new double[] {rnd.nextDouble(-extent, extent), rnd.nextDouble(-extent, extent), rnd.nextDouble(-extent, extent)};
        }
        return p;
    }

    /** Points on a grid of spacing h: every point on a cell boundary when the cell size is h. */
    private static double[][] latticePoints(int n, double h) {
        List<double[]> p = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                for (int k = 0; k < n; k++) {
                    p.add(new double[] {i * h, j * h, k * h});
                }
            }
        }
        return p.toArray(new double[0][]);
    }

    /** The input indices of the map's photons within radius of q, by the map. */
    private static TreeSet<Integer> query(PhotonMap map, double[] q, double radius) {
        TreeSet<Integer> found = new TreeSet<>();
        float[] d = map.data();
        map.forEachWithin(q[0], q[1], q[2], radius, new PhotonMap.Search(), (photon, dist2) -> {
            boolean fresh = found.add((int) d[photon * PhotonList.STRIDE + PhotonList.R]);
            assertThat(fresh).as("photon reported twice").isTrue();
            double dx = d[photon * PhotonList.STRIDE] - q[0], dy = d[photon * PhotonList.STRIDE + 1] - q[1], dz = d[photon * PhotonList.STRIDE + 2] - q[2];
            assertThat(dist2).isEqualTo(dx * dx + dy * dy + dz * dz);
        });
        return found;
    }

    /** The same by brute force, with the distance computed from the stored (float) positions as the map does. */
    private static TreeSet<Integer> bruteForce(double[][] pts, double[] q, double radius) {
        TreeSet<Integer> found = new TreeSet<>();
        for (int i = 0; i < pts.length; i++) {
            if (dist2(pts[i], q) <= radius * radius) {
                found.add(i);
            }
        }
        return found;
    }

    private static double dist2(double[] p, double[] q) {
        double dx = (float) p[0] - q[0], dy = (float) p[1] - q[1], dz = (float) p[2] - q[2];
        return dx * dx + dy * dy + dz * dz;
    }

    @Test
    void radiusQueriesMatchBruteForceOnRandomPoints() {
        SplittableRandom rnd = new SplittableRandom(1);
        double[][] pts = randomPoints(rnd, 3000, 1);
        for (double cell : new double[] {0.02, 0.1, 0.5}) {
            PhotonMap map = PhotonMap.build(points(pts), cell, Parallel.sequential(null));
            assertThat(map.size()).isEqualTo(pts.length);
            for (int t = 0; t < 300; t++) {
                double[] q = {rnd.nextDouble(-1.2, 1.2), rnd.nextDouble(-1.2, 1.2), rnd.nextDouble(-1.2, 1.2)};
                double radius = cell * rnd.nextDouble(0, 1.5);
                assertThat(query(map, q, radius)).as("cell %s, query %s r %s", cell, Arrays.toString(q), radius)
                        .isEqualTo(bruteForce(pts, q, radius));
            }
        }
    }

    @Test
    void pointsOnCellBoundariesAndAtExactlyTheRadiusAreFound() {
        double h = 0.25;
        double[][] pts = latticePoints(9, h);
        PhotonMap map = PhotonMap.build(points(pts), h, Parallel.sequential(null));
        for (double[] q : new double[][] {{1, 1, 1}, {0, 0, 0}, {2, 2, 2}, {0.5, 1.25, 0.75}, {1.125, 1, 1}}) {
            for (double radius : new double[] {0, h, 2 * h, h * Math.sqrt(2), 0.3}) {
                TreeSet<Integer> expected = bruteForce(pts, q, radius);
                assertThat(query(map, q, radius)).as("query %s r %s", Arrays.toString(q), radius).isEqualTo(expected);
            }
        }
        // Radius h around a lattice point: itself and its six neighbours at exactly h.
        assertThat(query(map, new double[] {1, 1, 1}, h)).hasSize(7);
    }

    @Test
    void emptyMapFindsNothing() {
        PhotonMap map = PhotonMap.build(new PhotonList(), 0.1, Parallel.sequential(null));
        assertThat(map.size()).isZero();
        assertThat(query(map, new double[] {0, 0, 0}, 100)).isEmpty();
        assertThat(map.nearest(0, 0, 0, 5, Double.POSITIVE_INFINITY, new PhotonMap.Search(), new int[5], new double[5])).isZero();
        assertThat(PhotonMap.empty().size()).isZero();
    }

    @Test
    void radiusLargerThanTheSceneFindsEveryPointOnce() {
        SplittableRandom rnd = new SplittableRandom(2);
        double[][] pts = randomPoints(rnd, 500, 1);
        PhotonMap map = PhotonMap.build(points(pts), 0.05, Parallel.sequential(null));
        assertThat(query(map, new double[] {0.3, -0.2, 0.1}, 10)).hasSize(500);
        assertThat(query(map, new double[] {50, 50, 50}, 1000)).hasSize(500);
        assertThat(query(map, new double[] {50, 50, 50}, 10)).isEmpty();        // query ball outside the points' box
    }

    @Test
    void coincidentPointsAreAllReported() {
        double[][] pts = new double[40][];
        for (int i = 0; i < pts.length; i++) {
            pts[i] = i < 30 ? new double[] {0.5, 0.5, 0.5} : new double[] {0.5 + 1e-3 * i, 0.5, 0.5};
        }
        PhotonMap map = PhotonMap.build(points(pts), 0.01, Parallel.sequential(null));
        assertThat(query(map, new double[] {0.5, 0.5, 0.5}, 0)).hasSize(30);
        assertThat(query(map, new double[] {0.5, 0.5, 0.5}, 1)).hasSize(40);
    }

    @Test
    void pointsOnAPlaneAsPhotonsLieMatchBruteForce() {
        SplittableRandom rnd = new SplittableRandom(3);
        double[][] pts = new double[4000][];
        for (int i = 0; i < pts.length; i++) {
            pts[i] = new double[] {rnd.nextDouble(-1, 1), 0, rnd.nextDouble(-1, 1)};       // a floor: all in one layer of cells
        }
        PhotonMap map = PhotonMap.build(points(pts), 0.03, Parallel.sequential(null));
        for (int t = 0; t < 200; t++) {
            double[] q = {rnd.nextDouble(-1, 1), rnd.nextDouble(-0.02, 0.02), rnd.nextDouble(-1, 1)};
            assertThat(query(map, q, 0.03)).isEqualTo(bruteForce(pts, q, 0.03));
        }
    }

    @Test
    void nearestNeighboursMatchBruteForce() {
        SplittableRandom rnd = new SplittableRandom(4);
        double[][] pts = randomPoints(rnd, 2000, 1);
        PhotonMap map = PhotonMap.build(points(pts), 0.04, Parallel.sequential(null));
        PhotonMap.Search search = new PhotonMap.Search();
        float[] d = map.data();
        for (int t = 0; t < 200; t++) {
            double[] q = {rnd.nextDouble(-1.5, 1.5), rnd.nextDouble(-1.5, 1.5), rnd.nextDouble(-1.5, 1.5)};
            int k = 1 + rnd.nextInt(40);
            double maxRadius = t % 3 == 0 ? 0.2 : Double.POSITIVE_INFINITY;
            int[] photon = new int[k];
            double[] dist2 = new double[k];
            int n = map.nearest(q[0], q[1], q[2], k, maxRadius, search, photon, dist2);

            Integer[] order = new Integer[pts.length];
            Arrays.setAll(order, i -> i);
            Arrays.sort(order, Comparator.comparingDouble(i -> dist2(pts[i], q)));
            List<Integer> expected = new ArrayList<>();
            for (int i = 0; i < k && dist2(pts[order[i]], q) <= maxRadius * maxRadius; i++) {
                expected.add(order[i]);
            }
            assertThat(n).as("query %d", t).isEqualTo(expected.size());
            for (int i = 0; i < n; i++) {
                assertThat(dist2[i]).as("distance %d of query %d", i, t).isEqualTo(dist2(pts[expected.get(i)], q));
                if (i > 0) {
                    assertThat(dist2[i]).isGreaterThanOrEqualTo(dist2[i - 1]);
                }
                int input = (int) d[photon[i] * PhotonList.STRIDE + PhotonList.R];
                assertThat(dist2(pts[input], q)).isEqualTo(dist2[i]);
            }
        }
    }

    @Test
    void nearestWithMoreRequestedThanStoredReturnsAll() {
        double[][] pts = randomPoints(new SplittableRandom(5), 7, 1);
        PhotonMap map = PhotonMap.build(points(pts), 0.01, Parallel.sequential(null));
        int[] photon = new int[20];
        double[] dist2 = new double[20];
        assertThat(map.nearest(3, 3, 3, 20, Double.POSITIVE_INFINITY, new PhotonMap.Search(), photon, dist2)).isEqualTo(7);
    }

    @Test
    void buildIsTheSameWhateverOrderTheChunksRunIn() {
        double[][] pts = randomPoints(new SplittableRandom(6), 70_000, 2);     // several build chunks
        PhotonMap forward = PhotonMap.build(points(pts), 0.05, Parallel.sequential(null));
        Parallel backwards = (count, task) -> {
            for (int i = count - 1; i >= 0; i--) {
                task.run(i, null);
            }
        };
        PhotonMap reversed = PhotonMap.build(points(pts), 0.05, backwards);
        assertThat(reversed.data()).isEqualTo(forward.data());
    }

    @Test
    void hugeExtentsWithTinyCellsStillWork() {
        double[][] pts = {{-1e6, 0, 0}, {1e6, 0, 0}, {0, 0, 0}, {0.001, 0, 0}};
        PhotonMap map = PhotonMap.build(points(pts), 1e-6, Parallel.sequential(null));
        assertThat(map.cellSize()).isGreaterThan(1e-6);                        // enlarged to keep the grid addressable
        assertThat(query(map, new double[] {0, 0, 0}, 0.01)).containsExactly(2, 3);
        assertThat(query(map, new double[] {1e6, 0, 0}, 1)).containsExactly(1);
    }

    @Test
    void refusesABadCellSize() {
        assertThatThrownBy(() -> PhotonMap.build(new PhotonList(), 0, Parallel.sequential(null))).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> PhotonMap.build(new PhotonList(), Double.NaN, Parallel.sequential(null))).isInstanceOf(IllegalArgumentException.class);
    }
}
