package dev.strahl.medium;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * A grid medium's delta and ratio tracking against closed forms: a grid that ramps linearly
 * between its voxel centres along the ray (and is clamped beyond them), inside a box the ray enters
 * and leaves, and a segment that ends inside the box. Ratio tracking's mean is e^(−∫σt), delta
 * tracking crosses with that probability and scatters in [a, b] with the mass albedo·∫ σt T dt.
 */
class GridMediumTest {
    private static final Vector3d MIN = new Vector3d(-1, 0, 2), MAX = new Vector3d(1, 0.5, 3);
    private static final double SCALE = 1.7;
    /** Two voxels along x (0.4 and 2), two along y and z alike: σt varies along x only. */
    private static final DensityGrid RAMP = new DensityGrid(2, 2, 2, new float[] {0.4f, 2, 0.4f, 2, 0.4f, 2, 0.4f, 2});
    private static final Rgb ALBEDO = new Rgb(0.9, 0.6, 0.3);

    /** ∫ σt along the line y = 0.25, z = 2.5 from x = −3 to x (the box spans x ∈ [−1, 1], centres at ±0.5). */
    static double opticalDepth(double x) {
        double total = 0;
        for (int i = 0; i < 4000; i++) {
            double a = -1 + 2.0 * i / 4000, b = -1 + 2.0 * (i + 1) / 4000;
            if (a >= x) {
                break;
            }
            double m = 0.5 * (a + Math.min(b, x));
            total += (Math.min(b, x) - a) * sigma(m);
        }
        return total;
    }

    private static double sigma(double x) {
        double f = Math.max(0, Math.min(1, (x + 0.5) / 1.0));
        return SCALE * (0.4 + f * 1.6);
    }

    private static GridMedium medium(Rgb albedo) {
        return new GridMedium(RAMP, MIN, MAX, SCALE, albedo, 0.2);
    }

    @Test
    void extinctionIsTheScaledGridInsideTheBoxAndZeroOutside() {
        GridMedium m = medium(ALBEDO);
        assertThat(m.sigmaT(-0.5, 0.1, 2.2)).isCloseTo(SCALE * 0.4, within(1e-6));
        assertThat(m.sigmaT(0.5, 0.4, 2.9)).isCloseTo(SCALE * 2, within(1e-6));
        assertThat(m.sigmaT(0, 0.25, 2.5)).isCloseTo(SCALE * 1.2, within(1e-6));
        assertThat(m.sigmaT(-0.9, 0.25, 2.5)).as("clamped between the last centre and the face").isCloseTo(SCALE * 0.4, within(1e-6));
        assertThat(m.sigmaT(1.01, 0.25, 2.5)).isZero();
        assertThat(m.sigmaT(0, 0.25, 1.99)).isZero();
    }

    @Test
    void ratioTrackingIsUnbiased() {
        GridMedium m = medium(ALBEDO);
        Vector3d o = new Vector3d(-3, 0.25, 2.5), d = new Vector3d(1, 0, 0);
        for (double tMax : new double[] {10, 3.2, 2.6, 1.5}) {
            double expected = Math.exp(-opticalDepth(-3 + tMax));
            TrackingRandom random = new TrackingRandom().seed(0.3, tMax / 11);
            int n = 200_000;
            double sum = 0, sumSq = 0;
            for (int i = 0; i < n; i++) {
                MutableRgb tr = new MutableRgb(1, 1, 1);
                m.transmittance(o, d, tMax, random, tr);
                assertThat(tr.r).isEqualTo(tr.b).isBetween(0.0, 1.0);
                sum += tr.r;
                sumSq += tr.r * tr.r;
            }
            assertThat(sum / n).as("tMax %s", tMax).isCloseTo(expected, within(4 * HomogeneousMediumTest.standardError(sum, sumSq, n)));
        }
    }

