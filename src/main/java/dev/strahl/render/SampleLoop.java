package dev.strahl.render;

import dev.strahl.camera.CameraRays;
import dev.strahl.color.MutableRgb;
import dev.strahl.film.Film;
import dev.strahl.geometry.Ray;
import dev.strahl.integrator.FeatureTracer;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.PathWavefront;
import dev.strahl.sampling.IndependentSampler;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.Sampler;
import dev.strahl.sampling.StratifiedSampler;
import org.joml.Vector3d;

/**
 * The sample loop of a render: the one place a camera sample is started ({@link #startSample}),
 * made ({@link #sample}) and added to a film ({@link #add}), with what each thread owns for it
 * ({@link WorkerState}). The local passes ({@link RenderWorkers}), the path tracer's wavefront
 * ({@link WavefrontLoop}) and a cluster member's units ({@link UnitRenderers}) all go through it,
 * so their sums are the same bits.
 */
final class SampleLoop {
    private SampleLoop() {}

    /** The {@link StratifiedSampler} (the default), or the {@link IndependentSampler} with {@code -Dstrahl.sampler=independent}. */
    static boolean stratifiedSampler() {
        return !"independent".equals(System.getProperty("strahl.sampler"));
    }

    /**
     * Samples [s0, end) of image pixel (x, y), added in index order to {@code pixel} of {@code film}
     * (the image's, or a cluster unit's tile), one sample at a time. Returns the samples that were
     * NaN or infinite (added as black).
     */
    static int samplePixel(WorkerState w, CameraRays cameraRays, long seed, Film film, int pixel, int x, int y, int s0, int end) {
        int invalid = 0;
        for (int s = s0; s < end; s++) {
            sample(w, cameraRays, seed, x, y, s);
            invalid += add(w, film, pixel, w.radiance);
        }
        return invalid;
    }

    /**
     * Adds a sample's radiance (and the feature values in {@code w.featureValues}, when kept) to
     * {@code pixel} of {@code film}: the one place a sample reaches a film. Returns 1 if the
     * radiance was NaN or infinite (added as black), else 0.
     */
    static int add(WorkerState w, Film film, int pixel, MutableRgb radiance) {
        if (w.features != null) {
            film.addFeatures(pixel, w.featureValues);
        }
        if (radiance.isFinite()) {
            film.add(pixel, radiance.r, radiance.g, radiance.b);
            return 0;
        }
        film.add(pixel, 0, 0, 0);
        return 1;
    }

    /**
     * Takes sample {@code s} of pixel (x, y) into {@code w.radiance}: the one place where a sample
     * is made, for the local passes and for a cluster's work units ({@link UnitRenderers}) alike.
     *
     * @return whether the radiance is finite (otherwise the caller adds black and counts it)
     */
    static boolean sample(WorkerState w, CameraRays cameraRays, long seed, int x, int y, int s) {
        startSample(w, w.sampler, cameraRays, seed, x, y, s);
        w.integrator.radiance(w.ray, w.sampler, w.radiance);
        return w.radiance.isFinite();
    }

    /**
     * Starts {@code sampler} for sample {@code s} of pixel (x, y) and takes the camera's numbers
     * from it: the camera ray into {@code w.ray}, and the feature values into
     * {@code w.featureValues} when the worker keeps them. The integrator goes on from there.
     */
    static void startSample(WorkerState w, Sampler sampler, CameraRays cameraRays, long seed, int x, int y, int s) {
        sampler.startPixelSample(x, y, s);
        sampler.getPixel2D(w.filmPosition);
        if (cameraRays.hasLens()) {
            sampler.get2D(w.lensPosition);       // a thin lens: the next pair, before the integrator's
            cameraRays.generate(x + w.filmPosition.u1, y + w.filmPosition.u2, w.lensPosition.u1, w.lensPosition.u2, w.disk, w.ray);
        } else {
            cameraRays.generate(x + w.filmPosition.u1, y + w.filmPosition.u2, w.ray);
        }
        if (w.features != null) {
            // before the integrator, which may change the ray; from streams of its own
            w.featureRay.o.set(w.ray.o);
            w.featureRay.d.set(w.ray.d);
            w.featureRay.tMax = w.ray.tMax;
            w.features.trace(w.featureRay, seed, x, y, s, w.featureValues);
        }
    }

    /** The sampler a render's settings choose, for a worker of one thread. */
    static Sampler newSampler(boolean stratified, long seed) {
        return stratified ? new StratifiedSampler(seed) : new IndependentSampler(seed);
    }

    /** What one worker thread owns: reused for every sample, so the loop allocates nothing. */
    static final class WorkerState {
        final int index;
        /** When this thread finished its part of the last pass (System.nanoTime). */
        long finished;
        final Integrator.Worker integrator;
        final Sampler sampler;
        final Sample2D filmPosition = new Sample2D();
        final Sample2D lensPosition = new Sample2D();
        final Vector3d disk = new Vector3d();
        final Ray ray = new Ray();
        final MutableRgb radiance = new MutableRgb();
        final FeatureTracer features;
        final Ray featureRay = new Ray();
        final double[] featureValues = new double[FeatureTracer.CHANNELS];
        /** The path tracer's wavefront, which renders this thread's samples a batch at a time ({@link WavefrontLoop}); null for one at a time. */
        final PathWavefront wavefront;
        /** Per slot of the wavefront: the film pixel its sample goes to, and its feature values. */
        final int[] slotPixel;
        final double[] slotFeatures;

        WorkerState(int index, Integrator.Worker integrator, Sampler sampler, FeatureTracer features) {
            this(index, integrator, sampler, features, null);
        }

        /** A worker whose samples a wavefront makes, when {@code wavefront} is not null (its worker is then {@code integrator}). */
        WorkerState(int index, Integrator.Worker integrator, Sampler sampler, FeatureTracer features, PathWavefront wavefront) {
            this.index = index;
            this.integrator = integrator;
            this.sampler = sampler;
            this.features = features;
            this.wavefront = wavefront;
            int slots = wavefront != null ? wavefront.capacity() : 0;
            this.slotPixel = new int[slots];
            this.slotFeatures = new double[features != null ? slots * FeatureTracer.CHANNELS : 0];
        }
    }
}
