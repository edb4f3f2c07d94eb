package dev.strahl.render;

import dev.strahl.camera.CameraRays;
import dev.strahl.film.Film;
import dev.strahl.integrator.FeatureTracer;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.PathTracer;
import dev.strahl.integrator.PathWavefront;
import dev.strahl.sampling.Sampler;

/**
 * The sample loop of the path tracer's wavefront (issue 28, stage 2): a rectangle's samples are
 * started one by one in pixel and sample order ({@link SampleLoop#startSample}, each with its own
 * sampler), traced a batch at a time by a {@link PathWavefront}, and added to the film in the
 * order they were started ({@link SampleLoop#add}). Every pixel adds its samples in index order
 * and each sample is the same bits as the scalar loop's, so the image is too, on any thread count
 * and across resume.
 *
 * <p>Only the {@code path} integrator has a wavefront; every other integrator renders one sample
 * at a time: the other integrators, and so the scenes they render, fall back to
 * {@link SampleLoop#sample}. {@code --wavefront on} ({@code -Dstrahl.wavefront=on}) turns it on,
 * off by default (docs/performance.md, stage 2, says why); {@code -Dstrahl.wavefront.batch=N}
 * sets the paths per batch.
 */
final class WavefrontLoop {
    /** Paths per batch unless {@code -Dstrahl.wavefront.batch} says otherwise. */
    static final int DEFAULT_BATCH = 1024;

    private WavefrontLoop() {}

    /** Paths per batch of the wavefront as the system properties say: 0 when it is off. */
    static int batch() {
        if (!"on".equals(System.getProperty(PathWavefront.PROPERTY, "off"))) {
            return 0;
        }
        return Math.max(1, Integer.getInteger("strahl.wavefront.batch", DEFAULT_BATCH));
    }

    /** A wavefront of {@code batch} paths of {@code integrator} for one thread, with the render's samplers; null if it has none or batch is 0. */
    static PathWavefront of(Integrator integrator, int batch, boolean stratified, long seed) {
        if (batch <= 0 || !(integrator instanceof PathTracer path)) {
            return null;
        }
        Sampler[] samplers = new Sampler[batch];
        for (int i = 0; i < batch; i++) {
            samplers[i] = SampleLoop.newSampler(stratified, seed);
        }
        return path.newWavefront(samplers);
    }

    /**
     * Samples [firstSample, endSample) of every pixel of the rectangle [x0, x1) × [y0, y1) of
     * {@code film} (each pixel from the count it holds, if more), with {@code w}'s wavefront; film
     * pixel (x, y) is image pixel (x + imageX, y + imageY) (a cluster unit's tile: its corner).
     * Returns the samples taken and adds those that were NaN or infinite to {@code invalid[0]}.
     */
    static long renderRect(SampleLoop.WorkerState w, CameraRays cameraRays, long seed, Film film, int x0, int y0, int x1, int y1,
                           int imageX, int imageY, int firstSample, int endSample, long[] invalid) {
        PathWavefront wf = w.wavefront;
        int capacity = wf.capacity();
        int n = 0;
        long taken = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                int pixel = film.pixelIndex(x, y);
                for (int s = Math.max(firstSample, film.sampleCountAt(pixel)); s < endSample; s++) {
                    SampleLoop.startSample(w, wf.sampler(n), cameraRays, seed, x + imageX, y + imageY, s);
                    wf.start(n, w.ray);
                    w.slotPixel[n] = pixel;
                    if (w.features != null) {
                        System.arraycopy(w.featureValues, 0, w.slotFeatures, n * FeatureTracer.CHANNELS, FeatureTracer.CHANNELS);
                    }
                    taken++;
                    if (++n == capacity) {
                        invalid[0] += flush(w, film, n);
                        n = 0;
                    }
                }
            }
        }
        invalid[0] += flush(w, film, n);
        return taken;
    }

    /** Traces the batch's n paths and adds them to the film in slot order; returns the invalid ones. */
    private static int flush(SampleLoop.WorkerState w, Film film, int n) {
        PathWavefront wf = w.wavefront;
        wf.run(n);
        int invalid = 0;
        for (int i = 0; i < n; i++) {
            if (w.features != null) {
                System.arraycopy(w.slotFeatures, i * FeatureTracer.CHANNELS, w.featureValues, 0, FeatureTracer.CHANNELS);
            }
            w.radiance.set(wf.red(i), wf.green(i), wf.blue(i));
            invalid += SampleLoop.add(w, film, w.slotPixel[i], w.radiance);
        }
        return invalid;
    }
}
