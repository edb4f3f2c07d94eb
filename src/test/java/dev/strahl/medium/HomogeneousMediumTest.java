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
 * A homogeneous medium against Beer–Lambert: the transmittance of a slab is e^(−σt·d) per
 * channel, and free-flight sampling of a uniformly chosen hero channel, its weight divided by the
 * mean of the channels' density ratios (MIS over the channels, as the path tracer does), is
 * unbiased for both things a path needs from it — the light that crosses the slab
 * (E[weight; crossed] = e^(−σt·d)) and the light scattered in any stretch [a, b] of it
 * (E[weight; scattered in [a, b]] = ∫ σs e^(−σt·t) dt) — with weights bounded by 3 × albedo, also
 * for a strongly chromatic σt.
 */
class HomogeneousMediumTest {
    private static final Vector3d O = new Vector3d(0.2, -1, 3);
    private static final Vector3d D = new Vector3d(1, 2, -2).normalize();
    private static final Rgb SIGMA = new Rgb(2.4, 0.9, 0.25);
    private static final Rgb ALBEDO = new Rgb(0.9, 0.5, 0.8);

    @Test
    void aSlabTransmitsBeerLambertPerChannel() {
        HomogeneousMedium m = new HomogeneousMedium(SIGMA, ALBEDO, 0.3);
        for (double d : new double[] {0, 0.1, 1.3, 7}) {
            MutableRgb tr = new MutableRgb(1, 1, 1);
            m.transmittance(O, D, d, new TrackingRandom(), tr);
            assertThat(tr.r).isCloseTo(Math.exp(-2.4 * d), within(1e-15));
            assertThat(tr.g).isCloseTo(Math.exp(-0.9 * d), within(1e-15));
            assertThat(tr.b).isCloseTo(Math.exp(-0.25 * d), within(1e-15));
        }
        MutableRgb forever = new MutableRgb(1, 1, 1);
        new HomogeneousMedium(new Rgb(1, 0, 2), ALBEDO, 0).transmittance(O, D, Double.POSITIVE_INFINITY, new TrackingRandom(), forever);
        assertThat(forever.r).isZero();
        assertThat(forever.g).as("a channel without extinction lets everything through").isEqualTo(1);
        assertThat(forever.b).isZero();
    }

    @Test
    void freeFlightSamplingIsUnbiasedForCrossingAndScattering() {
        HomogeneousMedium m = new HomogeneousMedium(SIGMA, ALBEDO, 0);
        double slab = 1.1, a = 0.3, b = 0.7;
        int n = 400_000;
        SplittableRandom random = new SplittableRandom(11);
        double[] crossed = new double[3], crossedSq = new double[3], scattered = new double[3], scatteredSq = new double[3];
        MutableRgb w = new MutableRgb(), ratio = new MutableRgb();
        double maxWeight = 0;
        for (int i = 0; i < n; i++) {
            double t = m.sampleScattering(O, D, slab, random.nextInt(3), random.nextDouble(), random.nextDouble(), new TrackingRandom(), w, ratio);
            w.mul(3 / (ratio.r + ratio.g + ratio.b));
            double[] c = {w.r, w.g, w.b};
            maxWeight = Math.max(maxWeight, w.max());
            for (int k = 0; k < 3; k++) {
                if (t == Double.POSITIVE_INFINITY) {
                    crossed[k] += c[k];
                    crossedSq[k] += c[k] * c[k];
                } else if (t >= a && t < b) {
                    scattered[k] += c[k];
                    scatteredSq[k] += c[k] * c[k];
                }
                assertThat(t).isGreaterThan(0);
            }
        }
        double[] sigma = {2.4, 0.9, 0.25}, albedo = {0.9, 0.5, 0.8};
        for (int k = 0; k < 3; k++) {
            double expectCross = Math.exp(-sigma[k] * slab);
            double expectScatter = albedo[k] * (Math.exp(-sigma[k] * a) - Math.exp(-sigma[k] * b));
            assertThat(crossed[k] / n).as("crossing, channel %d", k).isCloseTo(expectCross, within(4 * standardError(crossed[k], crossedSq[k], n)));
            assertThat(scattered[k] / n).as("scattering, channel %d", k)
                    .isCloseTo(expectScatter, within(4 * standardError(scattered[k], scatteredSq[k], n)));
        }
        assertThat(maxWeight).as("MIS over the channels bounds the weights").isLessThanOrEqualTo(3 * 0.9 + 1e-12);
        // without the MIS, one hero channel's weights for the others grow without bound: e^((2.4 - 0.25) t) for blue under red
        m.sampleScattering(O, D, 1e9, 0, 0.5, 0.999999, new TrackingRandom(), w, ratio);
        assertThat(w.b).isGreaterThan(100);
        w.mul(3 / (ratio.r + ratio.g + ratio.b));
        assertThat(w.b).isLessThanOrEqualTo(3 * 0.8 + 1e-12);
    }

