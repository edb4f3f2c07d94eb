package dev.strahl.medium;

import dev.strahl.sampling.SplitMix64;

/**
 * The uniform numbers of delta and ratio tracking, whose count depends on the medium (one or two
 * per tentative collision): a {@link SplitMix64} stream that the caller seeds from numbers its own
 * sampler drew ({@link #seed}), so that the sampler hands out the same dimensions in the same
 * order whatever the medium does, and the tracking is still a function of (seed, pixel, sample).
 * Mutable, one per worker thread.
 */
public final class TrackingRandom {
    private long state;

    /** Creates a stream to be {@link #seed seeded} before use. */
    public TrackingRandom() {}

    /** Starts the stream from two numbers of the caller's sampler (their 53 bits each, mixed). */
    public TrackingRandom seed(double u1, double u2) {
        state = SplitMix64.mix64(Double.doubleToRawLongBits(u1) * SplitMix64.GOLDEN_GAMMA ^ Double.doubleToRawLongBits(u2));
        return this;
    }

    /** The next uniform number in [0, 1). */
    public double next() {
        state += SplitMix64.GOLDEN_GAMMA;
        return SplitMix64.toUnit(SplitMix64.mix64(state));
    }
}
