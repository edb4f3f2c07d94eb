package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.geometry.Ray;
import dev.strahl.image.Image;
import dev.strahl.integrator.Integrator;
import dev.strahl.io.SceneLoader;
import dev.strahl.color.MutableRgb;
import dev.strahl.sampling.Sampler;
import dev.strahl.scene.Scene;
import dev.strahl.testing.Renders;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The teaching options {@code --accel none} and {@code --schedule stripes} change how the image
 * is computed, never the image: the same bits as the defaults. Stripes really are one stripe per
 * thread, and the idle time they cause is counted. The third, {@code --shadows off}, does change
 * the image (integrator/NoShadowsTest checks what it shows), deterministically.
 */
class TeachingOptionsTest {
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withSize(70, 50).withSamplesPerPixel(6).withSeed(42);

    @Test
    void defaultsAreTheBvhAndTiles() {
        assertThat(RenderSettings.defaults().execution().bruteForce()).isFalse();
        assertThat(RenderSettings.defaults().execution().stripes()).isFalse();
        assertThat(RenderSettings.defaults().transport().shadows()).isTrue();
        assertThat(SETTINGS.withBruteForce(true).withStripes(true).withShadows(false))
                .extracting(r -> r.execution().bruteForce(), r -> r.execution().stripes(), r -> r.transport().shadows()).containsExactly(true, true, false);
    }

    /** Without shadows the image is lighter (no light is blocked) and, like every image, the same bits on any number of threads. */
    @Test
    void withoutShadowsTheImageIsLighterAndTheSameBitsOnAnyThreadCount() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        for (IntegratorKind kind : IntegratorKind.values()) {
            RenderSettings s = SETTINGS.withIntegrator(kind).withPhotons(new PhotonParameters(5000, 0));
            Image shadows = Renders.render(scene, s.withThreads(2));
            Image none = Renders.render(scene, s.withShadows(false).withThreads(1));
            assertThat(Renders.render(scene, s.withShadows(false).withThreads(3)).rgb()).as("%s, 1 and 3 threads", kind)
                    .isEqualTo(none.rgb());
            // the Cornell Box's shadows hold 2.5 % (photon) to 5 % (path) of the green the camera sees
            assertThat(none.mean()[1]).as("%s: green without shadows against with", kind).isGreaterThan(1.015 * shadows.mean()[1]);
        }
    }

    @Test
    void bruteForceAndStripesGiveTheDefaultBits() throws Exception {
        for (String file : List.of("scenes/cornell-box.json", "scenes/cornell-sphere.json")) {
            Scene scene = SceneLoader.load(Path.of(file));
            Image reference = Renders.render(scene, SETTINGS.withThreads(2));
            assertThat(Renders.render(scene, SETTINGS.withThreads(2).withBruteForce(true)).rgb()).as(file).isEqualTo(reference.rgb());
            for (int threads : new int[] {1, 3, 7}) {              // 50 rows in 3 and 7 stripes: unequal heights
                assertThat(Renders.render(scene, SETTINGS.withThreads(threads).withStripes(true)).rgb())
                        .as("%s, %d stripes", file, threads).isEqualTo(reference.rgb());
            }
        }
    }

    /** Records the camera rays' vertical directions each worker (each thread) saw. */
    private static final class RowRecorder implements Integrator {
        final List<double[]> ranges = new ArrayList<>();

        @Override
        public synchronized Worker newWorker() {
            double[] range = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 0};
            ranges.add(range);
            return new Worker() {
                @Override
                public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
                    double y = ray.d.y / ray.d.length();
                    range[0] = Math.min(range[0], y);
                    range[1] = Math.max(range[1], y);
                    range[2]++;
                    out.set(0, 0, 0);
                }

                @Override
                public long rayCount() {
                    return 0;
                }
            };
        }
    }

    @Test
    void eachThreadRendersOnlyItsOwnStripe() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        RowRecorder rows = new RowRecorder();
        RenderSettings s = SETTINGS.withThreads(3).withStripes(true).withSize(16, 60).withSamplesPerPixel(2);
        try (RenderJob job = TestJobs.start(scene, s, rows, new RenderListener() {})) {
            RenderStats stats = job.awaitStats();
            assertThat(stats.threadIdleSeconds()).isGreaterThanOrEqualTo(0);
        }
        assertThat(rows.ranges).hasSize(3);
        List<double[]> sorted = new ArrayList<>(rows.ranges);
        sorted.sort((a, b) -> Double.compare(a[0], b[0]));
        for (int i = 0; i < 3; i++) {
            assertThat(sorted.get(i)[2]).as("samples of stripe %d", i).isEqualTo(16 * 20 * 2);
            if (i > 0) {
                // The pixel filter reaches a little past a pixel's edge: neighbouring stripes may
                // overlap by a fraction of a row, never by more than one (a stripe is 20 rows).
                double row = (sorted.get(i)[1] - sorted.get(i)[0]) / 20;
                assertThat(sorted.get(i - 1)[1] - sorted.get(i)[0]).as("overlap of stripes %d and %d", i - 1, i).isLessThan(row);
            }
        }
    }

    @Test
    void oneThreadNeverWaitsAndStripesOnUnevenWorkDo() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        try (RenderJob job = RenderJob.start(scene, SETTINGS.withThreads(1).withStripes(true))) {
            assertThat(job.awaitStats().threadIdleSeconds()).isZero();
        }
        // The Cornell Box from its camera: the top stripe (ceiling, light) and the bottom one (floor,
        // boxes) cost different amounts, so with two stripes one thread waits for the other.
        try (RenderJob job = RenderJob.start(scene, SETTINGS.withThreads(2).withStripes(true))) {
            assertThat(job.awaitStats().threadIdleSeconds()).isPositive();
        }
    }
}
