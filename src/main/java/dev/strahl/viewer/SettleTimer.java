package dev.strahl.viewer;

import java.util.function.LongConsumer;

/**
 * The wait after the last camera move before full-resolution rendering restarts: each move
 * restarts it (cancelling the wait before), and a firing that a later move or a full-resolution
 * start has made stale is recognised by its token. Not thread-safe: {@link RenderController} uses
 * it under its lock, also in the task it fires.
 */
final class SettleTimer {
    private final RenderJobs.Scheduler scheduler;
    private final long delayMillis;
    private Runnable cancel;
    private long token;

    SettleTimer(RenderJobs.Scheduler scheduler, long delayMillis) {
        this.scheduler = scheduler;
        this.delayMillis = delayMillis;
    }

    /** Waits anew: {@code task} gets this wait's token when it ends. */
    void restart(LongConsumer task) {
        if (cancel != null) {
            cancel.run();
        }
        long t = ++token;
        cancel = scheduler.schedule(() -> task.accept(t), delayMillis);
    }

    /** Whether the wait of {@code t} is the current one; if so it has ended. */
    boolean ended(long t) {
        if (t != token) {
            return false;
        }
        cancel = null;
        return true;
    }

    /** Stops the current wait, if any; its firing, already on its way, is stale. */
    void stop() {
        if (cancel != null) {
            cancel.run();
            cancel = null;
            token++;
        }
    }

    /** Cancels the wait and ends the scheduler for good. */
    void close() {
        if (cancel != null) {
            cancel.run();
        }
        scheduler.shutdown();
    }
}
