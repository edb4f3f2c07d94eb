package dev.strahl.material;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.color.MutableRgb;
import dev.strahl.image.Rgb;
import dev.strahl.testing.BsdfAssert;
import java.lang.management.ManagementFactory;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Smooth glass: Snell's law on both sides, reflection chosen with probability F, total internal
 * reflection, energy conservation with the radiance scaling 1/η'² undone, reversibility.
 */
class DielectricTest {
    private static final double ETA = 1.5;
    private final Dielectric glass = new Dielectric(ETA);

    /** A unit direction at θ degrees from +z (or from −z if {@code inside}), azimuth φ degrees. */
    private static Vector3d direction(double thetaDegrees, double phiDegrees, boolean inside) {
        Vector3d w = BsdfAssert.direction(thetaDegrees, phiDegrees);
        if (inside) {
            w.z = -w.z;
        }
        return w;
    }

    /** uc just below 1: refraction unless totally reflected (uc < F = 1). */
    private static final double REFRACT = Math.nextDown(1.0);
    /** uc = 0: reflection whenever F > 0. */
    private static final double REFLECT = 0;

    @Test
    void refractionObeysSnellsLawFromBothSides() {
        BsdfSample s = new BsdfSample();
        for (boolean inside : new boolean[] {false, true}) {
            double n1 = inside ? ETA : 1, n2 = inside ? 1 : ETA;
            for (double theta : new double[] {0, 10, 25, 40, 41.5, 60, 75, 89}) {
                Vector3d wo = direction(theta, 33, inside);
                double sinO = Math.sin(Math.toRadians(theta));
                if (n1 * sinO / n2 >= 1) {
                    continue;                      // beyond the critical angle: see the TIR test
                }
                assertThat(glass.sample(wo, REFRACT, 0.5, 0.5, s)).isTrue();
                double sinI = Math.hypot(s.wi.x, s.wi.y);
                String where = (inside ? "from inside" : "from outside") + ", θ = " + theta;
                assertThat(n2 * sinI).as(where).isCloseTo(n1 * sinO, within(1e-14));
                assertThat(s.wi.length()).isCloseTo(1, within(1e-14));
                assertThat(s.wi.z * wo.z).as("transmitted to the other side, " + where).isLessThan(0);
                assertThat(s.wi.x * wo.y - s.wi.y * wo.x).as("plane of incidence").isCloseTo(0, within(1e-14));
                assertThat(s.delta).isTrue();
                double etaRelative = n2 / n1;
                assertThat(s.weight.g).as("radiance scaling 1/η'²").isCloseTo(1 / (etaRelative * etaRelative), within(1e-15));
                assertThat(s.pdf).isCloseTo(1 - Fresnel.dielectric(wo.z, ETA), within(1e-15));
            }
        }
    }

    @Test
    void reflectionIsTheMirrorDirectionWithWeightOne() {
        BsdfSample s = new BsdfSample();
        for (boolean inside : new boolean[] {false, true}) {
            Vector3d wo = direction(30, 100, inside);
            assertThat(glass.sample(wo, REFLECT, 0.5, 0.5, s)).isTrue();
            assertThat(s.wi).isEqualTo(new Vector3d(-wo.x, -wo.y, wo.z));
            assertThat(s.weight.toRgb()).isEqualTo(Rgb.WHITE);
            assertThat(s.pdf).isCloseTo(Fresnel.dielectric(wo.z, ETA), within(1e-15));
            assertThat(s.delta).isTrue();
        }
    }

    /** Over many uniform uc the fraction of reflections is F(θ), within 5 binomial standard deviations. */
    @ParameterizedTest
    @ValueSource(doubles = {0, 30, 56.3, 70, 85, 89.5})
    void reflectsWithProbabilityFresnelAndRefractsOtherwise(double theta) {
        SplittableRandom random = new SplittableRandom(7);
        BsdfSample s = new BsdfSample();
        int n = 400_000;
        for (boolean inside : new boolean[] {false, true}) {
            Vector3d wo = direction(inside ? Math.min(theta, 40) : theta, 15, inside);
            double f = Fresnel.dielectric(wo.z, ETA);
            int reflected = 0;
            for (int i = 0; i < n; i++) {
                assertThat(glass.sample(wo, random.nextDouble(), 0.5, 0.5, s)).isTrue();
                if (s.wi.z * wo.z > 0) {
                    reflected++;
                    assertThat(s.pdf).isEqualTo(f);
                } else {
                    assertThat(s.pdf).isEqualTo(1 - f);
                }
            }
            double sigma = Math.sqrt(n * f * (1 - f));
            assertThat((double) reflected).as("reflections for wo = %s, F = %s", wo, f)
                    .isCloseTo(n * f, within(5 * sigma + 1));
        }
    }

