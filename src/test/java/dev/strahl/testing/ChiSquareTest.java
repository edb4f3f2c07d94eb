package dev.strahl.testing;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.testing.ChiSquare.Chart;
import dev.strahl.testing.ChiSquare.DirectionPdf;
import dev.strahl.testing.ChiSquare.DirectionSampler;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;

/**
 * The chi-square helper must have power (reject wrong densities, including subtle ones) and the
 * right size (accept correct ones about as often as its level says). The samplers here are written
 * out independently of {@code dev.strahl.sampling.Warp}, so the helper is not tested with the code
 * it is meant to test.
 */
class ChiSquareTest {
    private static final double ALPHA = ChiSquare.sidak(0.01, 8);
    private static final int N = 200_000;

    /** Cosine-weighted hemisphere by inversion: cosθ = sqrt(u1). pdf = cosθ/π. */
    private static final DirectionSampler COSINE = (u1, u2, w) -> {
        double z = Math.sqrt(u1), r = Math.sqrt(1 - u1), phi = 2 * Math.PI * u2;
        w.set(r * Math.cos(phi), r * Math.sin(phi), z);
        return true;
    };
    private static final DirectionPdf COSINE_PDF = w -> w.z() > 0 ? w.z() / Math.PI : 0;

    private static final DirectionSampler SPHERE = (u1, u2, w) -> {
        double z = 1 - 2 * u1, r = Math.sqrt(Math.max(0, 1 - z * z)), phi = 2 * Math.PI * u2;
        w.set(r * Math.cos(phi), r * Math.sin(phi), z);
        return true;
    };

    @Test
    void acceptsCorrectDensities() {
        ChiSquare.test(COSINE, COSINE_PDF, N, 1).assertAccepted(ALPHA);
        ChiSquare.test(SPHERE, w -> 1 / (4 * Math.PI), N, 2).assertAccepted(ALPHA);
    }

    @Test
    void rejectsCosineSamplesTestedAgainstTheUniformHemispherePdf() {
        ChiSquare.test(COSINE, w -> w.z() > 0 ? 1 / (2 * Math.PI) : 0, N, 3).assertRejected(1e-12);
    }

    @Test
    void rejectsAPdfWithATenPercentTilt() {
        // Still normalised (the tilt term integrates to zero), so only the shape is wrong.
        DirectionPdf tilted = w -> COSINE_PDF.pdf(w) * (1 + 0.1 * w.x());
        assertThat(ChiSquare.integrateOverSphere(tilted)).isCloseTo(1, within(1e-9));
        ChiSquare.test(COSINE, tilted, N, 4).assertRejected(1e-6);
    }

    @Test
    void rejectsAPdfFivePercentTooLarge() {
        ChiSquare.test(SPHERE, w -> 1.05 / (4 * Math.PI), N, 5).assertRejected(1e-6);
    }

    @Test
    void rejectsSamplesWhereThePdfIsZero() {
        ChiSquare.Result r = ChiSquare.test(SPHERE, w -> w.z() > 0 ? 1 / (2 * Math.PI) : 0, N, 6);
        assertThat(r.pValue()).isZero();
        assertThat(r.detail()).contains("pdf integrates to 0");
    }

    @Test
    void absorbedSamplesAreTheMassThePdfLacks() {
        DirectionSampler upperOnly = (u1, u2, w) -> SPHERE.sample(u1, u2, w) && w.z >= 0;
        // Right: the pdf integrates to the success probability 1/2.
        ChiSquare.test(upperOnly, w -> w.z() >= 0 ? 1 / (4 * Math.PI) : 0, N, 7).assertAccepted(ALPHA);
        // Wrong: the pdf claims every sample succeeds.
        ChiSquare.test(upperOnly, w -> w.z() >= 0 ? 1 / (2 * Math.PI) : 0, N, 8).assertRejected(1e-12);
    }

