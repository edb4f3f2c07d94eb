package dev.strahl.material;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.color.MutableRgb;
import dev.strahl.image.Rgb;
import dev.strahl.testing.BsdfAssert;
import dev.strahl.testing.ChiSquare;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.joml.Vector2d;
import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Kd·Lambert + Ks·Beckmann rough mirror: sampling against pdf (chi-square in a chart zoomed on the
 * lobe), weight = f·cos/pdf, reciprocity, energy, the normalisation of Kd + Ks, and the
 * microfacet building blocks (D, G1, erf) against closed forms and high-precision values.
 */
class GlossyTest {
    /** Phong exponents of the MTL files: rough, medium, nearly a mirror. */
    private static final double[] NS = {10, 100, 1000};
    /** Polar angles of wo in degrees, normal to near-grazing. */
    private static final double[] THETA_O = {0, 35, 70, 87, 89};
    private static final int CHI2_SAMPLES = 1_000_000;
    /** Chi-square tests in this class: 3 materials × 5 angles, 2 uniform-sampling ones, 1 on the default chart. */
    private static final double ALPHA = ChiSquare.sidak(0.01, NS.length * THETA_O.length + 3);

    private static Glossy material(int index) {
        return switch (index) {
            case 0 -> Glossy.fromPhongExponent(Rgb.gray(0.5), Rgb.gray(0.3), NS[0]);
            case 1 -> Glossy.fromPhongExponent(new Rgb(0.6, 0.2, 0.1), Rgb.gray(0.3), NS[1]);
            default -> Glossy.fromPhongExponent(Rgb.gray(0.1), Rgb.gray(0.9), NS[2]);
        };
    }

    static Stream<Arguments> materialsAndAngles() {
        List<Arguments> all = new ArrayList<>();
        for (int m = 0; m < NS.length; m++) {
            for (double theta : THETA_O) {
                all.add(Arguments.of(m, theta));
            }
        }
        return all.stream();
    }

    // ------------------------------------------------------------------------------------------
    // Sampling against pdf

    @ParameterizedTest(name = "material {0}, θo = {1}°")
    @MethodSource("materialsAndAngles")
    void samplingMatchesPdf(int materialIndex, double thetaO) {
        Glossy bsdf = material(materialIndex);
        lobeChiSquare(bsdf, BsdfAssert.direction(thetaO, 25), CHI2_SAMPLES, 100 + materialIndex * 10L + (long) thetaO)
                .assertAccepted(ALPHA);
    }

    @ParameterizedTest(name = "θo = {0}°")
    @ValueSource(doubles = {20, 80})
    void uniformDiffuseSamplingMatchesPdf(double thetaO) {
        Bsdf bsdf = Glossy.fromPhongExponent(Rgb.gray(0.6), Rgb.gray(0.3), 100).withUniformHemisphere(true);
        assertThat(bsdf).isInstanceOf(Glossy.class);
        assertThat(((Glossy) bsdf).uniform()).isEqualTo(true);
        lobeChiSquare((Glossy) bsdf, BsdfAssert.direction(thetaO, 300), CHI2_SAMPLES, 200 + (long) thetaO).assertAccepted(ALPHA);
    }

    /** A broad lobe is resolved by the plain equal-area chart too: the shared helper agrees. */
    @Test
    void roughLobeMatchesPdfOnTheEqualAreaChart() {
        BsdfAssert.assertSamplingMatchesPdf(Glossy.fromPhongExponent(Rgb.gray(0.3), Rgb.gray(0.6), 5),
                BsdfAssert.direction(50, 0), CHI2_SAMPLES, 300, ALPHA);
    }

    /** The zoomed chart is sharp: a 3 % error in α of the claimed density is rejected outright. */
    @Test
    void chiSquareRejectsADensityWithSlightlyWrongRoughness() {
        Glossy sampled = Glossy.fromPhongExponent(Rgb.BLACK, Rgb.WHITE, 1000);
        Glossy claimed = new Glossy(Rgb.BLACK, Rgb.WHITE, sampled.alpha() * 1.03, false);
        Vector3dc wo = BsdfAssert.direction(35, 0);
        ChiSquare.Result r = lobeChiSquare(sampled, wo, w -> claimed.pdf(wo, w), CHI2_SAMPLES, 400);
        assertThat(r.pValue()).as(r.summary()).isLessThan(1e-9);
    }

    // ------------------------------------------------------------------------------------------
    // sample, eval and pdf agree; reciprocity

