package dev.strahl.medium;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.math.Frame;
import dev.strahl.testing.ChiSquare;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/**
 * The Henyey–Greenstein phase function: sampling follows the density it returns (chi-square over
 * the whole sphere, for forward, backward, isotropic and nearly isotropic g, with wo along no
 * axis), the density integrates to one and has mean cosine g, and g &gt; 0 scatters forwards, as
 * Mitsuba 3's {@code hg} does.
 */
class HenyeyGreensteinTest {
    private static final double[] GS = {0, 0.3, -0.6, 0.9, -0.95, 5e-5, -2e-4};
    private static final double ALPHA = ChiSquare.sidak(0.01, GS.length);
    private static final Vector3d WO = new Vector3d(0.3, -0.5, 0.81).normalize();

    @ParameterizedTest
    @ValueSource(doubles = {0, 0.3, -0.6, 0.9, -0.95, 5e-5, -2e-4})
    void samplingFollowsTheDensity(double g) {
        Frame frame = new Frame();
        ChiSquare.test((u1, u2, wi) -> {
            double pdf = HenyeyGreenstein.sample(g, WO, u1, u2, frame, wi);
            assertThat(pdf).isCloseTo(HenyeyGreenstein.pdf(g, WO, wi), within(1e-9 * pdf));
            return true;
        }, wi -> HenyeyGreenstein.pdf(g, WO, wi), 200_000, 7, 20, 40, 32).assertAccepted(ALPHA);
    }

    @Test
    void aDensityOfTheWrongSignIsRejected() {
        Frame frame = new Frame();
        ChiSquare.Result r = ChiSquare.test((u1, u2, wi) -> {
            HenyeyGreenstein.sample(0.3, WO, u1, u2, frame, wi);
            return true;
        }, wi -> HenyeyGreenstein.pdf(-0.3, WO, wi), 400_000, 7);
        assertThat(r.pValue()).isLessThan(1e-12);
    }

    @Test
    void theDensityIntegratesToOneWithMeanCosineG() {
        for (double g : GS) {
            assertThat(ChiSquare.integrateOverSphere(w -> HenyeyGreenstein.pdf(g, WO, w))).as("g = %s", g).isCloseTo(1, within(2e-3));
            // the mean of cosθ = −wo·wi, integrated as the mean of 1 + cosθ ≥ 0 (the quadrature wants a density)
            assertThat(ChiSquare.integrateOverSphere(w -> (1 - WO.dot(w)) * HenyeyGreenstein.pdf(g, WO, w)) - 1).as("g = %s", g)
                    .isCloseTo(g, within(3e-3));
        }
    }

    @Test
    void positiveGScattersForwardsAsMitsubasHg() {
        // Mitsuba's hg: p = (1 − g²) / (4π (1 + g² + 2g·dot(wo_mitsuba, wi_mitsuba))^1.5), wi_mitsuba = −ray.d pointing back
        // along the way the light came (strahl's wo), wo_mitsuba the way it leaves (strahl's wi).
        double g = 0.7;
        Vector3d ahead = new Vector3d(WO).negate();
        double mitsubaForward = (1 - g * g) / (4 * Math.PI * Math.pow(1 + g * g + 2 * g * WO.dot(ahead), 1.5));
        assertThat(HenyeyGreenstein.pdf(g, WO, ahead)).isCloseTo(mitsubaForward, within(1e-12)).isGreaterThan(1);
        assertThat(HenyeyGreenstein.pdf(g, WO, WO)).isLessThan(0.02);
        assertThat(HenyeyGreenstein.eval(g, 1)).isCloseTo((1 + g) / (4 * Math.PI * (1 - g) * (1 - g)), within(1e-12));
        assertThat(HenyeyGreenstein.eval(0, 0.3)).isCloseTo(1 / (4 * Math.PI), within(1e-15));
    }

    @Test
    void theInverseIsMonotoneAndContinuousAcrossTheSmallGBranch() {
        SplittableRandom r = new SplittableRandom(3);
        for (int i = 0; i < 10_000; i++) {
            double u = r.nextDouble();
            double below = HenyeyGreenstein.cosTheta(Math.nextDown(HenyeyGreenstein.SMALL_G), u);
            double above = HenyeyGreenstein.cosTheta(HenyeyGreenstein.SMALL_G, u);
            assertThat(below).isCloseTo(above, within(1e-7));
        }
        double previous = -1;
        for (double g : GS) {
            for (int k = 0; k <= 1000; k++) {
                double c = HenyeyGreenstein.cosTheta(g, k / 1000.0);
                assertThat(c).isBetween(-1.0, 1.0);
                if (k > 0) {
                    assertThat(c).isGreaterThanOrEqualTo(previous);
                }
                previous = c;
            }
            assertThat(HenyeyGreenstein.cosTheta(g, 0)).isCloseTo(-1, within(1e-12));
            assertThat(HenyeyGreenstein.cosTheta(g, Math.nextDown(1.0))).isCloseTo(1, within(1e-9));
        }
    }
}
