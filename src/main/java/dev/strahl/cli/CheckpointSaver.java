package dev.strahl.cli;

import dev.strahl.image.Image;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;

/**
 * Saves a render's state to its checkpoint file every {@code interval} (at the end of the pass
 * that crosses it) and once more when the render ends, however it ends. A periodic save that
 * fails is a warning; the render goes on.
 */
final class CheckpointSaver implements RenderListener {
    private final Path file;
    private final long intervalNanos;
    private final PrintWriter err;
    private volatile RenderJob job;
    private long lastSave = System.nanoTime();
    private boolean warned;

    CheckpointSaver(Path file, Duration interval, PrintWriter err) {
        this.file = file;
        this.intervalNanos = interval.toNanos();
        this.err = err;
    }

    void attach(RenderJob renderJob) {
        this.job = renderJob;
    }

    @Override
    public void passCompleted(int samplesPerPixel, Image image) {
        RenderJob j = job;
        if (j == null || System.nanoTime() - lastSave < intervalNanos) {
            return;
        }
        try {
            j.saveCheckpoint(file);
        } catch (IOException | RuntimeException e) {
            if (!warned) {
                warned = true;
                err.println("strahl: warning: cannot write checkpoint " + file + ": " + e.getMessage() + " (rendering goes on)");
                err.flush();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        lastSave = System.nanoTime();
    }

    /** Saves the final state; a failure here fails the command. */
    void saveFinal() throws InterruptedException {
        try {
            job.saveCheckpoint(file);
        } catch (IOException e) {
            throw new RenderOutcome.RenderFailure("cannot write checkpoint " + file + ": " + e.getMessage(), e);
        }
    }
}
