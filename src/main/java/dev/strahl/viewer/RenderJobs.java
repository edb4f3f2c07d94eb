package dev.strahl.viewer;

import dev.strahl.image.Image;
import dev.strahl.render.RenderBuffers;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.scene.Scene;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/**
 * What {@link RenderController} runs: render jobs, started by a {@link Starter}, and a
 * {@link Scheduler} for delayed tasks; outside tests, real {@link RenderJob}s and a timer thread.
 */
final class RenderJobs {
    private RenderJobs() {
    }

    /** A running render as the controller sees it: a {@link RenderJob}, or a stand-in in tests. */
    interface Job {
        void cancel();

        void pause();

        void resume();

        long samplesDone();

        /** {@link RenderJob#snapshotBuffers()}: the last pass's buffers while the film holds exactly that pass. */
        Optional<RenderBuffers> snapshotBuffers();
    }

    /** The buffers of a frame's pass, copied when asked for: present while the job's film still holds that pass. */
    interface Buffers {
        Optional<RenderBuffers> get();
    }

    /** Starts a job that reports its passes to {@code listener}. */
    interface Starter {
        Job start(Scene scene, RenderSettings settings, RenderListener listener);
    }

    /** Runs a task after a delay on some other thread; the returned handle cancels it. */
    interface Scheduler {
        Runnable schedule(Runnable task, long delayMillis);

        void shutdown();
    }

    /** The preview's film is this many times smaller in each axis. */
    static final int PREVIEW_DIVISOR = 4;

    /** A preview's film edge for a full-resolution edge of {@code size}: a quarter, at least 1. */
    static int previewSize(int size) {
        return Math.max(1, Math.round(size / (float) PREVIEW_DIVISOR));
    }

    /**
     * The settings of a job the controller starts with the viewer's {@code settings}: passes of one sample per pixel
     * without end (the controller holds it), no time limit; a preview at a quarter of the size, never denoised and
     * never adaptive.
     */
    static RenderSettings settings(RenderSettings settings, boolean preview) {
        RenderSettings s = settings.withTimeLimit(java.time.Duration.ZERO);
        if (preview) {
            s = s.withSize(previewSize(s.output().width()), previewSize(s.output().height())).withAovs(Set.of()).withNoiseThreshold(0);
        }
        return s.withSamplesPerPixel(Integer.MAX_VALUE).withSamplesPerPass(1);
    }

    /** What a job of generation {@code g} reports after each pass: its samples per pixel and image. */
    interface PassReport {
        void pass(long g, int samplesPerPixel, Image image);
    }

    /** What a job of generation {@code g} reports of its noise threshold: its figures, and whether it ended by itself. */
    interface ConvergenceReport {
        void converged(long g, RenderStats stats, boolean ended);
    }

    /**
     * The listener of job {@code g}: each pass to {@code passes} (after its figures to {@code convergence}),
     * and its end to {@code convergence} (ended by itself unless cancelled).
     */
    static RenderListener listener(long g, PassReport passes, ConvergenceReport convergence) {
        return new RenderListener() {
            @Override
            public void passFinished(RenderStats soFar, Image image) {
                convergence.converged(g, soFar, false);
                passCompleted(soFar.samplesPerPixel(), image);
            }

            @Override
            public void passCompleted(int spp, Image image) {
                passes.pass(g, spp, image);
            }

            @Override
            public void finished(RenderStats stats) {
                convergence.converged(g, stats, !stats.cancelled());
            }
        };
    }

    /** Starts a {@link RenderJob}; the controller cancels, pauses and resumes it and reads its sample count. */
    static Job start(Scene scene, RenderSettings settings, RenderListener listener) {
        RenderJob job = RenderJob.start(scene, settings, listener);
        return new Job() {
            @Override
            public void cancel() {
                job.cancel();
            }

            @Override
            public void pause() {
                job.pause();
            }

            @Override
            public void resume() {
                job.resume();
            }

            @Override
            public long samplesDone() {
                return job.samplesDone();
            }

            @Override
            public Optional<RenderBuffers> snapshotBuffers() {
                return job.snapshotBuffers();
            }
        };
    }

    /** A scheduler on one daemon thread ("strahl-viewer-timer"). */
    static Scheduler timer() {
        return timer("strahl-viewer-timer");
    }

    /** A scheduler on one daemon thread of this name. */
    static Scheduler timer(String threadName) {
        ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, threadName);
            t.setDaemon(true);
            return t;
        });
        return new Scheduler() {
            @Override
            public Runnable schedule(Runnable task, long delayMillis) {
                ScheduledFuture<?> f = timer.schedule(task, delayMillis, TimeUnit.MILLISECONDS);
                return () -> f.cancel(false);
            }

            @Override
            public void shutdown() {
                timer.shutdownNow();
            }
        };
    }
}
