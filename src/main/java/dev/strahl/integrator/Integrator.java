package dev.strahl.integrator;

import dev.strahl.geometry.Ray;
import dev.strahl.math.Rgb;
import dev.strahl.sampling.Rng;

/**
 * Computes the radiance arriving along camera rays. An integrator is immutable and shared; the
 * working memory of one thread lives in the {@link Worker} it hands out, so that the hot path
 * allocates nothing. Integrators know nothing about threads, tiles or files.
 */
public interface Integrator {

    /** A new per-thread worker; never share one between threads. */
    Worker newWorker();

    /** The per-thread part of an integrator. */
    interface Worker {
        /**
         * Writes the radiance arriving at the ray's origin along {@code -ray.d} into {@code out}.
         * A pure function of the ray and the random stream; may modify {@code ray}.
         */
        void radiance(Ray ray, Rng rng, Rgb.Mutable out);

        /** Rays traced by this worker so far (camera, continuation and shadow rays). */
        long rayCount();
    }
}
