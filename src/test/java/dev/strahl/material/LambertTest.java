package dev.strahl.material;

import static dev.strahl.testing.BsdfAssert.direction;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.color.MutableRgb;
import dev.strahl.image.Rgb;
import dev.strahl.testing.BsdfAssert;
import dev.strahl.testing.ChiSquare;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Lambertian reflection: closed form, sampling against pdf, reciprocity, energy. */
class LambertTest {
    /** Chi-square tests in this class: 2 modes × 3 directions; together they keep a 1 % false-alarm level. */
    private static final double ALPHA = ChiSquare.sidak(0.01, 6);
    private static final Vector3dc UP = new Vector3d(0, 0, 1);
    private static final Rgb ALBEDO = new Rgb(0.8, 0.5, 0.2);
    /** The outgoing directions every sampling property is checked for: normal, oblique and grazing. */
    private static final Vector3dc[] WO = {UP, direction(30, 40), direction(85, 200)};

    private static Lambert lambert(boolean mode) {
        return new Lambert(ALBEDO, mode);
    }

    private static Vector3d random(SplittableRandom random) {
        return new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
    }

    // ---------------------------------------------------------------------------------------------
    // Closed form

    @Test
    void evalIsAlbedoOverPiWhenBothDirectionsAreAbove() {
        Lambert bsdf = new Lambert(ALBEDO);
        MutableRgb f = new MutableRgb();
        SplittableRandom random = new SplittableRandom(1);
        for (int i = 0; i < 10_000; i++) {
            Vector3d wo = random(random), wi = random(random);
            bsdf.eval(wo, wi, f);
            if (wo.z > 0 && wi.z > 0) {
                assertThat(f.r).as("f = albedo/π, wo = %s, wi = %s", wo, wi).isCloseTo(0.8 / Math.PI, within(1e-15));
                assertThat(f.g).isCloseTo(0.5 / Math.PI, within(1e-15));
                assertThat(f.b).isCloseTo(0.2 / Math.PI, within(1e-15));
            } else {
                assertThat(f.isBlack()).as("no transmission and no light from below: wo = %s, wi = %s, f = %s", wo, wi, f).isTrue();
            }
        }
    }

    @Test
    void evalIsZeroAtTheHorizon() {
        MutableRgb f = new MutableRgb(1, 1, 1);
        new Lambert(ALBEDO).eval(UP, direction(90, 0).setComponent(2, 0), f);
        assertThat(f.isBlack()).isTrue();
        f.set(1, 1, 1);
        new Lambert(ALBEDO).eval(direction(90, 0).setComponent(2, 0), UP, f);
        assertThat(f.isBlack()).isTrue();
    }

    @Test
    void pdfIsCosineOverPiOrUniform() {
        Lambert cosine = lambert(false), uniform = lambert(true);
        Vector3dc wo = direction(20, 0);
        for (double theta : new double[] {0, 10, 45, 80, 89.99}) {
            Vector3d wi = direction(theta, 123);
            assertThat(cosine.pdf(wo, wi)).as("cosine pdf at θ = %s", theta).isCloseTo(Math.cos(Math.toRadians(theta)) / Math.PI, within(1e-15));
            assertThat(uniform.pdf(wo, wi)).as("uniform pdf at θ = %s", theta).isCloseTo(1 / (2 * Math.PI), within(1e-15));
        }
        Vector3d below = direction(120, 10);
        assertThat(cosine.pdf(wo, below)).isZero();
        assertThat(uniform.pdf(wo, below)).isZero();
        assertThat(cosine.pdf(below, wo)).as("wo below the surface").isZero();
        assertThat(uniform.pdf(below, wo)).isZero();
    }

    @Test
    void defaultSamplingIsCosineAndTheLobeIsNotDeltaAndTwoSided() {
        Lambert bsdf = new Lambert(ALBEDO);
        assertThat(bsdf.uniform()).isEqualTo(false);
        assertThat(bsdf.isDelta()).isFalse();
        assertThat(bsdf.isTwoSided()).isTrue();
    }

    // ---------------------------------------------------------------------------------------------
    // Sampling

    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void samplingMatchesPdfChiSquare(boolean mode) {
        for (int k = 0; k < WO.length; k++) {
            BsdfAssert.assertSamplingMatchesPdf(lambert(mode), WO[k], 1_000_000, 17 + k, ALPHA);
        }
    }

    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void pdfIntegratesToOne(boolean mode) {
        for (Vector3dc wo : WO) {
            assertThat(BsdfAssert.pdfIntegral(lambert(mode), wo)).as("wo = %s", wo).isCloseTo(1, within(1e-9));
        }
    }

    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void weightIsEvalTimesCosineOverPdfForEverySample(boolean mode) {
        for (Vector3dc wo : WO) {
            BsdfAssert.assertSampleConsistent(lambert(mode), wo, 100_000, 3);
            BsdfAssert.assertPdfCoversEval(lambert(mode), wo, 100_000, 4);
        }
    }

