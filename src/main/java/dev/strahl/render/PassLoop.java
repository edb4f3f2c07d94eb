package dev.strahl.render;

import dev.strahl.film.Film;
import dev.strahl.image.Image;
import dev.strahl.integrator.Integrator;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.function.DoubleSupplier;

/**
 * The passes of a {@link RenderJob}, run on its coordinator thread: from the sample index every
 * pixel holds (0, or what a checkpoint restored) to the settings' count, in passes of 1, 1, 2, 4, 8
 * and then 16 samples per pixel (or the settings' pass size; one sample for an integrator that
 * prepares each sample index), each reported to the listener with the figures so far. A cancel
 * ends the loop at once, a time limit after the pass that crosses it. How many samples a pass
 * takes, and where, is decided here: with a noise threshold, only the pixels its
 * {@link NoiseTarget} has not found converged, in passes that end at its boundaries, where it
 * decides again; the render then also ends when no pixel is left.
 */
final class PassLoop {
    private static final int MAX_AUTO_PASS = 16;

    private final RenderSettings settings;
    private final Integrator integrator;
    private final PassRunner workers;
    private final Film film;
    private final PassBuffers passes;
    private final RenderListener listener;
    /** With a noise threshold, which pixels still render; else null. */
    private final NoiseTarget target;
    /** NaN or infinite samples of the renders a resumed job continues. */
    private final long earlierInvalid;
    /** Samples the film held when the job began (a resumed render's). */
    private final long restoredSamples;
    private volatile int completedSpp;

    PassLoop(RenderSettings settings, Integrator integrator, PassRunner workers, Film film, PassBuffers passes, RenderListener listener,
             NoiseTarget target, long earlierInvalid) {
        this.settings = settings;
        this.integrator = integrator;
        this.workers = workers;
        this.film = film;
        this.passes = passes;
        this.listener = listener;
        this.target = target;
        this.earlierInvalid = earlierInvalid;
        this.restoredSamples = film.totalSamples();
        this.completedSpp = completed();                       // 0, unless restored
    }

    /**
     * Runs the passes, then tells the listener the figures at the end and completes {@code result}
     * with them (or exceptionally with what failed, on whichever thread); shuts the workers down.
     *
     * @param elapsed the job's rendering time so far, in seconds
     * @param result  the job's result
     */
    void run(DoubleSupplier elapsed, CompletableFuture<RenderStats> result) {
        try {
            RenderStats stats = passes(elapsed);
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

    /** The passes; returns the figures at the end. */
    private RenderStats passes(DoubleSupplier elapsed) throws InterruptedException, ExecutionException {
        int spp = settings.sampling().samplesPerPixel();
        boolean prepares = integrator.preparesEachSample();
        int start = settle(target != null ? target.start() : film.minSampleCount(), spp);
        if (restoredSamples > 0) {
            passes.ended(film.toImage());              // what the restored film holds, until a pass ends
        }
        int perPass = settings.execution().samplesPerPass();
        double limit = settings.execution().timeLimit().toNanos() * 1e-9;
        int pass = 0;
        while (!workers.cancelled()) {
            int goal = target != null ? target.goal(spp) : spp;
            if (start >= goal) {
                break;
            }
            int size = prepares ? 1 : perPass > 0 ? perPass : workers.passSize(pass);
            int end = Math.min(goal, start + size);
            if (prepares) {
                integrator.prepareSample(settings.sampling().seed(), start, workers.parallel());
                if (workers.cancelled()) {
                    break;
                }
            }
            passes.starting();
            workers.renderPass(start, end, target);
            if (workers.cancelled()) {
                break;
            }
            start = settle(end, spp);
            completedSpp = end;
            Image image = film.toImage();
            passes.ended(image);
            pass++;
            listener.passFinished(figures(elapsed.getAsDouble(), pass), image);
            if (limit > 0 && elapsed.getAsDouble() >= limit) {
                break;                             // the pass that crossed the time limit is kept
            }
        }
        return figures(elapsed.getAsDouble(), pass);
    }

    /**
     * With a noise target, the decisions due now that the pixels still rendering hold {@code start}
     * samples: at each boundary they have reached (not beyond {@code spp}). Returns where the next
     * pass starts ({@link Integer#MAX_VALUE} when no pixel is left).
     */
    private int settle(int start, int spp) {
        while (target != null && start >= target.goal(spp) && target.decidesAt(target.goal(spp))) {
            target.decide(spp);
            start = target.start();
        }
        return start;
    }

    /** Samples per pixel of all completed passes: of the pixels still rendering, with a noise target. */
    private int completed() {
        int spp = settings.sampling().samplesPerPixel();
        int start = target != null ? target.start() : film.minSampleCount();
        return Math.min(spp, start != Integer.MAX_VALUE ? start : SampleCounts.of(film).max());
    }

    /** Samples per pixel of all completed passes (of a resumed render: counting those before). */
    int completedSamplesPerPixel() {
        return completedSpp;
    }

    /**
     * Fraction of the samples the render will take that it has taken: of the settings' count for
     * every pixel, or with a noise target, of what it estimated the pixels still rendering need at
     * its last decision.
     */
    double progress() {
        double done = restoredSamples + workers.samplesDone();
        double total = (double) settings.sampling().samplesPerPixel() * film.width() * film.height();
        double estimate = target != null ? target.estimatedTotalSamples() : 0;
        return Math.min(1, done / (estimate > 0 ? Math.min(estimate, total) : total));
    }

    /** The job's figures now, after {@code passCount} passes; read while nothing renders into the film. */
    RenderStats figures(double seconds, int passCount) {
        SampleCounts counts = SampleCounts.of(film);
        return new RenderStats(seconds, workers.samplesDone(), workers.rayCount(), completedSpp, workers.threads(), workers.cancelled(),
                earlierInvalid + workers.invalidSamples(), workers.idleSeconds(), passCount, counts.min(), counts.mean(), counts.max(),
                target != null ? target.convergedFraction() : 0, workers.members());
    }

    /** Passes of 1, 1, 2, 4, 8 and then 16 samples per pixel: a first image at once, little overhead later. */
    static int autoPassSize(int pass) {
        return pass == 0 ? 1 : Math.min(MAX_AUTO_PASS, 1 << Math.min(pass - 1, 4));
    }

    /** The fewest, mean and most samples of the film's pixels. */
    record SampleCounts(int min, double mean, int max) {
        static SampleCounts of(Film film) {
            int min = Integer.MAX_VALUE, max = 0;
            long sum = 0;
            for (int y = 0; y < film.height(); y++) {
                for (int x = 0; x < film.width(); x++) {
                    int n = film.sampleCount(x, y);
                    min = Math.min(min, n);
                    max = Math.max(max, n);
                    sum += n;
                }
            }
            return new SampleCounts(min, sum / ((double) film.width() * film.height()), max);
        }
    }
}
