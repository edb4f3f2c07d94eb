package dev.strahl.render;

/**
 * The time a job has rendered, without the time it was paused: started when the job starts,
 * stopped by {@link #pause()}, going on after {@link #resume()}. Thread-safe.
 */
final class PauseClock {
    private final long start = System.nanoTime();
    private boolean paused;
    private long pausedNanos;
    private long pauseStart;

    /** Stops the clock; returns whether it was running (so that a pause is acted on once). */
    synchronized boolean pause() {
        if (paused) {
            return false;
        }
        paused = true;
        pauseStart = System.nanoTime();
        return true;
    }

    /** Lets the clock go on; returns whether it was paused. */
    synchronized boolean resume() {
        if (!paused) {
            return false;
        }
        paused = false;
        pausedNanos += System.nanoTime() - pauseStart;
        return true;
    }

    synchronized boolean isPaused() {
        return paused;
    }

    synchronized double seconds() {
        long now = System.nanoTime();
        return (now - start - pausedNanos - (paused ? now - pauseStart : 0)) * 1e-9;
    }
}