    @ParameterizedTest(name = "material {0}, θo = {1}°")
    @MethodSource("materialsAndAngles")
    void weightIsEvalTimesCosineOverPdf(int materialIndex, double thetaO) {
        Glossy bsdf = material(materialIndex);
        Vector3d wo = BsdfAssert.direction(thetaO, 140);
        BsdfAssert.assertSampleConsistent(bsdf, wo, 50_000, 500 + (long) thetaO);
        BsdfAssert.assertSampleConsistent(bsdf.withUniformHemisphere(true), wo, 20_000, 600 + (long) thetaO);
        BsdfAssert.assertPdfCoversEval(bsdf, wo, 20_000, 700 + (long) thetaO);
    }

    @Test
    void isReciprocal() {
        for (int m = 0; m < NS.length; m++) {
            BsdfAssert.assertReciprocal(material(m), 50_000, 800 + m);
        }
        // Near the specular peak, where the values are large.
        Glossy smooth = material(2);
        MutableRgb a = new MutableRgb(), b = new MutableRgb();
        Vector3d wo = BsdfAssert.direction(40, 0);
        Vector3d wi = BsdfAssert.direction(41, 181);
        smooth.eval(wo, wi, a);
        smooth.eval(wi, wo, b);
        assertThat(a.r).isGreaterThan(10).isCloseTo(b.r, within(1e-12 * a.r));
    }

    @Test
    void evalIsZeroUnlessBothDirectionsAreAbove() {
        Glossy bsdf = material(0);
        MutableRgb f = new MutableRgb();
        Vector3d up = BsdfAssert.direction(30, 0);
        Vector3d down = new Vector3d(up.x, up.y, -up.z);
        for (Vector3d[] pair : new Vector3d[][] {{up, down}, {down, up}, {down, down}}) {
            bsdf.eval(pair[0], pair[1], f);
            assertThat(f.isBlack()).isTrue();
            assertThat(bsdf.pdf(pair[0], pair[1])).isZero();
        }
        assertThat(bsdf.sample(down, 0.5, 0.5, 0.5, new BsdfSample())).isFalse();
        assertThat(bsdf.isDelta()).isFalse();
        assertThat(bsdf.isTwoSided()).isTrue();
    }

    /** f = Kd/π + Ks·D·G/(4 cosθo cosθi), spelled out at one pair of directions. */
    @Test
    void evalIsDiffusePlusMicrofacetMirror() {
        Glossy bsdf = Glossy.fromPhongExponent(new Rgb(0.2, 0.3, 0.4), new Rgb(0.5, 0.4, 0.3), 50);
        Vector3d wo = BsdfAssert.direction(30, 10), wi = BsdfAssert.direction(45, 200);
        Vector3d h = new Vector3d(wo).add(wi).normalize();
        double alpha = bsdf.alpha();
        double tan2 = (1 - h.z * h.z) / (h.z * h.z);
        double d = Math.exp(-tan2 / (alpha * alpha)) / (Math.PI * alpha * alpha * Math.pow(h.z, 4));
        double g = Glossy.smithG1(wo, alpha) * Glossy.smithG1(wi, alpha);
        double spec = d * g / (4 * wo.z * wi.z);
        MutableRgb f = new MutableRgb();
        bsdf.eval(wo, wi, f);
        assertThat(f.r).isCloseTo(0.2 / Math.PI + 0.5 * spec, within(1e-13));
        assertThat(f.g).isCloseTo(0.3 / Math.PI + 0.4 * spec, within(1e-13));
        assertThat(f.b).isCloseTo(0.4 / Math.PI + 0.3 * spec, within(1e-13));
    }

    // ------------------------------------------------------------------------------------------
    // Energy

    @Test
    void albedoIsAtMostOneForEveryDirection() {
        BsdfAssert.assertEnergyAtMostOne(Glossy.fromPhongExponent(Rgb.gray(0.5), Rgb.gray(0.5), 10), 20, 50_000, 900);
        BsdfAssert.assertEnergyAtMostOne(Glossy.fromPhongExponent(Rgb.gray(0.2), Rgb.gray(0.8), 100), 20, 50_000, 901);
        BsdfAssert.assertEnergyAtMostOne(Glossy.fromPhongExponent(Rgb.BLACK, Rgb.WHITE, 1000), 20, 50_000, 902);
        BsdfAssert.assertEnergyAtMostOne(Glossy.fromPhongExponent(Rgb.WHITE, Rgb.WHITE, 0), 20, 50_000, 903);
    }

