package dev.strahl.light;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.GeometryBuilder;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.image.Rgb;
import dev.strahl.math.Frame;
import dev.strahl.color.MutableRgb;
import java.util.List;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** Point, spot and directional lights: what they give a point, their power, their photons, and how the light sampler picks them. */
class PunctualLightTest {
    private static final Vector3d ORIGIN = new Vector3d();

    @Test
    void pointLightGivesIntensityOverDistanceSquared() {
        PunctualLight light = PunctualLight.point(new Vector3d(1, 2, 2), new Rgb(9, 18, 27));
        LightSample ls = new LightSample();
        assertThat(light.illuminate(ORIGIN, ls)).isTrue();
        assertThat(ls.delta).isTrue();
        assertThat(ls.infinite).isFalse();
        assertThat(ls.distance).isCloseTo(3, within(1e-12));
        assertThat(ls.wi.distance(new Vector3d(1, 2, 2).div(3))).isLessThan(1e-12);
        assertThat(ls.radiance.r).isCloseTo(1, within(1e-12));
        assertThat(ls.radiance.g).isCloseTo(2, within(1e-12));
        assertThat(ls.radiance.b).isCloseTo(3, within(1e-12));
        assertThat(light.illuminate(new Vector3d(1, 2, 2), ls)).as("at the light itself").isFalse();
    }

    @Test
    void directionalLightGivesItsIrradianceFromWhereItComes() {
        PunctualLight light = PunctualLight.directional(new Vector3d(0, -2, 0), new Rgb(1, 2, 3));
        LightSample ls = new LightSample();
        assertThat(light.illuminate(new Vector3d(5, -7, 1), ls)).isTrue();
        assertThat(ls.infinite).isTrue();
        assertThat(ls.wi.y).isEqualTo(1);
        assertThat(ls.radiance.b).isEqualTo(3);
    }

    /** glTF's formula: 1 inside the inner cone, 0 outside the outer one, the squared linear ramp in cosine between. */
    @Test
    void spotFalloffFollowsGltfAndIsZeroPastTheOuterCone() {
        double inner = Math.toRadians(20), outer = Math.toRadians(30);
        PunctualLight spot = PunctualLight.spot(new Vector3d(0, 1, 0), new Vector3d(0, -1, 0), Rgb.gray(4), inner, outer);
        assertThat(spot.falloff(Math.cos(Math.toRadians(19.99)))).isEqualTo(1);
        assertThat(spot.falloff(Math.cos(Math.toRadians(30.01)))).isZero();
        double cd = Math.cos(Math.toRadians(25));
        double t = (cd - Math.cos(outer)) / (Math.cos(inner) - Math.cos(outer));
        assertThat(spot.falloff(cd)).isCloseTo(t * t, within(1e-15));
        LightSample ls = new LightSample();
        // A point on the floor 1 below: at 29.9° lit (dimly), at 30.1° not.
        assertThat(spot.illuminate(new Vector3d(Math.tan(Math.toRadians(29.9)), 0, 0), ls)).isTrue();
        assertThat(ls.radiance.r).isGreaterThan(0);
        assertThat(spot.illuminate(new Vector3d(Math.tan(Math.toRadians(30.1)), 0, 0), ls)).isFalse();
        assertThat(spot.illuminate(new Vector3d(0, 0, 0), ls)).isTrue();
        assertThat(ls.radiance.r).isCloseTo(4, within(1e-12));
        PunctualLight hard = PunctualLight.spot(ORIGIN, new Vector3d(0, 0, 1), Rgb.WHITE, 0.3, 0.3);
        assertThat(hard.falloff(Math.cos(0.2999))).isEqualTo(1);
        assertThat(hard.falloff(Math.cos(0.3001))).isZero();
    }