    @Test
    void deltaTrackingCrossesAndScattersWithTheRightProbabilities() {
        GridMedium m = medium(ALBEDO);
        Vector3d o = new Vector3d(-3, 0.25, 2.5), d = new Vector3d(1, 0, 0);
        double a = 1.8, b = 2.9, tMax = 3.5;
        SplittableRandom u = new SplittableRandom(5);
        TrackingRandom random = new TrackingRandom();
        MutableRgb w = new MutableRgb();
        int n = 200_000, crossed = 0, inside = 0;
        for (int i = 0; i < n; i++) {
            double t = m.sampleScattering(o, d, tMax, 1, u.nextDouble(), u.nextDouble(), random, w, new MutableRgb());
            if (t == Double.POSITIVE_INFINITY) {
                crossed++;
                assertThat(w.r).isEqualTo(1);
            } else {
                assertThat(t).isBetween(2.0, 4.0);
                assertThat(w.g).isEqualTo(0.6);
                if (t >= a && t < b) {
                    inside++;
                }
            }
        }
        double pCross = Math.exp(-opticalDepth(-3 + tMax));
        double pInside = Math.exp(-opticalDepth(-3 + a)) - Math.exp(-opticalDepth(-3 + b));
        assertThat((double) crossed / n).isCloseTo(pCross, within(4 * Math.sqrt(pCross * (1 - pCross) / n)));
        assertThat((double) inside / n).isCloseTo(pInside, within(4 * Math.sqrt(pInside * (1 - pInside) / n)));
    }

    @Test
    void aRayThatMissesTheBoxCrossesUntouched() {
        GridMedium m = medium(ALBEDO);
        MutableRgb w = new MutableRgb();
        assertThat(m.sampleScattering(new Vector3d(-3, 0.25, 2.5), new Vector3d(0, 1, 0), 100, 0, 0.5, 0.5, new TrackingRandom(), w, new MutableRgb())).isInfinite();
        assertThat(w.r).isEqualTo(1);
        MutableRgb tr = new MutableRgb(1, 1, 1);
        m.transmittance(new Vector3d(-3, 0.25, 2.5), new Vector3d(-1, 0, 0), 100, new TrackingRandom(), tr);
        assertThat(tr.g).isEqualTo(1);
    }

    @Test
    void anAbsorbingGridIsCrossedWithAnUnbiasedTransmittance() {
        GridMedium m = medium(Rgb.BLACK);
        Vector3d o = new Vector3d(-3, 0.25, 2.5), d = new Vector3d(1, 0, 0);
        SplittableRandom u = new SplittableRandom(8);
        TrackingRandom random = new TrackingRandom();
        MutableRgb w = new MutableRgb();
        int n = 100_000;
        double sum = 0, sumSq = 0;
        for (int i = 0; i < n; i++) {
            assertThat(m.sampleScattering(o, d, 10, 2, u.nextDouble(), u.nextDouble(), random, w, new MutableRgb())).isInfinite();
            sum += w.r;
            sumSq += w.r * w.r;
        }
        assertThat(sum / n).isCloseTo(Math.exp(-opticalDepth(7)), within(4 * HomogeneousMediumTest.standardError(sum, sumSq, n)));
    }

    /** A 20×17×13 grid (3×3×2 bricks) of hashed values, with a block of empty voxels: the bricks' majorants matter. */
    static DensityGrid bricky() {
        float[] v = new float[20 * 17 * 13];
        for (int k = 0; k < 13; k++) {
            for (int j = 0; j < 17; j++) {
                for (int i = 0; i < 20; i++) {
                    int h = (i * 73856093) ^ (j * 19349663) ^ (k * 83492791);
                    v[(k * 17 + j) * 20 + i] = i < 8 && j < 8 ? 0 : (h & 1023) / 1023f * (i >= 16 ? 4 : 1);
                }
            }
        }
        return new DensityGrid(20, 17, 13, v);
    }