    @Test
    void correctDensitiesAreRejectedAboutAsOftenAsTheLevelSays() {
        int runs = 60, rejectedAtTenPercent = 0;
        double minP = 1;
        for (int seed = 0; seed < runs; seed++) {
            double p = ChiSquare.test(COSINE, COSINE_PDF, 20_000, 100 + seed).pValue();
            rejectedAtTenPercent += p < 0.1 ? 1 : 0;
            minP = Math.min(minP, p);
        }
        // Binomial(60, 0.1): mean 6, P(X > 16) < 1e-4; and some p-values must be small (p is uniform).
        assertThat(rejectedAtTenPercent).isBetween(1, 16);
        assertThat(minP).isGreaterThan(1e-4);
    }

    @Test
    void rejectsNonUniformSamplesOfTheDisk() {
        ChiSquare.PointSampler naivePolar = (u1, u2, p) -> {
            double r = u1, phi = 2 * Math.PI * u2;      // r = u1 crowds the centre
            p.set(r * Math.cos(phi), r * Math.sin(phi));
            return true;
        };
        ChiSquare.PointSampler rightPolar = (u1, u2, p) -> naivePolar.sample(Math.sqrt(u1), u2, p);
        ChiSquare.test2d(rightPolar, (x, y) -> 1 / Math.PI, Chart.unitDisk(), 10, 20, N, 9).assertAccepted(ALPHA);
        ChiSquare.test2d(naivePolar, (x, y) -> 1 / Math.PI, Chart.unitDisk(), 10, 20, N, 10).assertRejected(1e-12);
    }

    @Test
    void rejectsPointsOutsideTheChart() {
        assertThatThrownBy(() -> ChiSquare.test2d((u1, u2, p) -> {
                    p.set(u1, u2);                      // the unit square, half of it outside the triangle
                    return true;
                },
                (x, y) -> 2, Chart.unitTriangle(), 10, 10, 1000, 11))
                .isInstanceOf(AssertionError.class).hasMessageContaining("outside the domain");
    }

    @Test
    void chartsRoundTripAndTheirJacobiansIntegrateToTheArea() {
        Vector2d p = new Vector2d(), st = new Vector2d();
        for (Chart chart : new Chart[] {Chart.unitDisk(), Chart.unitTriangle()}) {
            for (double s = 0.05; s < 1; s += 0.1) {
                for (double t = 0.05; t < 1; t += 0.1) {
                    chart.fromChart(s, t, p);
                    assertThat(chart.toChart(p.x, p.y, st)).isTrue();
                    assertThat(st.x).isCloseTo(s, within(1e-12));
                    assertThat(st.y).isCloseTo(t, within(1e-12));
                }
            }
        }
        assertThat(ChiSquare.integrate2d((x, y) -> 1, Chart.unitDisk())).isCloseTo(Math.PI, within(1e-12));
        assertThat(ChiSquare.integrate2d((x, y) -> 1, Chart.unitTriangle())).isCloseTo(0.5, within(1e-12));
    }

    @Test
    void poolsCellsWithSmallExpectedCounts() {
        // Five cells of 1 pool into one of 5; with the cell of 100 that makes 2 cells, dof 1.
        ChiSquare.Result r = ChiSquare.fromCounts(new double[] {1, 1, 1, 1, 1, 100}, new long[] {1, 0, 2, 1, 1, 100});
        assertThat(r.dof()).isEqualTo(1);
        assertThat(r.statistic()).isCloseTo(0, within(1e-12));
        assertThat(r.pValue()).isCloseTo(1, within(1e-12));
        // Observed 15 in the pool against 5 expected: (15-5)^2/5 + (90-100)^2/100 = 21.
        ChiSquare.Result bad = ChiSquare.fromCounts(new double[] {1, 1, 1, 1, 1, 100}, new long[] {3, 3, 3, 3, 3, 90});
        assertThat(bad.statistic()).isCloseTo(21, within(1e-12));
        assertThat(bad.pValue()).isCloseTo(ChiSquare.chiSquareSurvival(21, 1), within(1e-15));
    }

