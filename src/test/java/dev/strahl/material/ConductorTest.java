package dev.strahl.material;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import dev.strahl.testing.BsdfAssert;
import dev.strahl.testing.ChiSquare;
import dev.strahl.texture.TextureLookup;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * GGX conductor: visible-normal sampling against pdf (chi-square), weight = f·cos/pdf, reciprocity,
 * energy ≤ 1, a furnace with F = 1 (the albedo is then the GGX masking term's 1 − loss, known in
 * closed form at normal incidence only for α → 0, so it is checked against its eval integral), and
 * the conductor Fresnel term against known values.
 */
class ConductorTest {
    private static final double[] ALPHAS = {0.1, 0.2, 0.5, 1.0};
    private static final double[] THETA_O = {0, 40, 75, 88};
    private static final double ALPHA = ChiSquare.sidak(0.01, ALPHAS.length * THETA_O.length);
    private static final Rgb[] GOLD = Conductor.PRESETS.get("gold");

    static Stream<Arguments> alphasAndAngles() {
        List<Arguments> all = new ArrayList<>();
        for (double a : ALPHAS) {
            for (double t : THETA_O) {
                all.add(Arguments.of(a, t));
            }
        }
        return all.stream();
    }

    private static Conductor gold(double alpha) {
        return new Conductor(GOLD[0], GOLD[1], TextureLookup.of(alpha));
    }

    @ParameterizedTest(name = "α = {0}, θo = {1}°")
    @MethodSource("alphasAndAngles")
    void samplingMatchesPdf(double alpha, double thetaO) {
        int bins = alpha <= 0.1 ? 80 : 40;
        BsdfAssert.chiSquare(gold(alpha), BsdfAssert.direction(thetaO, 30), 1_000_000, 11 + (long) (alpha * 100 + thetaO), bins, 2 * bins)
                .assertAccepted(ALPHA);
    }

    @ParameterizedTest(name = "α = {0}")
    @ValueSource(doubles = {0.01, 0.1, 0.5, 1.0})
    void sampleEvalPdfAgreeAndAreReciprocal(double alpha) {
        Conductor c = gold(alpha);
        for (double t : THETA_O) {
            BsdfAssert.assertSampleConsistent(c, BsdfAssert.direction(t, 70), 20_000, 3);
            BsdfAssert.assertPdfCoversEval(c, BsdfAssert.direction(t, 70), 20_000, 4);
        }
        BsdfAssert.assertReciprocal(c, 20_000, 5);
        BsdfAssert.assertEnergyAtMostOne(c, 20, 20_000, 6);
    }

    /** The pdf integrates to the visible-normal mass that reflects above the surface: at most 1. */
    @Test
    void pdfIntegratesToAtMostOne() {
        for (double a : ALPHAS) {
            double integral = BsdfAssert.pdfIntegral(gold(a), BsdfAssert.direction(30, 0));
            assertThat(integral).as("α = %s", a).isLessThanOrEqualTo(1 + 1e-3);
        }
    }

    /**
     * A perfect reflector (F ≈ 1: huge k) reflects nearly everything when smooth; rough, it loses
     * what the microfacets reflect below the horizon: the single-scattering albedo of GGX at
     * α = 0.5 and θo = 60° is 0.68601 by an 800 × 1600 midpoint quadrature of the same formula
     * (docs/anchors/ggx_albedo.py), which sampling and eval must both reproduce.
     */
    @Test
    void aPerfectReflectorLosesOnlyWhatMaskingLoses() {
        Conductor perfect = new Conductor(Rgb.gray(1), Rgb.gray(1e6), TextureLookup.of(0.01));
        var e = BsdfAssert.albedoBySampling(perfect, BsdfAssert.direction(30, 0), 200_000, 9);
        assertThat(e.r()).isCloseTo(1, within(1e-3));
        var rough = new Conductor(Rgb.gray(1), Rgb.gray(1e6), TextureLookup.of(0.5));
        var bySampling = BsdfAssert.albedoBySampling(rough, BsdfAssert.direction(60, 0), 400_000, 10);
        var byEval = BsdfAssert.albedoByEval(rough, BsdfAssert.direction(60, 0), 2_000_000, 11);
        assertThat(Math.abs(bySampling.r() - byEval.r())).isLessThan(5 * Math.hypot(bySampling.errR(), byEval.errR()));
        assertThat(Math.abs(bySampling.r() - 0.68601)).isLessThan(5 * bySampling.errR() + 2e-4);
    }

