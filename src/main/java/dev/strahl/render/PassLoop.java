package dev.strahl.render;

import dev.strahl.film.Film;
import dev.strahl.image.Image;
import dev.strahl.integrator.Integrator;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.function.DoubleSupplier;
import java.util.function.IntConsumer;
import java.util.function.IntFunction;

/**
 * The passes of a {@link RenderJob}, run on its coordinator thread: from the sample index every
 * pixel holds (0, or what a checkpoint restored) to the settings' count, in passes of 1, 1, 2, 4, 8
 * and then 16 samples per pixel (or the settings' pass size; one sample for an integrator that
 * prepares each sample index), each reported to the listener with the figures so far. A cancel
 * ends the loop at once, a time limit after the pass that crosses it. How many samples a pass
 * takes, and where, is decided here.
 */
final class PassLoop {
    private static final int MAX_AUTO_PASS = 16;

    private final RenderSettings settings;
    private final Integrator integrator;
    private final PassRunner workers;
    private final Film film;
    private final PassBuffers passes;
    private final RenderListener listener;

    PassLoop(RenderSettings settings, Integrator integrator, PassRunner workers, Film film, PassBuffers passes, RenderListener listener) {
        this.settings = settings;
        this.integrator = integrator;
        this.workers = workers;
        this.film = film;
        this.passes = passes;
        this.listener = listener;
    }

    /**
     * Runs the passes, then tells the listener the figures at the end and completes {@code result}
     * with them (or exceptionally with what failed, on whichever thread); shuts the workers down.
     *
     * @param restored  whether the film holds a checkpoint's samples (shown until the first pass ends)
     * @param completed hears the samples per pixel of all completed passes after each
     * @param figures   the job's figures after a number of passes
     * @param elapsed   the job's rendering time so far, in seconds
     * @param result    the job's result
     */
    void run(boolean restored, IntConsumer completed, IntFunction<RenderStats> figures, DoubleSupplier elapsed,
             CompletableFuture<RenderStats> result) {
        try {
            RenderStats stats = passes(restored, completed, figures, elapsed);
            listener.finished(stats);
            result.complete(stats);
        } catch (ExecutionException e) {
            result.completeExceptionally(e.getCause());    // what failed on a render thread, not its wrapper
        } catch (Throwable t) {
            result.completeExceptionally(t);
        } finally {
            workers.shutdown();
        }
    }

    /**
     * The passes.
     *
     * @param restored  whether the film holds a checkpoint's samples (shown until the first pass ends)
     * @param completed hears the samples per pixel of all completed passes after each
     * @param figures   the job's figures after a number of passes
     * @param elapsed   the job's rendering time so far, in seconds
     * @return the figures at the end
     */
    private RenderStats passes(boolean restored, IntConsumer completed, IntFunction<RenderStats> figures, DoubleSupplier elapsed)
            throws InterruptedException, ExecutionException {
        int spp = settings.sampling().samplesPerPixel();
        boolean prepares = integrator.preparesEachSample();
        int start = film.minSampleCount();
        if (restored) {
            passes.ended(film.toImage());              // what the restored film holds, until a pass ends
        }
        int perPass = settings.execution().samplesPerPass();
        double limit = settings.execution().timeLimit().toNanos() * 1e-9;
        int pass = 0;
        while (start < spp && !workers.cancelled()) {
            int size = prepares ? 1 : perPass > 0 ? perPass : workers.passSize(pass);
            int end = Math.min(spp, start + size);
            if (prepares) {
                integrator.prepareSample(settings.sampling().seed(), start, workers.parallel());
                if (workers.cancelled()) {
                    break;
                }
            }
            passes.starting();
            workers.renderPass(start, end);
            if (workers.cancelled()) {
                break;
            }
            completed.accept(end);
            Image image = film.toImage();
            passes.ended(image);
            pass++;
            listener.passFinished(figures.apply(pass), image);
            start = end;
            if (limit > 0 && elapsed.getAsDouble() >= limit) {
                break;                             // the pass that crossed the time limit is kept
            }
        }
        return figures.apply(pass);
    }

    /** Passes of 1, 1, 2, 4, 8 and then 16 samples per pixel: a first image at once, little overhead later. */
    static int autoPassSize(int pass) {
        return pass == 0 ? 1 : Math.min(MAX_AUTO_PASS, 1 << Math.min(pass - 1, 4));
    }
}
