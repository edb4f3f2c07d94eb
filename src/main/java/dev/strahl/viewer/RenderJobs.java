package dev.strahl.viewer;

import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/** What {@link RenderController} runs on outside tests: real render jobs and a timer thread. */
final class RenderJobs {
    private RenderJobs() {
    }

    /** Starts a {@link RenderJob}; the controller cancels, pauses and resumes it and reads its sample count. */
    static RenderController.Job start(Scene scene, RenderSettings settings, RenderListener listener) {
        RenderJob job = RenderJob.start(scene, settings, listener);
        return new RenderController.Job() {
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
        };
    }

    /** A scheduler on one daemon thread ("strahl-viewer-timer"). */
    static RenderController.Scheduler timer() {
        ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "strahl-viewer-timer");
            t.setDaemon(true);
            return t;
        });
        return new RenderController.Scheduler() {
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
