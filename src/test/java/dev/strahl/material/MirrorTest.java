package dev.strahl.material;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.color.MutableRgb;
import dev.strahl.image.Rgb;
import dev.strahl.testing.BsdfAssert;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** The perfect mirror: exact mirror direction, weight Ks, nothing for eval and pdf. */
class MirrorTest {
    private static final Rgb KS = new Rgb(0.9, 0.6, 0.3);
    private final Mirror mirror = new Mirror(KS);

    @Test
    void samplesTheExactMirrorDirectionWithWeightKs() {
        SplittableRandom random = new SplittableRandom(1);
        BsdfSample s = new BsdfSample();
        for (int i = 0; i < 10_000; i++) {
            Vector3d wo = BsdfAssert.direction(90 * random.nextDouble(), 360 * random.nextDouble());
            if (wo.z <= 0) {
                continue;
            }
            assertThat(mirror.sample(wo, random.nextDouble(), random.nextDouble(), random.nextDouble(), s)).isTrue();
            assertThat(s.wi.x).isEqualTo(-wo.x);
            assertThat(s.wi.y).isEqualTo(-wo.y);
            assertThat(s.wi.z).isEqualTo(wo.z);
            // The angle to the normal is kept and wo + wi is along the normal.
            Vector3d sum = new Vector3d(wo).add(s.wi);
            assertThat(Math.hypot(sum.x, sum.y)).isEqualTo(0);
            assertThat(s.weight.toRgb()).isEqualTo(KS);
            assertThat(s.pdf).isEqualTo(1);
            assertThat(s.delta).isTrue();
        }
    }

    @Test
    void evalAndPdfAreZeroForEveryDirection() {
        SplittableRandom random = new SplittableRandom(2);
        MutableRgb f = new MutableRgb(5, 5, 5);
        for (int i = 0; i < 1000; i++) {
            Vector3d wo = BsdfAssert.direction(180 * random.nextDouble(), 360 * random.nextDouble());
            Vector3d wi = BsdfAssert.direction(180 * random.nextDouble(), 360 * random.nextDouble());
            mirror.eval(wo, wi, f);
            assertThat(f.isBlack()).isTrue();
            assertThat(mirror.pdf(wo, wi)).isZero();
        }
        // Even exactly in the mirror direction: a delta has no finite value there.
        Vector3d wo = BsdfAssert.direction(30, 40);
        Vector3d wr = Fresnel.reflect(wo, new Vector3d());
        mirror.eval(wo, wr, f);
        assertThat(f.isBlack()).isTrue();
        assertThat(mirror.pdf(wo, wr)).isZero();
    }

    @Test
    void albedoIsKsAtEveryAngle() {
        for (double theta : new double[] {0, 30, 60, 89.9}) {
            BsdfAssert.Estimate e = BsdfAssert.albedoBySampling(mirror, BsdfAssert.direction(theta, 10), 1000, 3);
            assertThat(e.r()).isCloseTo(KS.r(), within(1e-15));
            assertThat(e.g()).isCloseTo(KS.g(), within(1e-15));
            assertThat(e.b()).isCloseTo(KS.b(), within(1e-15));
        }
        BsdfAssert.assertEnergyAtMostOne(new Mirror(Rgb.WHITE), 50, 100, 4);
    }

    @Test
    void samplesAreConsistent() {
        BsdfAssert.assertSampleConsistent(mirror, BsdfAssert.direction(45, 20), 10_000, 5);
    }

    @Test
    void isADeltaTwoSidedBsdf() {
        assertThat(mirror.isDelta()).isTrue();
        assertThat(mirror.isTwoSided()).isTrue();
        assertThat(mirror.withUniformHemisphere(true)).isSameAs(mirror);
    }

    @Test
    void refusesReflectanceOutsideTheUnitInterval() {
        assertThatThrownBy(() -> new Mirror(new Rgb(1.1, 0, 0))).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new Mirror(new Rgb(-0.1, 0, 0))).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void directionBelowTheSurfaceIsAbsorbed() {
        assertThat(mirror.sample(new Vector3d(0, 0.6, -0.8), 0.5, 0.5, 0.5, new BsdfSample())).isFalse();
    }
}
