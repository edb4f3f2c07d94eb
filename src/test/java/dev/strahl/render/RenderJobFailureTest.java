package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowable;

import dev.strahl.color.MutableRgb;
import dev.strahl.scene.Camera;
import dev.strahl.film.Film;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.Sphere;
import dev.strahl.integrator.Integrator;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.sampling.Sampler;
import dev.strahl.scene.Scene;
import java.util.concurrent.atomic.AtomicInteger;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** A render thread that fails ends the job with its error, and only once every other thread has stopped too. */
class RenderJobFailureTest {
    private static final Scene SPHERE = Scene.builder()
            .addSphere(new Vector3d(), 1, Material.diffuse("grey", Rgb.gray(0.5)))
            .camera(new Camera(new Vector3d(0, 0, 4), new Vector3d(), new Vector3d(0, 1, 0), 40))
            .build();

    /** The first worker fails on its 100th sample; the others take 20 µs a sample, far from done by then. */
    private static final class FailingOnce implements Integrator {
        final AtomicInteger created = new AtomicInteger();
        final Error error;

        FailingOnce(Error error) {
            this.error = error;
        }

        @Override
        public Worker newWorker() {
            boolean fails = created.getAndIncrement() == 0;
            return new Worker() {
                int samples;

                @Override
                public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
                    if (fails && ++samples == 100) {
                        throw error;
                    }
                    long until = System.nanoTime() + 20_000;
                    while (System.nanoTime() < until) {
                        Thread.onSpinWait();
                    }
                    out.set(1, 1, 1);
                }

                @Override
                public long rayCount() {
                    return 0;
                }
            };
        }
    }

    @Test
    void theFailureIsTheRendersResultAndNoThreadWritesIntoTheFilmAfterwards() throws Exception {
        OutOfMemoryError error = new OutOfMemoryError("on purpose");
        RenderSettings settings = RenderSettings.defaults().withSize(256, 256).withSamplesPerPixel(4).withThreads(3);
        Film film;
        long samplesAtTheEnd;
        try (RenderJob job = RenderJob.start(SPHERE, settings, new FailingOnce(error), new RenderListener() {})) {
            Throwable failure = catchThrowable(job::awaitStats);
            assertThat(failure).isInstanceOf(IllegalStateException.class).hasCause(error);   // the error itself, unwrapped
            assertThat(failure.getCause()).isSameAs(error);
            film = job.film();
            samplesAtTheEnd = film.totalSamples();
        }
        assertThat(samplesAtTheEnd).as("the failure came long before the last tile").isLessThan(256L * 256 * 4);
        Thread.sleep(200);
        assertThat(film.totalSamples()).as("samples written after the job ended").isEqualTo(samplesAtTheEnd);
    }
}
