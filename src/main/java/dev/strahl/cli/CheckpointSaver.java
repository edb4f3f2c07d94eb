package dev.strahl.cli;

import dev.strahl.film.Film;
import dev.strahl.film.Image;
import dev.strahl.render.Checkpoint;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderStats;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;

/**
 * Saves a render's film to its checkpoint file every {@code interval} (at the end of the pass
 * that crosses it, while the workers wait) and once more when the render ends, however it ends.
 */
final class CheckpointSaver implements RenderListener {
    private final Checkpoint identity;
    private final Path file;
    private final Film film;
    private final long intervalNanos;
    private final long earlierInvalid;
    private final double earlierSeconds;
    private final PrintWriter err;
    private volatile RenderJob job;
    private long lastSave = System.nanoTime();
    private boolean warned;

    CheckpointSaver(Checkpoint identity, Path file, Film film, Duration interval, Checkpoint.Restored restored,
                    PrintWriter err) {
        this.identity = identity;
        this.file = file;
        this.film = film;
        this.intervalNanos = interval.toNanos();
        this.earlierInvalid = restored != null ? restored.invalidSamples() : 0;
        this.earlierSeconds = restored != null ? restored.seconds() : 0;
        this.err = err;
    }

    /** The job whose figures go into the checkpoints (it starts before the saver can know it). */
    void attach(RenderJob renderJob) {
        this.job = renderJob;
    }

    /** Runs on the render's coordinator thread between passes: no worker writes to the film now. */
    @Override
    public void passCompleted(int samplesPerPixel, Image image) {
        RenderJob j = job;
        if (j == null || System.nanoTime() - lastSave < intervalNanos) {
            return;
        }
        try {
            identity.save(file, film, earlierInvalid + j.invalidSamples(), earlierSeconds + j.elapsedSeconds());
        } catch (IOException | RuntimeException e) {
            if (!warned) {
                warned = true;
                err.println("strahl: warning: cannot write checkpoint " + file + ": " + e.getMessage() + " (rendering goes on)");
                err.flush();
            }
        }
        lastSave = System.nanoTime();
    }

    /**
     * Saves the state the render ended with (all workers have stopped), so that it can be resumed
     * after an interruption or continued to more samples. Returns true; a failure to write is a
     * {@link RenderCommand.RenderFailure}.
     */
    boolean saveFinal(RenderStats stats) {
        try {
            identity.save(file, film, earlierInvalid + stats.invalidSamples(), earlierSeconds + stats.seconds());
        } catch (IOException e) {
            throw new RenderCommand.RenderFailure("cannot write checkpoint " + file + ": " + e.getMessage(), e);
        }
        return true;
    }
}
