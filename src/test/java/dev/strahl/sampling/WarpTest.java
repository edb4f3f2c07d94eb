package dev.strahl.sampling;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.testing.ChiSquare;
import dev.strahl.testing.ChiSquare.Chart;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** Every warp against its density: chi-square of the samples, and the density integrates to one. */
class WarpTest {
    /** Six chi-square tests in this class; together they keep a 1 % false-alarm level. */
    private static final double ALPHA = ChiSquare.sidak(0.01, 6);
    private static final int N = 1_000_000;

    @FunctionalInterface
    private interface DirectionWarp {
        Vector3d apply(double u1, double u2, Vector3d dest);
    }

    /** A warp as a chi-square sampler that never absorbs a sample. */
    private static ChiSquare.DirectionSampler never(DirectionWarp warp) {
        return (u1, u2, w) -> {
            warp.apply(u1, u2, w);
            return true;
        };
    }

    /** Uniform numbers that include the corners and edges of the square, where warps have their special cases. */
    private static double[] edgeCases() {
        return new double[] {0, Double.MIN_VALUE, 1e-300, 1e-12, 0.25, 0.5, Math.nextDown(0.5), Math.nextUp(0.5),
            0.75, 1 - 1e-12, Math.nextDown(1.0)};
    }

    @Test
    void cosineHemisphereFollowsCosineOverPi() {
        ChiSquare.test(never(Warp::cosineHemisphere),
                w -> Warp.cosineHemispherePdf(w.z()), N, 1).assertAccepted(ALPHA);
    }

    @Test
    void uniformHemisphereIsUniformOverTheUpperHemisphere() {
        ChiSquare.test(never(Warp::uniformHemisphere),
                w -> Warp.uniformHemispherePdf(w.z()), N, 2).assertAccepted(ALPHA);
    }

    @Test
    void uniformSphereIsUniform() {
        ChiSquare.test(never(Warp::uniformSphere),
                w -> Warp.uniformSpherePdf(), N, 3).assertAccepted(ALPHA);
    }

    /** A cone of 53° half-angle: its edge cosθ = 0.6 falls on an edge of the 10 cosθ bins, so the cells see no partial coverage. */
    @Test
    void uniformConeIsUniformInsideTheConeAndEmptyOutside() {
        ChiSquare.test(never((u1, u2, d) -> Warp.uniformCone(u1, u2, 0.6, d)),
                w -> Warp.uniformConePdf(w.z(), 0.6), N, 6).assertAccepted(ALPHA);
    }

    @Test
    void uniformConeStaysInsideItsConeAtTheEdgesOfTheSquare() {
        Vector3d w = new Vector3d();
        for (double cosMax : new double[] {-1, 0, 0.5, Math.cos(1e-3), 1 - 1e-12}) {
            for (double u1 : edgeCases()) {
                for (double u2 : edgeCases()) {
                    Warp.uniformCone(u1, u2, cosMax, w);
                    assertThat(w.length()).isCloseTo(1, within(1e-12));
                    assertThat(w.z).isGreaterThanOrEqualTo(cosMax - 1e-12);
                }
            }
        }
        assertThat(Warp.uniformConePdf(0.49, 0.5)).isZero();
        assertThat(Warp.uniformConePdf(1, 1)).as("a degenerate cone has no density").isZero();
        assertThat(Warp.uniformConePdf(0.7, -1)).isCloseTo(Warp.uniformSpherePdf(), within(1e-15));
    }

    @Test
    void directionPdfsIntegrateToOne() {
        assertThat(ChiSquare.integrateOverSphere(w -> Warp.cosineHemispherePdf(w.z()))).isCloseTo(1, within(1e-9));
        assertThat(ChiSquare.integrateOverSphere(w -> Warp.uniformHemispherePdf(w.z()))).isCloseTo(1, within(1e-9));
        assertThat(ChiSquare.integrateOverSphere(w -> Warp.uniformSpherePdf())).isCloseTo(1, within(1e-9));
        assertThat(ChiSquare.integrateOverSphere(w -> Warp.uniformConePdf(w.z(), 0.5))).isCloseTo(1, within(1e-9));
    }

    @Test
    void hemisphereSamplesAreUnitAndAboveTheHorizon() {
        Vector3d w = new Vector3d();
        for (double u1 : edgeCases()) {
            for (double u2 : edgeCases()) {
                Warp.cosineHemisphere(u1, u2, w);
                assertThat(w.length()).as("cosine |w| for u = (%s, %s)", u1, u2).isCloseTo(1, within(1e-12));
                assertThat(w.z).isGreaterThanOrEqualTo(0);
                Warp.uniformHemisphere(u1, u2, w);
                assertThat(w.length()).as("uniform |w| for u = (%s, %s)", u1, u2).isCloseTo(1, within(1e-12));
                assertThat(w.z).isGreaterThanOrEqualTo(0);
                Warp.uniformSphere(u1, u2, w);
                assertThat(w.length()).as("sphere |w| for u = (%s, %s)", u1, u2).isCloseTo(1, within(1e-12));
            }
        }
    }