    @Test
    void aGreyMediumScattersWithWeightAlbedoAndCrossesWithWeightOne() {
        HomogeneousMedium m = new HomogeneousMedium(Rgb.gray(1.5), ALBEDO, 0.5);
        MutableRgb w = new MutableRgb(), ratio = new MutableRgb();
        SplittableRandom random = new SplittableRandom(2);
        int crossings = 0, n = 100_000;
        for (int i = 0; i < n; i++) {
            double t = m.sampleScattering(O, D, 0.8, random.nextInt(3), random.nextDouble(), random.nextDouble(), new TrackingRandom(), w, ratio);
            assertThat(ratio.r).isEqualTo(1);
            assertThat(ratio.b).isEqualTo(1);
            if (t == Double.POSITIVE_INFINITY) {
                crossings++;
                assertThat(w.r).isCloseTo(1, within(1e-12));
                assertThat(w.b).isCloseTo(1, within(1e-12));
            } else {
                assertThat(w.r).isCloseTo(0.9, within(1e-12));
                assertThat(w.g).isCloseTo(0.5, within(1e-12));
            }
        }
        double p = Math.exp(-1.5 * 0.8);
        assertThat((double) crossings / n).isCloseTo(p, within(4 * Math.sqrt(p * (1 - p) / n)));
    }

    @Test
    void anAbsorbingMediumIsCrossedWithItsTransmittanceAndNoNoise() {
        HomogeneousMedium m = new HomogeneousMedium(SIGMA, Rgb.BLACK, 0);
        MutableRgb w = new MutableRgb(), ratio = new MutableRgb();
        assertThat(m.sampleScattering(O, D, 0.6, 2, 0.1, 0.999, new TrackingRandom(), w, ratio)).isInfinite();
        assertThat(ratio.g).isEqualTo(1);
        assertThat(w.r).isCloseTo(Math.exp(-2.4 * 0.6), within(1e-15));
        assertThat(w.b).isCloseTo(Math.exp(-0.25 * 0.6), within(1e-15));
    }

    @Test
    void outOfRangeParametersAreRefused() {
        assertThatThrownBy(() -> new HomogeneousMedium(new Rgb(1, -0.1, 1), ALBEDO, 0)).hasMessageContaining("sigmaT");
        assertThatThrownBy(() -> new HomogeneousMedium(SIGMA, new Rgb(1.1, 0, 0), 0)).hasMessageContaining("albedo");
        assertThatThrownBy(() -> new HomogeneousMedium(SIGMA, ALBEDO, 1)).hasMessageContaining("(-1, 1)");
        assertThatThrownBy(() -> new HomogeneousMedium(SIGMA, ALBEDO, Double.NaN)).hasMessageContaining("(-1, 1)");
    }

    static double standardError(double sum, double sumSq, int n) {
        double mean = sum / n;
        return Math.sqrt(Math.max(sumSq / n - mean * mean, 1e-30) / n);
    }
}