    @Test
    void totalInternalReflectionBeyondTheCriticalAngleAlwaysReflects() {
        double critical = Math.toDegrees(Math.asin(1 / ETA));    // 41.81°
        BsdfSample s = new BsdfSample();
        SplittableRandom random = new SplittableRandom(8);
        for (double theta = critical + 0.01; theta < 90; theta += 2) {
            Vector3d wo = direction(theta, 200, true);
            for (int i = 0; i < 1000; i++) {
                double uc = i == 0 ? REFRACT : random.nextDouble();
                assertThat(glass.sample(wo, uc, 0.5, 0.5, s)).isTrue();
                assertThat(s.wi).isEqualTo(new Vector3d(-wo.x, -wo.y, wo.z));
                assertThat(s.weight.toRgb()).isEqualTo(Rgb.WHITE);
                assertThat(s.pdf).isEqualTo(1);
            }
        }
        // Just inside the critical angle some light escapes.
        assertThat(glass.sample(direction(critical - 0.5, 200, true), REFRACT, 0.5, 0.5, s)).isTrue();
        assertThat(s.wi.z).isGreaterThan(0);
    }

    /**
     * White furnace for glass: reflection and transmission together carry all the energy. With the
     * radiance factor 1/η'² undone, every sample weight is 1, so the expected weight
     * F·1 + (1 − F)·1 is exactly 1, from either side and at every angle.
     */
    @Test
    void reflectionPlusTransmissionConserveEnergy() {
        SplittableRandom random = new SplittableRandom(9);
        BsdfSample s = new BsdfSample();
        for (boolean inside : new boolean[] {false, true}) {
            for (double theta = 0; theta < 90; theta += 5) {
                Vector3d wo = direction(theta, 60, inside);
                double sum = 0;
                int n = 20_000;
                for (int i = 0; i < n; i++) {
                    assertThat(glass.sample(wo, random.nextDouble(), random.nextDouble(), random.nextDouble(), s)).isTrue();
                    boolean transmitted = s.wi.z * wo.z < 0;
                    double etaRelative = Fresnel.relativeEta(wo.z, ETA);
                    sum += transmitted ? s.weight.g * etaRelative * etaRelative : s.weight.g;
                }
                assertThat(sum / n).as("albedo at θ = %s, inside = %s", theta, inside).isCloseTo(1, within(1e-12));
            }
        }
    }

    @Test
    void refractingInThenOutReturnsTheOriginalDirection() {
        BsdfSample in = new BsdfSample(), out = new BsdfSample();
        for (double theta = 0; theta < 90; theta += 3) {
            Vector3d wo = direction(theta, 123, false);
            assertThat(glass.sample(wo, REFRACT, 0.5, 0.5, in)).isTrue();
            assertThat(in.wi.z).isLessThan(0);
            // The path continues inside towards in.wi; seen from there wo' = in.wi, from inside.
            assertThat(glass.sample(in.wi, REFRACT, 0.5, 0.5, out)).isTrue();
            assertThat(out.wi.distance(wo)).as("θ = %s", theta).isLessThan(1e-14);
            assertThat(in.weight.g * out.weight.g).as("the radiance factors cancel").isCloseTo(1, within(1e-14));
        }
    }

    @Test
    void evalAndPdfAreZeroAndTheBsdfIsOneSidedDelta() {
        MutableRgb f = new MutableRgb(1, 1, 1);
        glass.eval(direction(20, 0, false), direction(30, 180, true), f);
        assertThat(f.isBlack()).isTrue();
        assertThat(glass.pdf(direction(20, 0, false), direction(20, 180, false))).isZero();
        assertThat(glass.isDelta()).isTrue();
        assertThat(glass.isTwoSided()).isFalse();
        BsdfAssert.assertSampleConsistent(glass, direction(35, 10, false), 10_000, 10);
        BsdfAssert.assertSampleConsistent(glass, direction(35, 10, true), 10_000, 11);
    }

    @Test
    void refusesNonPositiveIndex() {
        assertThatThrownBy(() -> new Dielectric(0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new Dielectric(Double.NaN)).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void samplingAllocatesNothing() {
        var mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        BsdfSample s = new BsdfSample();
        Vector3d wo = direction(30, 10, false);
        Vector3d woInside = direction(60, 10, true);
        for (int i = 0; i < 20_000; i++) {               // warm up
            glass.sample(wo, (i % 100) / 100.0, 0.5, 0.5, s);
        }
        long before = mx.getCurrentThreadAllocatedBytes();
        for (int i = 0; i < 10_000; i++) {
            glass.sample(wo, (i % 100) / 100.0, 0.5, 0.5, s);
            glass.sample(woInside, (i % 100) / 100.0, 0.5, 0.5, s);
        }
        assertThat(mx.getCurrentThreadAllocatedBytes() - before).isLessThan(1024);
    }
}