    @Test
    void pdfsAreZeroBelowTheHorizon() {
        assertThat(Warp.cosineHemispherePdf(-0.3)).isZero();
        assertThat(Warp.uniformHemispherePdf(-0.3)).isZero();
        assertThat(Warp.cosineHemispherePdf(0.5)).isCloseTo(0.5 / Math.PI, within(1e-15));
    }

    @Test
    void concentricDiskStaysInTheDisk() {
        Vector3d p = new Vector3d();
        for (double u1 : edgeCases()) {
            for (double u2 : edgeCases()) {
                Warp.concentricDisk(u1, u2, p);
                assertThat(p.x * p.x + p.y * p.y).as("|p|^2 for u = (%s, %s)", u1, u2).isLessThanOrEqualTo(1 + 1e-15);
                assertThat(p.z).isZero();
            }
        }
        SplittableRandom random = new SplittableRandom(4);
        for (int i = 0; i < 100_000; i++) {
            Warp.concentricDisk(random.nextDouble(), random.nextDouble(), p);
            assertThat(p.x * p.x + p.y * p.y).isLessThanOrEqualTo(1 + 1e-15);
        }
        // Corners of the square go to the rim; the centre to the centre.
        assertThat(Warp.concentricDisk(0.5, 0.5, p).length()).isZero();
        assertThat(Warp.concentricDisk(1, 0.5, p).distance(1, 0, 0)).isCloseTo(0, within(1e-15));
    }

    @Test
    void concentricDiskIsUniformByArea() {
        Vector3d q = new Vector3d();
        ChiSquare.test2d((u1, u2, p) -> {
            Warp.concentricDisk(u1, u2, q);
            p.set(q.x, q.y);
            return true;
        }, (x, y) -> 1 / Math.PI, Chart.unitDisk(), 10, 20, N, 5).assertAccepted(ALPHA);
    }

    @Test
    void uniformTriangleIsUniformOverTheTriangle() {
        Vector3d b = new Vector3d();
        // (b0, b1) live in the triangle {b0, b1 >= 0, b0 + b1 <= 1} of area 1/2: density 2.
        ChiSquare.test2d((u1, u2, p) -> {
            Warp.uniformTriangle(u1, u2, b);
            p.set(b.x, b.y);
            return true;
        }, (x, y) -> 2, Chart.unitTriangle(), 10, 10, N, 6).assertAccepted(ALPHA);
    }

    @Test
    void uniformTriangleBarycentricsLieInTheTriangleWithUniformMoments() {
        Vector3d b = new Vector3d();
        for (double u1 : edgeCases()) {
            for (double u2 : edgeCases()) {
                Warp.uniformTriangle(u1, u2, b);
                assertThat(b.x).isBetween(0.0, 1.0);
                assertThat(b.y).isBetween(0.0, 1.0);
                assertThat(b.x + b.y).isLessThanOrEqualTo(1);
            }
        }
        // Uniform on the triangle: E[bi] = 1/3, E[bi^2] = 1/6, E[b0 b1] = 1/12 (Dirichlet(1,1,1)).
        SplittableRandom random = new SplittableRandom(7);
        int n = 400_000;
        double s0 = 0, s1 = 0, s2 = 0, s00 = 0, s11 = 0, s22 = 0, s01 = 0;
        for (int i = 0; i < n; i++) {
            Warp.uniformTriangle(random.nextDouble(), random.nextDouble(), b);
            double b0 = b.x, b1 = b.y, b2 = 1 - b0 - b1;
            assertThat(b2).isGreaterThanOrEqualTo(-1e-15);
            s0 += b0;
            s1 += b1;
            s2 += b2;
            s00 += b0 * b0;
            s11 += b1 * b1;
            s22 += b2 * b2;
            s01 += b0 * b1;
        }
        // Standard deviations of the estimates: sd(bi) = 1/sqrt(18), sd(bi^2) = sqrt(1/15 - 1/36), sd(b0 b1) < 0.1.
        double tolMean = 5 / Math.sqrt(18.0 * n), tolSquare = 5 * Math.sqrt((1 / 15.0 - 1 / 36.0) / n), tolCross = 5 * 0.1 / Math.sqrt(n);
        assertThat(s0 / n).isCloseTo(1 / 3.0, within(tolMean));
        assertThat(s1 / n).isCloseTo(1 / 3.0, within(tolMean));
        assertThat(s2 / n).isCloseTo(1 / 3.0, within(tolMean));
        assertThat(s00 / n).isCloseTo(1 / 6.0, within(tolSquare));
        assertThat(s11 / n).isCloseTo(1 / 6.0, within(tolSquare));
        assertThat(s22 / n).isCloseTo(1 / 6.0, within(tolSquare));
        assertThat(s01 / n).isCloseTo(1 / 12.0, within(tolCross));
    }
}