    /**
     * A white Ks-only surface lit at normal incidence: wo = n, so h = m, wi at 2θm, G1(wo) = 1 and
     * the weight of distribution sampling is G1(wi); the albedo is
     * ρ = 2π ∫₀^{π/4} D(θ) cosθ sinθ G1(2θ) dθ (wi leaves the surface for θm &lt; 45°), computed
     * here by quadrature. The Monte Carlo albedo must agree, and for smooth surfaces be close to 1.
     */
    @ParameterizedTest(name = "Ns = {0}")
    @ValueSource(doubles = {10, 100, 1000})
    void specularAlbedoAtNormalIncidenceMatchesQuadrature(double ns) {
        Glossy bsdf = Glossy.fromPhongExponent(Rgb.BLACK, Rgb.WHITE, ns);
        double alpha = bsdf.alpha();
        double expected = simpson(theta -> 2 * Math.PI * beckmannD(theta, alpha) * Math.cos(theta) * Math.sin(theta)
                * Glossy.smithG1(BsdfAssert.direction(Math.toDegrees(2 * theta), 0), alpha), 0, Math.PI / 4, 200_000);
        BsdfAssert.Estimate e = BsdfAssert.albedoBySampling(bsdf, new Vector3d(0, 0, 1), 200_000, 1000 + (long) ns);
        assertThat(e.isCloseTo(Rgb.gray(expected), 5)).as("sampled %s vs quadrature %s", e, expected).isTrue();
        assertThat(expected).isLessThanOrEqualTo(1);
        if (ns >= 100) {
            assertThat(expected).isGreaterThan(0.99);
        } else {
            assertThat(expected).isGreaterThan(0.9);
        }
    }

    /** The albedo by the BSDF's own sampling and by uniform sampling of eval agree (rough lobes, several wo). */
    @ParameterizedTest(name = "θo = {0}°")
    @ValueSource(doubles = {0, 45, 80})
    void sampledAlbedoAgreesWithUniformEstimate(double thetaO) {
        Glossy bsdf = Glossy.fromPhongExponent(new Rgb(0.5, 0.3, 0.1), Rgb.gray(0.4), 10);
        Vector3d wo = BsdfAssert.direction(thetaO, 70);
        BsdfAssert.Estimate bySampling = BsdfAssert.albedoBySampling(bsdf, wo, 400_000, 1100 + (long) thetaO);
        BsdfAssert.Estimate byEval = BsdfAssert.albedoByEval(bsdf, wo, 400_000, 1200 + (long) thetaO);
        double z = 5;
        assertThat(bySampling.r()).isCloseTo(byEval.r(), within(z * Math.hypot(bySampling.errR(), byEval.errR())));
        assertThat(bySampling.g()).isCloseTo(byEval.g(), within(z * Math.hypot(bySampling.errG(), byEval.errG())));
        assertThat(bySampling.b()).isCloseTo(byEval.b(), within(z * Math.hypot(bySampling.errB(), byEval.errB())));
    }

    @Test
    void factoryDividesKdAndKsByTheirLargestSumAboveOne() {
        Glossy g = Glossy.fromPhongExponent(new Rgb(0.8, 0.6, 0.2), new Rgb(0.5, 0.5, 0.5), 100);
        assertThat(g.diffuse().r()).isCloseTo(0.8 / 1.3, within(1e-15));
        assertThat(g.diffuse().g()).isCloseTo(0.6 / 1.3, within(1e-15));
        assertThat(g.diffuse().b()).isCloseTo(0.2 / 1.3, within(1e-15));
        assertThat(g.specular().r()).isCloseTo(0.5 / 1.3, within(1e-15));
        assertThat(g.diffuse().r() + g.specular().r()).isCloseTo(1, within(1e-15));
        // At most 1 already: unchanged.
        Glossy unchanged = Glossy.fromPhongExponent(new Rgb(0.5, 0.2, 0.1), new Rgb(0.5, 0.3, 0.1), 100);
        assertThat(unchanged.diffuse()).isEqualTo(new Rgb(0.5, 0.2, 0.1));
        assertThat(unchanged.specular()).isEqualTo(new Rgb(0.5, 0.3, 0.1));
        // The constructor refuses what the factory would have normalised.
        assertThatThrownBy(() -> new Glossy(Rgb.gray(0.6), Rgb.gray(0.6), 0.1, false))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("energy");
        assertThatThrownBy(() -> new Glossy(Rgb.gray(0.5), Rgb.gray(0.5), 0, false))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> Glossy.fromPhongExponent(Rgb.gray(0.5), Rgb.gray(0.5), -1))
                .isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void alphaFromPhongExponentInvertsWaltersCorrespondence() {
        assertThat(Glossy.alphaFromPhongExponent(0)).isEqualTo(1);
        assertThat(Glossy.alphaFromPhongExponent(10)).isCloseTo(Math.sqrt(1 / 6.0), within(1e-15));
        for (double ns : new double[] {1, 10, 100, 1000, 1e5}) {
            double alpha = Glossy.alphaFromPhongExponent(ns);
            assertThat(2 / (alpha * alpha) - 2).as("Ns = 2 α⁻² − 2").isCloseTo(ns, within(1e-9 * ns));
        }
    }