    /** Fresnel of a conductor: k = 0 is the dielectric formula; normal incidence ((η−1)² + k²)/((η+1)² + k²); grazing 1. */
    @Test
    void conductorFresnelMatchesKnownValues() {
        for (double c : new double[] {1, 0.8, 0.5, 0.2, 0.05}) {
            assertThat(Fresnel.conductor(c, 1.5, 0)).isCloseTo(Fresnel.dielectric(c, 1.5), within(1e-12));
        }
        double eta = 0.143036, k = 3.983;
        assertThat(Fresnel.conductor(1, eta, k)).isCloseTo(((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k), within(1e-12));
        assertThat(Fresnel.conductor(0, eta, k)).isCloseTo(1, within(1e-12));
        assertThat(Fresnel.conductor(-0.5, eta, k)).isEqualTo(Fresnel.conductor(0.5, eta, k));
    }

    /** The weight of a sample is F(wo·m) G1(wi): for F = 1 it lies in (0, 1]. */
    @Test
    void smoothConductorReflectsFresnelAtTheMirrorDirection() {
        var s = new SmoothConductor(GOLD[0], GOLD[1]);
        BsdfSample out = new BsdfSample();
        Vector3d wo = BsdfAssert.direction(45, 10);
        assertThat(s.sample(wo, 0.3, 0.4, 0.5, out)).isTrue();
        assertThat(out.delta).isTrue();
        assertThat(out.wi.z).isCloseTo(wo.z, within(1e-15));
        assertThat(out.weight.r).isCloseTo(Fresnel.conductor(wo.z, GOLD[0].r(), GOLD[1].r()), within(1e-15));
        assertThat(Conductor.of(GOLD[0], GOLD[1], TextureLookup.of(0))).isInstanceOf(SmoothConductor.class);
        assertThat(Conductor.of(GOLD[0], GOLD[1], TextureLookup.of(0.1))).isInstanceOf(Conductor.class);
    }

    @Test
    void refusesBadParameters() {
        assertThatThrownBy(() -> new Conductor(new Rgb(0, 1, 1), Rgb.BLACK, TextureLookup.of(0.1))).hasMessageContaining("eta");
        assertThatThrownBy(() -> new Conductor(Rgb.WHITE, new Rgb(-1, 0, 0), TextureLookup.of(0.1))).hasMessageContaining("k");
        assertThatThrownBy(() -> new Conductor(Rgb.WHITE, Rgb.WHITE, TextureLookup.of(-0.1))).hasMessageContaining("alpha");
    }

    /** Sampling is allocation-free: the visible-normal sample writes into the caller's BsdfSample. */
    @Test
    void evalAndSampleAllocateNothing() {
        var mx = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        Conductor c = gold(0.3);
        BsdfSample out = new BsdfSample();
        MutableRgb f = new MutableRgb();
        Vector3d wo = BsdfAssert.direction(40, 10);
        for (int i = 0; i < 20_000; i++) {
            c.sample(wo, 0.5, (i % 97) / 97.0, (i % 89) / 89.0, out);
            c.eval(wo, out.wi, f);
        }
        long before = mx.getCurrentThreadAllocatedBytes();
        for (int i = 0; i < 100_000; i++) {
            c.sample(wo, 0.5, (i % 97) / 97.0, (i % 89) / 89.0, out);
            c.eval(wo, out.wi, f);
        }
        assertThat(mx.getCurrentThreadAllocatedBytes() - before).isLessThan(1024);
    }
}
