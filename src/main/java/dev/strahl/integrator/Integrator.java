package dev.strahl.integrator;

import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Ray;
import dev.strahl.sampling.Sampler;

/**
 * Computes the radiance arriving along camera rays. An integrator is shared by all threads; the
 * working memory of one thread lives in the {@link Worker} it hands out, so that the hot path
 * allocates nothing. Integrators know nothing about threads, tiles or files.
 *
 * <p>Most integrators are immutable. One that needs work done once per sample index before any
 * pixel takes that sample (a photon mapper traces a photon map for every iteration) says so with
 * {@link #preparesEachSample()}; the render job then renders one sample index per pass and calls
 * {@link #prepareSample} before each pass, while no worker is computing radiance.
 */
public interface Integrator {

    /** Returns {@code maxDepth} if it is -1 (unbounded) or at least 1; throws otherwise. */
    static int checkMaxDepth(int maxDepth) {
        if (maxDepth == 0 || maxDepth < -1) {
            throw new IllegalArgumentException("maxDepth must be -1 (unbounded) or >= 1, got " + maxDepth);
        }
        return maxDepth;
    }

    /** A new per-thread worker; never share one between threads. */
    Worker newWorker();

    /**
     * Whether {@link #prepareSample} must run before the pixels take each sample index. If so, a
     * render job renders passes of one sample per pixel. Default: false.
     */
    default boolean preparesEachSample() {
        return false;
    }

    /**
     * Prepares sample index {@code sampleIndex} of a render with seed {@code seed}; called by the
     * render job before any pixel takes that sample, never while workers compute radiance. The
     * result must depend only on (seed, sampleIndex), not on the thread count, so that renders
     * stay bit-identical on any number of threads. Heavy work goes through {@code parallel},
     * which runs it on the job's worker threads. Does nothing unless {@link #preparesEachSample()}.
     */
    default void prepareSample(long seed, int sampleIndex, Parallel parallel) {}

    /** The per-thread part of an integrator. */
    interface Worker {
        /**
         * Writes the radiance arriving at the ray's origin along {@code -ray.d} into {@code out}.
         * A pure function of the ray, the sampler's numbers and the prepared sample index; may
         * modify {@code ray}. The sampler has been started for the sample (and the camera has
         * taken the pixel position); what the integrator draws begins at dimension
         * {@link Sampler#FIRST_INTEGRATOR_DIMENSION}.
         */
        void radiance(Ray ray, Sampler sampler, MutableRgb out);

        /** Rays traced by this worker so far (camera, continuation and shadow rays, and any traced for {@link #prepareSample}). */
        long rayCount();
    }
}