    @Test
    void blackMaterialAbsorbsEverything() {
        Glossy black = new Glossy(Rgb.BLACK, Rgb.BLACK, 0.3, false);
        Vector3d wo = BsdfAssert.direction(20, 0);
        assertThat(black.sample(wo, 0.5, 0.5, 0.5, new BsdfSample())).isFalse();
        assertThat(black.pdf(wo, BsdfAssert.direction(20, 180))).isZero();
    }

    // ------------------------------------------------------------------------------------------
    // Microfacet building blocks

    /** ∫ D(m) cosθm dωm = 2π ∫₀^{π/2} D(θ) cosθ sinθ dθ = 1 (the projected microfacet area is the macro area). */
    @ParameterizedTest(name = "α = {0}")
    @ValueSource(doubles = {1.0, 0.408, 0.14, 0.0447, 0.01})
    void beckmannIntegratesToOneOverTheProjectedHemisphere(double alpha) {
        double integral = simpson(theta -> 2 * Math.PI * beckmannD(theta, alpha) * Math.cos(theta) * Math.sin(theta),
                0, Math.PI / 2, 200_000);
        assertThat(integral).isCloseTo(1, within(1e-9));
        assertThat(beckmannD(0, alpha)).as("peak 1/(πα²)").isCloseTo(1 / (Math.PI * alpha * alpha), within(1e-12 / (alpha * alpha)));
        if (alpha >= 0.3) {
            assertThat(ChiSquare.integrateOverSphere(w -> Glossy.beckmannD(w.x(), w.y(), w.z(), alpha) * Math.max(0, w.z())))
                    .isCloseTo(1, within(1e-6));
        }
    }

    /** Reference values of erf and erfc to 20 digits (mpmath, 40-digit arithmetic). */
    @Test
    void erfAndErfcMatchHighPrecisionValues() {
        double[][] reference = {
            // x, erf(x), erfc(x)
            {0.1, 0.1124629160182848922, 0.8875370839817151078},
            {0.5, 0.52049987781304653768, 0.47950012218695346232},
            {1, 0.84270079294971486934, 0.15729920705028513066},
            {1.5, 0.96610514647531072707, 0.033894853524689272933},
            {1.999, 0.99530155665137051003, 0.0046984433486294899663},
            {2, 0.99532226501895273416, 0.0046777349810472658379},
            {2.5, 0.99959304798255504106, 0.00040695201744495893956},
            {3, 0.99997790950300141456, 0.000022090496998585441373},
            {4, 0.99999998458274209972, 1.5417257900280018852e-8},
            {5, 0.99999999999846254021, 1.5374597944280348502e-12},
            {6, 0.99999999999999997848, 2.1519736712498913117e-17},
        };
        for (double[] r : reference) {
            double x = r[0];
            assertThat(Glossy.erf(x)).as("erf(%s)", x).isCloseTo(r[1], within(1e-15));
            assertThat(Glossy.erf(-x)).as("erf(-%s)", x).isCloseTo(-r[1], within(1e-15));
            assertThat(Glossy.erfc(x)).as("erfc(%s)", x).isCloseTo(r[2], within(2e-13 * r[2]));
            assertThat(Glossy.erfc(-x)).as("erfc(-%s)", x).isCloseTo(2 - r[2], within(4e-16));
        }
        assertThat(Glossy.erf(0)).isZero();
        assertThat(Glossy.erfc(0)).isEqualTo(1);
        assertThat(Glossy.erfc(30)).isZero();
        // No jump where the method changes (x = 2): the slope there is −(2/√π) e^{−4} ≈ −0.0207.
        double below = Glossy.erfc(Math.nextDown(2.0)), at = Glossy.erfc(2.0);
        assertThat(below - at).isBetween(0.0, 5e-16);
    }

