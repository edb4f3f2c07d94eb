package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.color.MutableRgb;
import dev.strahl.scene.Camera;
import dev.strahl.film.Film;
import dev.strahl.image.Image;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.Sphere;
import dev.strahl.integrator.Integrator;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.sampling.Sampler;
import dev.strahl.scene.Scene;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** NaN and infinite radiance never reaches the film: such samples count as black and are counted. */
class InvalidSampleTest {
    private static final Scene SPHERE = Scene.builder()
            .addSphere(new Vector3d(), 1, Material.diffuse("grey", Rgb.gray(0.5)))
            .camera(new Camera(new Vector3d(0, 0, 4), new Vector3d(), new Vector3d(0, 1, 0), 40))
            .build();

    /** 0.5 everywhere, except NaN in one channel in the left half of column 0 and +∞ in the right half of column 1. */
    private static final Integrator POISONED = () -> new Integrator.Worker() {
        @Override
        public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
            out.set(0.5, 0.5, 0.5);
            double px = ray.d.x;                     // the camera looks down -z: x of the direction grows to the right
            if (px < -0.2) {
                out.set(0.5, Double.NaN, 0.5);
            } else if (px > 0.2) {
                out.set(Double.POSITIVE_INFINITY, 0.5, 0.5);
            }
        }

        @Override
        public long rayCount() {
            return 0;
        }
    };

    @Test
    void nanAndInfiniteSamplesAreCountedAndAddedAsBlack() throws Exception {
        RenderSettings settings = RenderSettings.defaults().withSize(40, 10).withSamplesPerPixel(8);
        try (RenderJob job = RenderJob.start(SPHERE, settings, POISONED, new RenderListener() {})) {
            Film film = TestJobs.awaitFilm(job);
            RenderStats stats = job.awaitStats();
            Image img = film.toImage();
            long expectedBad = 0;
            for (int y = 0; y < 10; y++) {
                for (int x = 0; x < 40; x++) {
                    for (int c = 0; c < 3; c++) {
                        assertThat(Float.isFinite(img.get(x, y, c))).as("pixel %d,%d", x, y).isTrue();
                    }
                    float r = img.get(x, y, 0);
                    assertThat(r).isBetween(0f, 0.5f);
                    expectedBad += Math.round((0.5 - r) / 0.5 * 8);   // each bad sample lowers the mean by 0.5/8
                }
            }
            assertThat(stats.invalidSamples()).isEqualTo(expectedBad).isPositive();
            assertThat(job.invalidSamples()).isEqualTo(stats.invalidSamples());
            assertThat(stats.invalidSamples()).isLessThan(40 * 10 * 8);
        }
    }
}
