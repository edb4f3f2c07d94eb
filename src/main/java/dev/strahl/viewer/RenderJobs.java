package dev.strahl.viewer;

import dev.strahl.render.RenderBuffers;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import java.util.Optional;
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