    /**
     * Smith G1 for Beckmann against values of 2/(1 + erf(a) + e^{−a²}/(a√π)) to 20 digits, and
     * against Walter et al.'s rational approximation (relative error &lt; 0.35 %) over all angles.
     */
    @Test
    void smithG1MatchesExactValuesAndWaltersApproximation() {
        double[][] reference = {
            {0.1, 0.29858674638241916823},
            {0.5, 0.83358255480699046274},
            {1, 0.97548863292880548767},
            {1.6, 0.99819951550776919256},
            {3, 0.99999944082781640411},
        };
        double alpha = 0.5;
        for (double[] r : reference) {
            double a = r[0];
            double theta = Math.atan(1 / (a * alpha));           // a = 1/(α tanθ)
            Vector3d v = new Vector3d(Math.sin(theta), 0, Math.cos(theta));
            assertThat(Glossy.smithG1(v, alpha)).as("G1 at a = %s", a).isCloseTo(r[1], within(1e-14));
        }
        for (double alphaK : new double[] {0.05, 0.2, 0.7}) {
            for (int k = 0; k < 900; k++) {
                double theta = Math.toRadians(k * 0.1);
                Vector3d v = new Vector3d(Math.sin(theta), 0, Math.cos(theta));
                double a = 1 / (alphaK * Math.tan(theta));
                double walter = a >= 1.6 ? 1 : (3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a);
                double g1 = Glossy.smithG1(v, alphaK);
                assertThat(g1).isBetween(0.0, 1.0);
                assertThat(g1).as("α = %s, θ = %s°", alphaK, k * 0.1).isCloseTo(walter, within(0.0036 * g1 + 1e-15));
            }
        }
        assertThat(Glossy.smithG1(new Vector3d(0, 0, 1), 0.3)).isEqualTo(1);
        assertThat(Glossy.smithG1(new Vector3d(1, 0, 0), 0.3)).isZero();
    }

