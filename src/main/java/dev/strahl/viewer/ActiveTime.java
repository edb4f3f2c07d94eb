package dev.strahl.viewer;

import java.util.function.LongSupplier;

/** The time a job of the viewer has rendered, not counting the time it was paused or held. Not thread-safe. */
final class ActiveTime {
    private final LongSupplier nanoTime;
    private long activeNanos;
    private long runningSince = -1;

    ActiveTime(LongSupplier nanoTime) {
        this.nanoTime = nanoTime;
    }

    /** From zero, running. */
    void restart() {
        activeNanos = 0;
        runningSince = nanoTime.getAsLong();
    }

    /** Running again, if stopped. */
    void start() {
        if (runningSince < 0) {
            runningSince = nanoTime.getAsLong();
        }
    }

    void stop() {
        if (runningSince >= 0) {
            activeNanos += nanoTime.getAsLong() - runningSince;
            runningSince = -1;
        }
    }

    double seconds() {
        long running = runningSince >= 0 ? nanoTime.getAsLong() - runningSince : 0;
        return (activeNanos + running) * 1e-9;
    }
}
