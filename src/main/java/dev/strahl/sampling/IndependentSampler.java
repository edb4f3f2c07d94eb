package dev.strahl.sampling;

/**
 * Independent uniform numbers (Mitsuba's and pbrt's "independent" sampler): dimension d of a
 * sample is position d + 1 of the {@link SplitMix64} stream of (seed, pixel, sample index), so
 * every dimension is independent of every other, and a pair of {@link #get2D} is just the next
 * two dimensions. The render's sampler with {@code -Dstrahl.sampler=independent}.
 *
 * <p>{@link #startStream} starts a stream that is no pixel sample (the photon mapper's photon j
 * of iteration i): its dimensions count from 0, and {@link #getPixel2D} does not apply.
 */
public final class IndependentSampler extends StreamSampler {
    private final long seed;
    private boolean pixelSample;

    /** A sampler for pixel samples of a render with this seed (the seed does not matter for {@link #startStream}). */
    public IndependentSampler(long seed) {
        super(0);
        this.seed = seed;
    }

    @Override
    public void startPixelSample(int px, int py, int sampleIndex) {
        this.stream = SplitMix64.streamSeed(seed, px, py, sampleIndex);
        this.dimension = FIRST_INTEGRATOR_DIMENSION;
        this.pixelSample = true;
    }

    /** Starts the stream of {@code streamSeed}, which is no pixel sample: the next call draws its dimension 0. */
    public void startStream(long streamSeed) {
        this.stream = streamSeed;
        this.dimension = 0;
        this.pixelSample = false;
    }

    @Override
    public Sample2D getPixel2D(Sample2D dest) {
        assert pixelSample : "getPixel2D in a stream started by startStream";
        dest.u1 = streamValue(0);
        dest.u2 = streamValue(1);
        return dest;
    }

    @Override
    public double get1D() {
        return streamValue(dimension++);
    }

    @Override
    public Sample2D get2D(Sample2D dest) {
        return streamPair(dimension, dest);
    }
}