    /** The spot's power formula against the falloff integrated over the sphere numerically. */
    @Test
    void spotPowerIsTheFalloffIntegratedOverTheSphere() {
        for (double[] cone : new double[][] {{0, 45}, {20, 30}, {10, 90}, {25, 25}}) {
            PunctualLight spot = PunctualLight.spot(ORIGIN, new Vector3d(0, 0, 1), Rgb.gray(2), Math.toRadians(cone[0]),
                    Math.toRadians(cone[1]));
            int n = 2_000_000;
            double sum = 0;
            for (int i = 0; i < n; i++) {
                double z = -1 + 2 * (i + 0.5) / n;        // ∫ a dω = 2π ∫ a(z) dz for a rotationally symmetric a
                sum += spot.falloff(z);
            }
            double numeric = 2 * Math.PI * 2 * sum * 2.0 / n;
            assertThat(spot.power(1)).as("cone %s", java.util.Arrays.toString(cone)).isCloseTo(numeric, within(1e-4 * numeric));
        }
        assertThat(PunctualLight.point(ORIGIN, new Rgb(1, 2, 3)).power(7)).isCloseTo(8 * Math.PI, within(1e-12));
        assertThat(PunctualLight.directional(new Vector3d(1, 0, 0), Rgb.gray(2)).power(3)).isCloseTo(18 * Math.PI, within(1e-12));
    }

    /** The mean photon flux is the light's power per channel: emission is an unbiased estimator of it. */
    @Test
    void photonsCarryTheLightsPowerOnAverage() {
        PunctualLight[] lights = {
            PunctualLight.point(new Vector3d(1, 2, 3), new Rgb(1, 2, 3)),
            PunctualLight.spot(new Vector3d(1, 2, 3), new Vector3d(1, -1, 0), new Rgb(1, 2, 3), Math.toRadians(15), Math.toRadians(40)),
            PunctualLight.directional(new Vector3d(1, -1, 0.5), new Rgb(1, 2, 3)),
        };
        Vector3d center = new Vector3d(0.5, 0, 0);
        double radius = 2;
        for (PunctualLight light : lights) {
            SplittableRandom random = new SplittableRandom(7);
            Ray ray = new Ray();
            MutableRgb flux = new MutableRgb();
            Frame frame = new Frame();
            Vector3d local = new Vector3d();
            double sum = 0;
            int n = 400_000;
            for (int i = 0; i < n; i++) {
                light.emit(random.nextDouble(), random.nextDouble(), random.nextDouble(), random.nextDouble(), center, radius, frame, local,
                        ray, flux);
                assertThat(ray.d.length()).isCloseTo(1, within(1e-9));
                if (light.type() == PunctualLight.Type.DIRECTIONAL) {
                    // From the disc across the bounding sphere, on the side the light comes from.
                    Vector3d toStart = new Vector3d(ray.o).sub(center);
                    assertThat(toStart.dot(ray.d)).isCloseTo(-radius, within(1e-9));
                    assertThat(toStart.fma(radius, ray.d).length()).isLessThanOrEqualTo(radius * (1 + 1e-9));
                } else if (light.type() == PunctualLight.Type.SPOT) {
                    assertThat(ray.d.dot(new Vector3d(1, -1, 0).normalize())).isGreaterThanOrEqualTo(Math.cos(Math.toRadians(40)) - 1e-12);
                }
                sum += flux.g;
            }
            double power = light.power(radius) * 2 / 2;   // mean over channels is 2, as the green channel
            assertThat(sum / n).as("%s", light.type()).isCloseTo(power, within(0.01 * power));
        }
    }

    @Test
    void badParametersAreRefused() {
        assertThatThrownBy(() -> PunctualLight.spot(ORIGIN, new Vector3d(0, 0, 1), Rgb.WHITE, 0.5, 0.4)).hasMessageContaining("inner");
        assertThatThrownBy(() -> PunctualLight.spot(ORIGIN, new Vector3d(0, 0, 1), Rgb.WHITE, 0, 2)).hasMessageContaining("90");
        assertThatThrownBy(() -> PunctualLight.spot(ORIGIN, new Vector3d(0, 0, 1), Rgb.WHITE, 0, 0)).hasMessageContaining("outer");
        assertThatThrownBy(() -> PunctualLight.directional(new Vector3d(), Rgb.WHITE)).hasMessageContaining("non-zero");
        assertThatThrownBy(() -> PunctualLight.point(new Vector3d(Double.NaN, 0, 0), Rgb.WHITE)).hasMessageContaining("finite");
        assertThatThrownBy(() -> PunctualLight.point(ORIGIN, new Rgb(1, -1, 1))).hasMessageContaining("negative");
    }

