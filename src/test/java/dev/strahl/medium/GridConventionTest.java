package dev.strahl.medium;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * strahl's grid against Mitsuba 3.9.1's {@code gridvolume} itself: the 12×10×8 golden smoke grid
 * (src/test/resources/golden/media/smoke.vol) mapped onto its bounds by {@code to_world}, looked up
 * by Mitsuba at 244 points — voxel centres, random points inside, points in the half voxel at the
 * faces and beyond them (docs/anchors/media_refs.py {@code grid}, grid-lookups.txt). The same
 * points in strahl give the same values: voxel centres at (i + ½)/X, trilinear, clamped, x fastest.
 * A grid shifted by half a voxel, or read z fastest, does not.
 */
class GridConventionTest {
    static final Vector3d MIN = new Vector3d(-0.6, 0.02, -0.4), MAX = new Vector3d(0.6, 1.02, 0.4);
    static final Path DIR = Path.of("src/test/resources/golden/media");

    private static List<double[]> lookups() throws IOException {
        return Files.readAllLines(DIR.resolve("grid-lookups.txt")).stream().filter(l -> !l.startsWith("#"))
                .map(l -> java.util.Arrays.stream(l.trim().split(" ")).mapToDouble(Double::parseDouble).toArray()).toList();
    }

    /** The largest difference between strahl's lookups (the grid's own, clamped, coordinates) and Mitsuba's. */
    private static double worst(DensityGrid grid, Vector3d min, Vector3d max) throws IOException {
        double worst = 0;
        for (double[] l : lookups()) {
            double u = (l[0] - min.x) / (max.x - min.x), v = (l[1] - min.y) / (max.y - min.y), w = (l[2] - min.z) / (max.z - min.z);
            worst = Math.max(worst, Math.abs(grid.eval(u, v, w) - l[3]));
        }
        return worst;
    }

    @Test
    void lookupsAreMitsubasInsideAtAndBeyondTheFaces() throws IOException {
        DensityGrid grid = VolFile.read(DIR.resolve("smoke.vol")).grid();
        assertThat(lookups()).hasSize(244);
        assertThat(worst(grid, MIN, MAX)).isLessThan(1e-6);
        // the medium: scale x the same values inside the box, nothing outside (Mitsuba's heterogeneous medium clips to it)
        GridMedium medium = new GridMedium(grid, MIN, MAX, 2.5, Rgb.gray(0.9), 0);
        for (double[] l : lookups()) {
            boolean inside = l[0] >= MIN.x && l[0] <= MAX.x && l[1] >= MIN.y && l[1] <= MAX.y && l[2] >= MIN.z && l[2] <= MAX.z;
            assertThat(medium.sigmaT(l[0], l[1], l[2])).isCloseTo(inside ? 2.5 * l[3] : 0, within(3e-6));
        }
    }

    @Test
    void aGridShiftedByHalfAVoxelOrReadZFastestDiffers() throws IOException {
        DensityGrid grid = VolFile.read(DIR.resolve("smoke.vol")).grid();
        Vector3d half = new Vector3d(0.5 * 1.2 / 12, 0, 0);
        assertThat(worst(grid, new Vector3d(MIN).add(half), new Vector3d(MAX).add(half))).isGreaterThan(0.1);
        float[] transposed = new float[12 * 10 * 8];
        for (int k = 0; k < 8; k++) {
            for (int j = 0; j < 10; j++) {
                for (int i = 0; i < 12; i++) {
                    transposed[(i * 10 + j) * 8 + k] = (float) grid.voxel(i, j, k);
                }
            }
        }
        assertThat(worst(new DensityGrid(8, 10, 12, transposed), MIN, MAX)).isGreaterThan(0.1);
    }
}