    @Test
    void samplingAndEvaluationAllocateNothing() {
        var mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        Glossy bsdf = material(1);
        BsdfSample s = new BsdfSample();
        MutableRgb f = new MutableRgb();
        Vector3d wo = BsdfAssert.direction(50, 10), wi = BsdfAssert.direction(40, 170);
        double sink = 0;
        for (int pass = 0; pass < 2; pass++) {                    // the first pass warms up the JIT
            long before = mx.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < 20_000; i++) {
                double u = (i % 997) / 997.0;
                bsdf.sample(wo, u, (i % 101) / 101.0, u, s);
                bsdf.eval(wo, wi, f);
                sink += bsdf.pdf(wo, wi) + f.g + s.weight.r;
            }
            if (pass == 1) {
                assertThat(mx.getCurrentThreadAllocatedBytes() - before).as("bytes allocated").isLessThan(1024);
            }
        }
        assertThat(sink).isFinite();
    }

    // ------------------------------------------------------------------------------------------
    // Helpers

    private static double beckmannD(double theta, double alpha) {
        return Glossy.beckmannD(Math.sin(theta), 0, Math.cos(theta), alpha);
    }

    /** Composite Simpson rule with {@code intervals} (even) intervals. */
    private static double simpson(java.util.function.DoubleUnaryOperator f, double a, double b, int intervals) {
        double h = (b - a) / intervals;
        double sum = f.applyAsDouble(a) + f.applyAsDouble(b);
        for (int i = 1; i < intervals; i++) {
            sum += (i % 2 == 1 ? 4 : 2) * f.applyAsDouble(a + i * h);
        }
        return sum * h / 3;
    }

    private static ChiSquare.Result lobeChiSquare(Glossy bsdf, Vector3dc wo, int samples, long seed) {
        return lobeChiSquare(bsdf, wo, w -> bsdf.pdf(wo, w), samples, seed);
    }

    /**
     * Chi-square test of {@code bsdf.sample} against {@code pdf} in the coordinates (z = cosθ, φ),
     * where dω = dz dφ, so the density per dz dφ is the solid-angle pdf. The cells are laid out by
     * a chart that is fine around the mirror direction of wo, whatever α: the plain equal-area
     * grid of {@link ChiSquare#test} cannot resolve a lobe of width α = 0.045 (Ns = 1000). The chart:
     * <ul>
     *   <li>z: the lower hemisphere [−1, 0) gets 2 of the 42 rows (the samples must avoid it), the
     *       upper one the other 40 through a sinh map x = c + h sinh(A + (B − A) u) centred on the
     *       mirror direction's z with scale h = α sinθr + α²; the horizon z = 0 is a cell edge, so
     *       the jump of the density there stays on an edge, where the quadrature handles it;</li>
     *   <li>φ: 40 columns over [φr − π, φr + π) through a sinh map centred on the mirror azimuth
     *       φr with scale α max(cosθr, α) / max(sinθr, α). The cosθr: at grazing wo and wi are
     *       nearly opposite, so h = normalize(wo + wi) turns fast as wi leaves the plane of
     *       incidence and the lobe is squeezed to an azimuthal width of about 2α cosθo.</li>
     * </ul>
     * Lobe choices use their own seeded stream; absorbed samples (wi below the surface) form the
     * extra cell of the missing mass.
     */
    private static ChiSquare.Result lobeChiSquare(Glossy bsdf, Vector3dc wo, ChiSquare.DirectionPdf pdf, int samples, long seed) {
        double alpha = bsdf.alpha();
        double zc = wo.z();
        double sinR = Math.sqrt(Math.max(0, 1 - zc * zc));
        double phiC = Math.atan2(-wo.y(), -wo.x());
        SinhMap zMap = SinhMap.of(0, 1, zc, alpha * sinR + alpha * alpha);
        SinhMap phiMap = SinhMap.of(phiC - Math.PI, phiC + Math.PI, phiC, alpha * Math.max(zc, alpha) / Math.max(sinR, alpha));
        int zBins = 42, phiBins = 40;
        double s0 = 2.0 / zBins;
        ChiSquare.Chart chart = new ChiSquare.Chart() {
            @Override
            public boolean toChart(double z, double phi, Vector2d dest) {
                if (!(z >= -1 && z <= 1)) {
                    return false;
                }
                double s = z < 0 ? (z + 1) * s0 : s0 + (1 - s0) * zMap.u(z);
                dest.set(s, phiMap.u(phi));
                return true;
            }

            @Override
            public double fromChart(double s, double t, Vector2d dest) {
                double z, jacobianZ;
                if (s < s0) {
                    z = -1 + s / s0;
                    jacobianZ = 1 / s0;
                } else {
                    double u = (s - s0) / (1 - s0);
                    z = zMap.x(u);
                    jacobianZ = zMap.dxdu(u) / (1 - s0);
                }
                dest.set(z, phiMap.x(t));
                return jacobianZ * phiMap.dxdu(t);
            }
        };
        Vector3d w = new Vector3d();
        ChiSquare.PointPdf pointPdf = (z, phi) -> {
            double r = Math.sqrt(Math.max(0, 1 - z * z));
            return pdf.pdf(w.set(r * Math.cos(phi), r * Math.sin(phi), z));
        };
        SplittableRandom lobe = new SplittableRandom(seed * 31 + 7);
        BsdfSample s = new BsdfSample();
        ChiSquare.PointSampler sampler = (u1, u2, dest) -> {
            if (!bsdf.sample(wo, lobe.nextDouble(), u1, u2, s)) {
                return false;
            }
            double phi = Math.atan2(s.wi.y, s.wi.x);
            while (phi < phiC - Math.PI) {
                phi += 2 * Math.PI;
            }
            while (phi >= phiC + Math.PI) {
                phi -= 2 * Math.PI;
            }
            dest.set(s.wi.z, phi);
            return true;
        };
        return ChiSquare.test2d(sampler, pointPdf, chart, zBins, phiBins, samples, seed);
    }

    /** A monotone map of u ∈ [0, 1] onto [lo, hi], fine near c at scale h: x = c + h sinh(A + (B − A) u). */
    private record SinhMap(double c, double h, double a, double b) {
        static SinhMap of(double lo, double hi, double c, double h) {
            return new SinhMap(c, h, asinh((lo - c) / h), asinh((hi - c) / h));
        }

        double x(double u) {
            return c + h * Math.sinh(a + (b - a) * u);
        }

        double dxdu(double u) {
            return h * (b - a) * Math.cosh(a + (b - a) * u);
        }

        double u(double x) {
            return (asinh((x - c) / h) - a) / (b - a);
        }

        private static double asinh(double x) {
            double ax = Math.abs(x);
            return Math.copySign(Math.log(ax + Math.sqrt(ax * ax + 1)), x);
        }
    }
}
