package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.color.MutableRgb;
import dev.strahl.scene.Camera;
import dev.strahl.image.Image;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.Sphere;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.Parallel;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.sampling.Sampler;
import dev.strahl.scene.Scene;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicIntegerArray;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** The render job's side of {@link Integrator#prepareSample}: one sample index per pass, prepared first, on the job's threads. */
class RenderJobPrepareTest {
    private static final Scene SPHERE = Scene.builder()
            .addSphere(new Vector3d(), 1, Material.diffuse("grey", Rgb.gray(0.5)))
            .camera(new Camera(new Vector3d(0, 0, 4), new Vector3d(), new Vector3d(0, 1, 0), 40))
            .build();
    private static final int CHUNKS = 37;

    /** Every pixel's radiance is the index of the prepared sample; preparing runs CHUNKS chunks. */
    private static final class Preparing implements Integrator {
        final List<Integer> prepared = new CopyOnWriteArrayList<>();
        final Set<Worker> chunkWorkers = ConcurrentHashMap.newKeySet();
        final Set<Worker> workers = ConcurrentHashMap.newKeySet();
        final AtomicIntegerArray chunkRuns = new AtomicIntegerArray(CHUNKS);
        final int failAt;
        volatile int current = -1;

        Preparing(int failAt) {
            this.failAt = failAt;
        }

        @Override
        public boolean preparesEachSample() {
            return true;
        }

        @Override
        public void prepareSample(long seed, int sampleIndex, Parallel parallel) {
            parallel.forEach(CHUNKS, (chunk, worker) -> {
                if (sampleIndex == failAt) {
                    throw new IllegalStateException("chunk failed on purpose");
                }
                chunkRuns.incrementAndGet(chunk);
                chunkWorkers.add(worker);
            });
            prepared.add(sampleIndex);
            current = sampleIndex;
        }

        @Override
        public Worker newWorker() {
            Worker w = new Worker() {
                @Override
                public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
                    out.set(current, 0, 0);
                }

                @Override
                public long rayCount() {
                    return 0;
                }
            };
            workers.add(w);
            return w;
        }
    }

    @Test
    void eachSampleIndexIsPreparedBeforeThePixelsTakeIt() throws Exception {
        Preparing integrator = new Preparing(-1);
        RenderSettings settings = RenderSettings.defaults().withSize(40, 30).withSamplesPerPixel(9).withThreads(2).withSamplesPerPass(4);
        List<Integer> passes = new CopyOnWriteArrayList<>();
        RenderListener listener = new RenderListener() {
            @Override
            public void passCompleted(int spp, Image image) {
                passes.add(spp);
            }
        };
        try (RenderJob job = RenderJob.start(SPHERE, settings, integrator, listener)) {
            Image img = job.awaitCompletion();
            // Mean of the prepared indices 0..8: every sample used the iteration prepared for it.
            assertThat(img.mean()[0]).isEqualTo(4.0);
        }
        assertThat(integrator.prepared).containsExactly(0, 1, 2, 3, 4, 5, 6, 7, 8);
        assertThat(passes).containsExactly(1, 2, 3, 4, 5, 6, 7, 8, 9);              // one sample per pass, whatever was asked
        for (int c = 0; c < CHUNKS; c++) {
            assertThat(integrator.chunkRuns.get(c)).as("chunk %d", c).isEqualTo(9);   // each chunk once per iteration
        }
        assertThat(integrator.workers).containsAll(integrator.chunkWorkers);          // chunks run with the job's workers
    }

    @Test
    void aFailingChunkFailsTheRender() throws Exception {
        Preparing integrator = new Preparing(2);
        RenderSettings settings = RenderSettings.defaults().withSize(8, 8).withSamplesPerPixel(5).withThreads(2);
        try (RenderJob job = RenderJob.start(SPHERE, settings, integrator, new RenderListener() {})) {
            assertThatThrownBy(job::awaitStats).hasMessageContaining("chunk failed on purpose");
            assertThat(job.completedSamplesPerPixel()).isEqualTo(2);
        }
    }

    @Test
    void integratorsThatPrepareNothingKeepTheirPasses() throws Exception {
        RenderSettings settings = RenderSettings.defaults().withSize(8, 8).withSamplesPerPixel(20);
        List<Integer> passes = new CopyOnWriteArrayList<>();
        try (RenderJob job = RenderJob.start(SPHERE, settings, new RenderListener() {
            @Override
            public void passCompleted(int spp, Image image) {
                passes.add(spp);
            }
        })) {
            job.awaitCompletion();
        }
        assertThat(passes).containsExactly(1, 2, 4, 8, 16, 20);
    }
}
