package dev.strahl.sampling;

/**
 * What both samplers share: the dimension counter and the {@link SplitMix64} stream of the
 * sample, of which dimension d ≥ {@code firstStreamDimension} is position
 * d − {@code firstStreamDimension} + 1. So a dimension's value depends on its number alone, not
 * on what was drawn before it.
 */
abstract sealed class StreamSampler implements Sampler permits IndependentSampler, StratifiedSampler {
    private final int firstStreamDimension;
    /** The seed of the current sample's stream. */
    long stream;
    /** The next dimension to draw. */
    int dimension;

    StreamSampler(int firstStreamDimension) {
        this.firstStreamDimension = firstStreamDimension;
    }

    /** The next dimension, for tests. */
    final int dimension() {
        return dimension;
    }

    /** Dimension d ≥ the first stream dimension. */
    final double streamValue(int d) {
        return SplitMix64.toUnit(SplitMix64.at(stream, d - (firstStreamDimension - 1L)));
    }

    /** Dimensions d and d + 1 into {@code dest}; the next dimension is then d + 2. */
    final Sample2D streamPair(int d, Sample2D dest) {
        dimension = d + 2;
        dest.u1 = streamValue(d);
        dest.u2 = streamValue(d + 1);
        return dest;
    }
}
