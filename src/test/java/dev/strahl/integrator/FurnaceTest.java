package dev.strahl.integrator;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.scene.TestScenes;
import dev.strahl.scene.Camera;
import dev.strahl.image.Image;
import dev.strahl.geometry.Sphere;
import dev.strahl.material.Lambert;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.scene.Scene;
import dev.strahl.testing.Meshes;
import dev.strahl.testing.Renders;
import org.joml.Vector3d;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * White furnace tests: scenes whose radiance is known in closed form. Inside a closed surface of
 * albedo ρ that emits Le everywhere, every path segment adds ρ times the previous one, so the
 * radiance is Le·(1 + ρ + … + ρ^(d−1)) for maxDepth d and Le/(1−ρ) unbounded.
 */
class FurnaceTest {
    private static final double LE = 1.0;

    private static Scene closedFurnace(double albedo) {
        Material wall = TestScenes.material("furnace", new Lambert(Rgb.gray(albedo)), Rgb.gray(LE));
        return Scene.builder()
                .addMesh(Meshes.icosphere(2, 1.0, true), wall)
                .camera(new Camera(new Vector3d(0.1, -0.2, 0.05), new Vector3d(0.3, 0.4, -1), new Vector3d(0, 1, 0), 60))
                .build();
    }

    private static RenderSettings settings(int maxDepth, int spp) {
        return RenderSettings.defaults().withSize(24, 24).withSamplesPerPixel(spp).withMaxDepth(maxDepth).withSeed(3);
    }

    @ParameterizedTest(name = "albedo {0}, maxDepth {1}")
    @CsvSource({"0.5, 1", "0.5, 2", "0.5, 5", "0.8, 3", "0.5, -1", "0.8, -1", "0.95, -1"})
    void closedEmittingSphereGivesGeometricSeries(double albedo, int maxDepth) {
        Image img = Renders.render(closedFurnace(albedo), settings(maxDepth, 64));
        double expected = maxDepth < 0 ? LE / (1 - albedo) : LE * (1 - Math.pow(albedo, maxDepth)) / (1 - albedo);
        for (int c = 0; c < 3; c++) {
            assertThat(img.mean()[c]).as("channel %d", c).isCloseTo(expected, within(0.01 * expected));
        }
    }

    /**
     * 256 spp: at 64 the image means of seeds 3..6 spread ±0.035 around 5 (by the light tree as by
     * power: 4.945, 5.008, 5.030, 4.997 and 4.960, 5.008, 5.025, 4.997), too close to the 1 % bound.
     */
    @Test
    void uniformHemisphereSamplingConvergesToTheSameFurnace() {
        Scene scene = closedFurnace(0.8);
        Image img = Renders.render(scene, settings(-1, 256).withHemisphere(HemisphereSampling.UNIFORM));
        assertThat(img.mean()[1]).isCloseTo(5.0, within(0.05));
    }

    @Test
    void backFaceCullingDoesNotChangeTheFurnace() {
        // The furnace faces inwards, so it is not an outward closed mesh: culling must not apply.
        Image img = Renders.render(closedFurnace(0.5), settings(-1, 32).withCullBackFaces(true));
        assertThat(img.mean()[0]).isCloseTo(2.0, within(0.02));
    }

    /** A convex diffuse sphere in a uniform environment: every reflected ray escapes, so L = ρ·Lenv exactly. */
    @ParameterizedTest(name = "{0} hemisphere sampling")
    @CsvSource({"COSINE", "UNIFORM"})
    void convexSphereInUniformEnvironmentReflectsAlbedoTimesEnvironment(HemisphereSampling sampling) {
        double albedo = 0.6;
        Scene scene = Scene.builder()
                // Radius 0.9: seen from 3 units under 17.5°, inside every centre pixel and clear of the
                // corner pixel, whose inner corner lies at 19.2° (a unit sphere, at 19.5°, reached into
                // it: a stratified sampler, covering the pixel evenly, found that sliver).
                .addSphere(new Vector3d(0, 0, 0), 0.9, Material.diffuse("grey", Rgb.gray(albedo)))
                .environment(new Rgb(1, 2, 0.5))
                .camera(new Camera(new Vector3d(0, 0, 3), new Vector3d(0, 0, 0), new Vector3d(0, 1, 0), 30))
                .build();
        Image img = Renders.render(scene, settings(-1, 16).withHemisphere(sampling));
        // The centre pixel sees the sphere, a corner pixel the environment.
        for (int c = 0; c < 3; c++) {
            double env = c == 0 ? 1 : c == 1 ? 2 : 0.5;
            double centre = 0;
            for (int y = 10; y < 14; y++) {
                for (int x = 10; x < 14; x++) {
                    centre += img.get(x, y, c) / 16.0;
                }
            }
            double tolerance = sampling == HemisphereSampling.COSINE ? 1e-6 : 0.03;   // float film: 1e-7 relative
            assertThat(centre).isCloseTo(albedo * env, within(tolerance * env));
            assertThat((double) img.get(0, 0, c)).isCloseTo(env, within(1e-6));
        }
    }
}
