package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.geometry.Ray;
import dev.strahl.image.Image;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.Parallel;
import dev.strahl.io.SceneLoader;
import dev.strahl.color.MutableRgb;
import dev.strahl.sampling.Sampler;
import dev.strahl.scene.Scene;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * {@link RenderJob#snapshotBuffers()}: the buffers of exactly the last completed pass (never half
 * of the next), from a listener, from another thread while the job runs, during a pause begun at
 * the end of a pass (and not during one begun in the middle of a pass), and after the render,
 * where they are those of {@link RenderJob#awaitBuffers()}; and taking them changes no bit of the
 * render.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class SnapshotBuffersTest {
    static Scene cornell;

    @BeforeAll
    static void load() throws Exception {
        cornell = SceneLoader.load(Path.of("scenes", "cornell-box.json"));
    }

    static RenderSettings settings(int size, int spp) {
        return RenderSettings.defaults().withSize(size, size).withSamplesPerPixel(spp).withSeed(3).withThreads(2)
                .withAovs(EnumSet.allOf(Aov.class));
    }

    /** A listener that takes the buffers at the end of every pass (the job is set once it has started). */
    static final class Taking implements RenderListener {
        final CountDownLatch started = new CountDownLatch(1);
        final AtomicReference<RenderJob> job = new AtomicReference<>();
        final Map<Integer, RenderBuffers> bySpp = new ConcurrentHashMap<>();
        final Map<Integer, Image> images = new ConcurrentHashMap<>();
        final List<Integer> spps = new java.util.concurrent.CopyOnWriteArrayList<>();
        volatile long sleepMillis;

        @Override
        public void passFinished(RenderStats soFar, Image image) {
            try {
                started.await();
                Optional<RenderBuffers> b = job.get().snapshotBuffers();
                assertThat(b).as("in a listener the film holds the pass").isPresent();
                assertThat(b.get().color()).isSameAs(image);
                bySpp.put(soFar.samplesPerPixel(), b.get());
                images.put(soFar.samplesPerPixel(), image);
                spps.add(soFar.samplesPerPixel());
                Thread.sleep(sleepMillis);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        RenderJob start(Scene scene, RenderSettings s) {
            RenderJob j = RenderJob.start(scene, s, this);
            job.set(j);
            started.countDown();
            return j;
        }
    }

    static void assertSame(RenderBuffers actual, RenderBuffers expected) {
        assertThat(actual.color()).isEqualTo(expected.color());
        assertThat(actual.variance()).isEqualTo(expected.variance());
        assertThat(actual.albedo()).isEqualTo(expected.albedo());
        assertThat(actual.normal()).isEqualTo(expected.normal());
        assertThat(actual.depth()).isEqualTo(expected.depth());
    }

    @Test
    void fromAListenerEveryPassHasItsBuffersAndTheLastAreThoseOfAwaitBuffers() throws Exception {
        Taking taking = new Taking();
        RenderBuffers end;
        RenderBuffers after;
        try (RenderJob job = taking.start(cornell, settings(40, 12))) {
            end = job.awaitBuffers();
            after = job.snapshotBuffers().orElseThrow();
        }
        assertThat(taking.spps).as("passes of 1, 1, 2, 4, 4 (to 12) spp").containsExactly(1, 2, 4, 8, 12);
        for (RenderBuffers b : taking.bySpp.values()) {
            assertThat(b.albedo()).isNotNull();
            assertThat(b.normal()).isNotNull();
            assertThat(b.depth()).isNotNull();
        }
        assertSame(taking.bySpp.get(12), end);
        assertSame(after, end);
        assertThat(taking.bySpp.get(4).variance()).as("a pass's own variance").isNotEqualTo(end.variance());
        assertThat(taking.bySpp.get(4).albedo()).as("the albedo of 4 samples per pixel").isNotEqualTo(end.albedo());

        // Taking the buffers changes nothing in the render
        try (RenderJob plain = RenderJob.start(cornell, settings(40, 12))) {
            assertSame(plain.awaitBuffers(), end);
        }
    }

    @Test
    void withoutFeatureBuffersOnlyTheImageAndItsVarianceAreThere() throws Exception {
        try (RenderJob job = RenderJob.start(cornell, settings(16, 4).withAovs(EnumSet.noneOf(Aov.class)))) {
            RenderBuffers end = job.awaitBuffers();
            RenderBuffers b = job.snapshotBuffers().orElseThrow();
            assertSame(b, end);
            assertThat(b.albedo()).isNull();
            assertThat(b.normal()).isNull();
            assertThat(b.depth()).isNull();
            assertThat(b.variance().mean()[0]).as("8 samples per pixel have a variance").isPositive();
        }
    }

    /**
     * A thread that asks all the time while the job renders 1-spp passes gets, whenever it gets
     * any, the buffers of one whole pass: bit for bit those the listener took at its end.
     */
    @Test
    void fromAnotherThreadWhileRenderingTheBuffersAreAlwaysOneWholePass() throws Exception {
        Taking taking = new Taking();
        taking.sleepMillis = 3;                // keeps each pass's end open a little, so the other thread meets some
        List<RenderBuffers> seen = new ArrayList<>();
        int empty = 0;
        try (RenderJob job = taking.start(cornell, settings(32, 12).withSamplesPerPass(1))) {
            while (!job.isDone()) {
                Optional<RenderBuffers> b = job.snapshotBuffers();
                if (b.isPresent()) {
                    seen.add(b.get());
                } else {
                    empty++;
                }
                Thread.sleep(0, 300_000);
            }
            job.awaitStats();
        }
        assertThat(empty).as("mostly a pass is being rendered").isPositive();
        assertThat(seen).as("some asks met the end of a pass").isNotEmpty();
        for (RenderBuffers b : seen) {
            Integer spp = taking.images.entrySet().stream().filter(e -> e.getValue().equals(b.color()))
                    .map(Map.Entry::getKey).findFirst().orElse(null);
            assertThat(spp).as("the image is one pass's").isNotNull();
            assertSame(b, taking.bySpp.get(spp));
        }
    }

    /**
     * Paused from a listener, the job keeps the film at that pass and the buffers can be had from
     * any thread; paused in the middle of a pass, there are none until it goes on.
     */
    @Test
    void aPauseAtTheEndOfAPassKeepsItsBuffersAndOneInTheMiddleHasNone() throws Exception {
        Gated integrator = new Gated();
        CountDownLatch pausedAtPass2 = new CountDownLatch(1);
        AtomicReference<RenderJob> ref = new AtomicReference<>();
        CountDownLatch started = new CountDownLatch(1);
        Map<Integer, Image> images = new ConcurrentHashMap<>();
        RenderListener listener = new RenderListener() {
            @Override
            public void passCompleted(int spp, Image image) {
                try {
                    started.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                images.put(spp, image);
                if (spp == 2) {
                    ref.get().pause();
                    pausedAtPass2.countDown();
                }
            }
        };
        RenderSettings s = RenderSettings.defaults().withSize(8, 8).withSamplesPerPixel(4).withThreads(1)
                .withAovs(EnumSet.allOf(Aov.class));
        try (RenderJob job = TestJobs.start(cornell, s, integrator, listener)) {
            ref.set(job);
            started.countDown();
            assertThat(pausedAtPass2.await(10, TimeUnit.SECONDS)).isTrue();
            Thread.sleep(50);                                       // the next pass would have begun by now
            RenderBuffers held = job.snapshotBuffers().orElseThrow();
            assertThat(held.color()).isSameAs(images.get(2)).isEqualTo(job.snapshot());
            assertThat(held.color().get(0, 0, 0)).as("the mean of sample indices 0 and 1").isEqualTo(0.5f);

            integrator.gateAt = 2;                                  // pass 3 stops in its first pixel
            job.resume();
            assertThat(integrator.waiting.await(10, TimeUnit.SECONDS)).isTrue();
            job.pause();                                            // in the middle of pass 3
            assertThat(job.snapshotBuffers()).as("paused in the middle of a pass").isEmpty();
            integrator.gate.countDown();
            Thread.sleep(50);                                       // the worker ends its tile and holds
            assertThat(job.snapshotBuffers()).isEmpty();
            assertThat(job.isDone()).isFalse();
            job.resume();
            RenderBuffers end = job.awaitBuffers();
            assertSame(job.snapshotBuffers().orElseThrow(), end);
            assertThat(end.color().get(0, 0, 0)).as("(0 + 1 + 2 + 3) / 4").isEqualTo(1.5f);
            assertThat(end.albedo()).isNotNull();
        }
    }

    /** Each sample's radiance is its sample index; sample index {@link #gateAt} waits for the gate. */
    static final class Gated implements Integrator {
        volatile int current = -1;
        volatile int gateAt = -1;
        final CountDownLatch waiting = new CountDownLatch(1);
        final CountDownLatch gate = new CountDownLatch(1);

        @Override
        public boolean preparesEachSample() {
            return true;
        }

        @Override
        public void prepareSample(long seed, int sampleIndex, Parallel parallel) {
            current = sampleIndex;
        }

        @Override
        public Worker newWorker() {
            return new Worker() {
                @Override
                public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
                    if (current == gateAt) {
                        waiting.countDown();
                        try {
                            gate.await();
                        } catch (InterruptedException e) {
                            Thread.currentThread().interrupt();
                        }
                    }
                    out.set(current, current, current);
                }

                @Override
                public long rayCount() {
                    return 0;
                }
            };
        }
    }
}
