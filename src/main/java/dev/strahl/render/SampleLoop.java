package dev.strahl.render;

import dev.strahl.camera.CameraRays;
import dev.strahl.color.MutableRgb;
import dev.strahl.film.Film;
import dev.strahl.geometry.Ray;
import dev.strahl.integrator.FeatureTracer;
import dev.strahl.integrator.Integrator;
import dev.strahl.sampling.IndependentSampler;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.Sampler;
import dev.strahl.sampling.StratifiedSampler;
import org.joml.Vector3d;

/**
 * The sample loop of a render: the one place a camera sample is made ({@link #sample}) and added
 * to a film ({@link #samplePixel}), with what each thread owns for it ({@link WorkerState}). The
 * local passes ({@link RenderWorkers}) and a cluster member's units ({@link UnitRenderers}) both
 * go through it, so their sums are the same bits.
 */
final class SampleLoop {
    private SampleLoop() {}

    /** The {@link StratifiedSampler} (the default), or the {@link IndependentSampler} with {@code -Dstrahl.sampler=independent}. */
    static boolean stratifiedSampler() {
        return !"independent".equals(System.getProperty("strahl.sampler"));
    }

    /**
     * Samples [s0, end) of image pixel (x, y), added in index order to {@code pixel} of {@code film}
     * (the image's, or a cluster unit's tile): the one place a sample reaches a film. Returns the
     * samples that were NaN or infinite (added as black).
     */
    static int samplePixel(WorkerState w, CameraRays cameraRays, long seed, Film film, int pixel, int x, int y, int s0, int end) {
        int invalid = 0;
        for (int s = s0; s < end; s++) {
            boolean finite = sample(w, cameraRays, seed, x, y, s);
            if (w.features != null) {
                film.addFeatures(pixel, w.featureValues);
            }
            if (finite) {
                film.add(pixel, w.radiance.r, w.radiance.g, w.radiance.b);
            } else {
                film.add(pixel, 0, 0, 0);
                invalid++;
            }
        }
        return invalid;
    }

    /**
     * Takes sample {@code s} of pixel (x, y) into {@code w.radiance}: the one place where a sample
     * is made, for the local passes and for a cluster's work units ({@link UnitRenderers}) alike.
     *
     * @return whether the radiance is finite (otherwise the caller adds black and counts it)
     */
    static boolean sample(WorkerState w, CameraRays cameraRays, long seed, int x, int y, int s) {
        w.sampler.startPixelSample(x, y, s);
        w.sampler.getPixel2D(w.filmPosition);
        if (cameraRays.hasLens()) {
            w.sampler.get2D(w.lensPosition);     // a thin lens: the next pair, before the integrator's
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
        w.integrator.radiance(w.ray, w.sampler, w.radiance);
        return w.radiance.isFinite();
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

        WorkerState(int index, Integrator.Worker integrator, Sampler sampler, FeatureTracer features) {
            this.index = index;
            this.integrator = integrator;
            this.sampler = sampler;
            this.features = features;
        }
    }
}
