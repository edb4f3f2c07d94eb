package dev.strahl.render;

import dev.strahl.integrator.Parallel;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.ExecutionException;

/**
 * What renders the passes of a {@link RenderJob}: the job's own threads ({@link RenderWorkers}), or
 * the members of a cluster ({@link ClusterPasses}). Either way every pixel adds its samples in
 * index order, so the image is the same bits.
 */
interface PassRunner {
    /**
     * Renders samples [firstSample, endSample) of every pixel, or with {@code only} non-null of the
     * pixels it {@linkplain NoiseTarget#renders renders} (skipping tiles without any); returns when the
     * pass is done or cancelled.
     */
    void renderPass(int firstSample, int endSample, NoiseTarget only) throws InterruptedException, ExecutionException;

    /** Runs an integrator's per-sample preparation; null when this runner cannot (a cluster). */
    Parallel parallel();

    /** Asks the work to stop soon. */
    void cancel();

    boolean cancelled();

    /** Holds the work between tiles (or units) until {@link #release()}. */
    void hold();

    void release();

    /** While held: waits until nothing writes into the film. */
    void awaitStill() throws InterruptedException;

    /** What the runner has counted: camera samples taken, and those that were NaN or infinite. */
    Tally tally();

    /** Camera samples taken. */
    default long samplesDone() {
        return tally().samples.get();
    }

    /** Samples that were NaN or infinite (added as black). */
    default long invalidSamples() {
        return tally().invalid.get();
    }

    /** The counts of a runner, added to by its threads. */
    final class Tally {
        final AtomicLong samples = new AtomicLong();
        final AtomicLong invalid = new AtomicLong();
    }

    long rayCount();

    /** Seconds, summed over threads, that threads waited at the ends of passes for the others (0 where not measured: a cluster). */
    default double idleSeconds() {
        return 0;
    }

    /** What each member of a cluster did for the job so far; none for the job's own threads. */
    default List<RenderStats.Member> members() {
        return List.of();
    }

    /** Threads that render (of all members, for a cluster). */
    int threads();

    void shutdown();

    /** Samples per pixel of automatic pass {@code pass} (from 0). */
    default int passSize(int pass) {
        return PassLoop.autoPassSize(pass);
    }
}