    @Test
    void theBricksMajorantsBoundEveryLookupInThem() {
        DensityGrid g = bricky();
        MajorantGrid bricks = new MajorantGrid(g);
        assertThat(new int[] {bricks.nx, bricks.ny, bricks.nz}).containsExactly(3, 3, 2);
        assertThat(bricks.max(0, 0, 0)).as("empty voxels and their ring only").isLessThan(0.999);
        SplittableRandom r = new SplittableRandom(4);
        for (int n = 0; n < 200_000; n++) {
            double u = r.nextDouble(), v = r.nextDouble(), w = r.nextDouble();
            int bi = Math.min((int) (u * 20 / 8), 2), bj = Math.min((int) (v * 17 / 8), 2), bk = Math.min((int) (w * 13 / 8), 1);
            assertThat(g.eval(u, v, w)).isLessThanOrEqualTo(bricks.max(bi, bj, bk) + 1e-6);
        }
    }

    @Test
    void trackingBrickByBrickIsUnbiasedAlongRaysInEveryDirection() {
        Vector3d min = new Vector3d(-1, -0.5, 0), max = new Vector3d(1, 1.2, 0.9);
        GridMedium m = new GridMedium(bricky(), min, max, 2.2, ALBEDO, 0);
        SplittableRandom r = new SplittableRandom(6);
        Vector3d[][] rays = {
            {new Vector3d(-3, 0.3, 0.45), new Vector3d(1, 0, 0)},                       // along x, through every brick column
            {new Vector3d(0.5, 3, 0.2), new Vector3d(0, -1, 0)},
            {new Vector3d(0.2, 0.1, 0.3), new Vector3d(-0.3, 0.5, 0.8).normalize()},    // starts inside
            {new Vector3d(2, 2, 2), new Vector3d(-1, -0.9, -0.8).normalize()},          // corner to corner, backwards on every axis
            {new Vector3d(-0.7, -2, 0.05), new Vector3d(0.1, 1, 0.02).normalize()}};
        for (Vector3d[] ray : rays) {
            Vector3d o = ray[0], d = ray[1];
            double tMax = 6;
            double depth = 0, steps = 200_000;
            for (int i = 0; i < steps; i++) {
                double t = (i + 0.5) * tMax / steps;
                depth += m.sigmaT(o.x + t * d.x, o.y + t * d.y, o.z + t * d.z) * tMax / steps;
            }
            double expected = Math.exp(-depth);
            TrackingRandom random = new TrackingRandom().seed(r.nextDouble(), r.nextDouble());
            int n = 60_000, crossed = 0;
            double sum = 0, sumSq = 0;
            MutableRgb w = new MutableRgb();
            for (int i = 0; i < n; i++) {
                MutableRgb tr = new MutableRgb(1, 1, 1);
                m.transmittance(o, d, tMax, random, tr);
                sum += tr.r;
                sumSq += tr.r * tr.r;
                if (m.sampleScattering(o, d, tMax, 0, r.nextDouble(), r.nextDouble(), random, w, new MutableRgb()) == Double.POSITIVE_INFINITY) {
                    crossed++;
                }
            }
            assertThat(sum / n).as("ratio tracking along %s", d).isCloseTo(expected, within(4 * HomogeneousMediumTest.standardError(sum, sumSq, n) + 1e-4));
            assertThat((double) crossed / n).as("delta tracking along %s", d)
                    .isCloseTo(expected, within(4 * Math.sqrt(expected * (1 - expected) / n) + 1e-4));
        }
    }

    @Test
    void badBoundsAndScalesAreRefused() {
        assertThatThrownBy(() -> new GridMedium(RAMP, MAX, MIN, 1, ALBEDO, 0)).hasMessageContaining("min < max");
        assertThatThrownBy(() -> new GridMedium(RAMP, MIN, new Vector3d(1, 0, 3), 1, ALBEDO, 0)).hasMessageContaining("min < max");
        assertThatThrownBy(() -> new GridMedium(RAMP, MIN, new Vector3d(1, Double.NaN, 3), 1, ALBEDO, 0)).hasMessageContaining("bounds");
        assertThatThrownBy(() -> new GridMedium(RAMP, MIN, MAX, -1, ALBEDO, 0)).hasMessageContaining("scale");
        assertThatThrownBy(() -> new GridMedium(RAMP, MIN, MAX, 1, ALBEDO, -1)).hasMessageContaining("g");
    }
}