    @Test
    void weightIsTheClosedForm() {
        BsdfSample s = new BsdfSample();
        assertThat(lambert(false).sample(WO[1], 0.5, 0.3, 0.7, s)).isTrue();
        assertThat(s.weight.toRgb()).as("cosine sampling: weight = albedo").isEqualTo(ALBEDO);
        assertThat(s.delta).isFalse();
        assertThat(lambert(true).sample(WO[1], 0.5, 0.3, 0.7, s)).isTrue();
        assertThat(s.weight.r).as("uniform sampling: weight = 2·albedo·cosθ").isCloseTo(2 * 0.8 * s.wi.z, within(1e-15));
    }

    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void noSampleFromBelowTheSurface(boolean mode) {
        BsdfSample s = new BsdfSample();
        SplittableRandom random = new SplittableRandom(8);
        for (int i = 0; i < 1000; i++) {
            Vector3d wo = direction(90 + 90 * random.nextDouble(), 360 * random.nextDouble());
            assertThat(lambert(mode).sample(wo, random.nextDouble(), random.nextDouble(), random.nextDouble(), s))
                    .as("wo = %s", wo).isFalse();
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Reciprocity and energy

    @Test
    void isReciprocal() {
        BsdfAssert.assertReciprocal(new Lambert(ALBEDO), 10_000, 5);
    }

    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void conservesEnergy(boolean mode) {
        BsdfAssert.assertEnergyAtMostOne(new Lambert(Rgb.WHITE, mode), 20, 20_000, 6);
        BsdfAssert.assertEnergyAtMostOne(lambert(mode), 20, 20_000, 7);
    }

    /** ∫ f cosθi dωi = albedo for every wo, estimated both by the BSDF's sampling and independently of it. */
    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void directionalAlbedoIsTheAlbedo(boolean mode) {
        for (Vector3dc wo : WO) {
            BsdfAssert.Estimate bySampling = BsdfAssert.albedoBySampling(lambert(mode), wo, 200_000, 9);
            BsdfAssert.Estimate byEval = BsdfAssert.albedoByEval(lambert(mode), wo, 200_000, 10);
            assertThat(bySampling.isCloseTo(ALBEDO, 5)).as("%s sampling, wo = %s: %s", mode, wo, bySampling).isTrue();
            assertThat(byEval.isCloseTo(ALBEDO, 5)).as("uniform sphere estimate, wo = %s: %s", wo, byEval).isTrue();
            assertThat(byEval.errR()).as("the estimate is precise enough to mean something").isLessThan(0.005);
        }
        // Cosine sampling is exact: every weight is the albedo.
        BsdfAssert.Estimate exact = BsdfAssert.albedoBySampling(lambert(false), WO[2], 1000, 11);
        assertThat(exact.r()).isCloseTo(0.8, within(1e-12));
        assertThat(exact.errR()).isCloseTo(0, within(1e-12));
    }

    // ---------------------------------------------------------------------------------------------
    // Construction

    @Test
    void withHemisphereSamplingReturnsALambertWithThatMode() {
        Lambert cosine = new Lambert(ALBEDO);
        Bsdf uniform = cosine.withUniformHemisphere(true);
        assertThat(uniform).isEqualTo(new Lambert(ALBEDO, true));
        assertThat(uniform.withUniformHemisphere(false)).isEqualTo(cosine);
        assertThat(cosine.withUniformHemisphere(false)).isSameAs(cosine);
    }

    @Test
    void refusesAlbedoOutsideZeroToOne() {
        for (Rgb bad : new Rgb[] {new Rgb(1.01, 0.5, 0.5), new Rgb(0.5, 0.5, 1 + 1e-9), new Rgb(-0.1, 0, 0), new Rgb(0, -1e-12, 0)}) {
            assertThatThrownBy(() -> new Lambert(bad)).as("albedo %s", bad)
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("albedo");
        }
        assertThat(new Lambert(Rgb.BLACK).albedo().mean()).isEqualTo(Rgb.BLACK);
        assertThat(new Lambert(Rgb.WHITE).albedo().mean()).isEqualTo(Rgb.WHITE);
    }

    /** A missing sampling mode must not silently mean uniform sampling. */
    @Test
    void refusesMissingArguments() {
        assertThatThrownBy(() -> new Lambert((Rgb) null)).isInstanceOf(NullPointerException.class).hasMessageContaining("albedo");
    }
}