    @Test
    void incompleteGammaMatchesKnownValues() {
        // Reference values from mpmath (30 digits) and closed forms.
        assertThat(ChiSquare.regularizedGammaP(0.5, 1)).isCloseTo(0.842700792949714869, within(1e-14)); // erf(1)
        assertThat(ChiSquare.regularizedGammaQ(3, 2)).isCloseTo(5 * Math.exp(-2), within(1e-14));
        assertThat(ChiSquare.regularizedGammaP(10, 3)).isCloseTo(0.00110248813011547974, within(1e-16));
        assertThat(ChiSquare.regularizedGammaQ(10, 15)).isCloseTo(0.0698536606994097677, within(1e-14));
        assertThat(ChiSquare.regularizedGammaP(100, 90)).isCloseTo(0.158220989186430168, within(1e-12));
        assertThat(ChiSquare.regularizedGammaQ(100, 120)).isCloseTo(0.0278637398905206615, within(1e-12));
        assertThat(ChiSquare.regularizedGammaQ(0.1, 0.01)).isCloseTo(0.337378740045520194, within(1e-14));
        assertThat(ChiSquare.regularizedGammaP(2.5, 50)).isCloseTo(1, within(1e-15));
        for (double x : new double[] {1e-3, 0.5, 1, 2, 7.5, 40}) {
            assertThat(ChiSquare.regularizedGammaP(1, x)).isCloseTo(-Math.expm1(-x), within(1e-14));
            assertThat(ChiSquare.regularizedGammaP(4, x) + ChiSquare.regularizedGammaQ(4, x)).isCloseTo(1, within(1e-14));
        }
        assertThat(ChiSquare.regularizedGammaP(3, 0)).isZero();
    }

    @Test
    void chiSquareSurvivalMatchesTableQuantiles() {
        assertThat(ChiSquare.chiSquareSurvival(3.841458820694124, 1)).isCloseTo(0.05, within(1e-12));
        assertThat(ChiSquare.chiSquareSurvival(6.634896601021214, 1)).isCloseTo(0.01, within(1e-12));
        assertThat(ChiSquare.chiSquareSurvival(18.307038053275146, 10)).isCloseTo(0.05, within(1e-12));
        assertThat(ChiSquare.chiSquareSurvival(124.34211340400407, 100)).isCloseTo(0.05, within(1e-12));
        assertThat(ChiSquare.chiSquareSurvival(300, 199)).isCloseTo(4.77602314577077352e-6, within(1e-16));
        for (double x : new double[] {0.1, 1, 4, 30}) {
            assertThat(ChiSquare.chiSquareSurvival(x, 2)).isCloseTo(Math.exp(-x / 2), within(1e-14));
        }
    }

    @Test
    void logGammaMatchesKnownValues() {
        assertThat(ChiSquare.logGamma(1)).isCloseTo(0, within(1e-14));
        assertThat(ChiSquare.logGamma(0.5)).isCloseTo(0.5 * Math.log(Math.PI), within(1e-14));
        assertThat(ChiSquare.logGamma(10)).isCloseTo(Math.log(362880), within(1e-13));
        assertThat(ChiSquare.logGamma(1e-3)).isCloseTo(6.90717888538385368, within(1e-13));
        assertThat(ChiSquare.logGamma(123.4)).isCloseTo(469.336097442190558, within(1e-11));
        assertThat(ChiSquare.logGamma(1e5)).isCloseTo(1051287.70897365689, within(1e-8));
    }

    @Test
    void sidakLevelKeepsTheFamilyWiseLevel() {
        double level = ChiSquare.sidak(0.01, 10);
        assertThat(1 - Math.pow(1 - level, 10)).isCloseTo(0.01, within(1e-15));
        assertThat(level).isLessThan(0.01 / 10 + 1e-5).isGreaterThan(0.01 / 10);
    }
}