    private static Geometry unitQuad() {
        GeometryBuilder b = new GeometryBuilder();
        b.addMesh(new float[] {0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1}, new int[] {0, 2, 1, 0, 3, 2}, null, null, new int[] {0, 0}, new byte[2]);
        return b.build();
    }

    /**
     * An area light of flux π·1·Le = π (Le 1, area 1) and a point light of power 4π·1: the point
     * light gets 4/5 of the samples, each its choice probability as pdf; the area light's density
     * drops to 1/5 of what it is alone.
     */
    @Test
    void lightsAreChosenByPowerAndTheAreaLightsDensityShrinksByItsShare() {
        Geometry quad = unitQuad();
        Rgb[] emission = {Rgb.WHITE};
        LightSampler alone = new LightSampler(quad, Emission.constants(emission), Environment.BLACK, List.of()).byPower();
        LightSampler both = new LightSampler(quad, Emission.constants(emission), Environment.BLACK,
                List.of(PunctualLight.point(new Vector3d(0.5, 2, 0.5), Rgb.WHITE))).byPower();
        assertThat(both.pdf(new Vector3d(), null, 0, 2, 0.5)).isCloseTo(alone.pdf(new Vector3d(), null, 0, 2, 0.5) / 5, within(1e-12));
        SurfacePoint sp = new SurfacePoint();
        LightSample ls = new LightSample();
        Vector3d ref = new Vector3d(0.3, 1, 0.4);
        int delta = 0, n = 100_000;
        SplittableRandom random = new SplittableRandom(1);
        for (int i = 0; i < n; i++) {
            if (both.sample(ref, null, random.nextDouble(), random.nextDouble(), random.nextDouble(), false, sp, ls) && ls.delta) {
                delta++;
                assertThat(ls.pdf).isCloseTo(0.8, within(1e-12));
            }
        }
        assertThat(delta / (double) n).isCloseTo(0.8, within(0.01));
        assertThat(both.isEmpty()).isFalse();
        assertThat(new LightSampler(new GeometryBuilder().build(), new Emission[0], Environment.BLACK,
                List.of(PunctualLight.directional(new Vector3d(0, -1, 0), Rgb.WHITE))).isEmpty()).isFalse();
    }

    /** With an environment map too, the environment keeps its half; punctual and area lights share the other half (by power here). */
    @Test
    void anEnvironmentMapKeepsItsHalf() {
        Geometry quad = unitQuad();
        Environment env = Environment.map(2, 2, new float[] {1, 1, 1, 2, 2, 2, 1, 1, 1, 2, 2, 2}, 1, 0, "test");
        LightSampler s = new LightSampler(quad, Emission.constants(Rgb.WHITE), env, List.of(PunctualLight.point(new Vector3d(0, 3, 0), Rgb.WHITE))).byPower();
        SurfacePoint sp = new SurfacePoint();
        LightSample ls = new LightSample();
        int envCount = 0, pointCount = 0, n = 100_000;
        SplittableRandom random = new SplittableRandom(2);
        for (int i = 0; i < n; i++) {
            if (s.sample(new Vector3d(0.5, 1, 0.5), null, random.nextDouble(), random.nextDouble(), random.nextDouble(), false, sp, ls)) {
                envCount += ls.infinite && !ls.delta ? 1 : 0;
                pointCount += ls.delta ? 1 : 0;
            }
        }
        assertThat(envCount / (double) n).isCloseTo(0.5, within(0.01));
        assertThat(pointCount / (double) n).isCloseTo(0.4, within(0.01));
    }
}
