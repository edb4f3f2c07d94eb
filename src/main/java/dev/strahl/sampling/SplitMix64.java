package dev.strahl.sampling;

/**
 * The random streams behind the samplers: SplitMix64 (Steele, Lea &amp; Flood, "Fast Splittable
 * Pseudorandom Number Generators", OOPSLA 2014), a Weyl sequence passed through a strong 64-bit
 * finaliser. Its k-th value (k ≥ 1) from seed s is {@code mix64(s + k·γ)}, so any position of a
 * stream can be computed without the ones before it: the samplers number their dimensions and
 * take dimension d from a fixed position of the stream of (seed, pixel, sample index), whatever
 * was drawn before it.
 */
public final class SplitMix64 {
    /** The Weyl increment γ: the odd integer nearest 2^64 / φ. */
    public static final long GOLDEN_GAMMA = 0x9e3779b97f4a7c15L;
    private static final double DOUBLE_UNIT = 0x1.0p-53;

    private SplitMix64() {}

    /** SplitMix64 finaliser: a well-mixed 64-bit hash of {@code z}. */
    public static long mix64(long z) {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    /** Pixel (px, py) as one 64-bit key: y in the high half, x in the low half. */
    static long pixelKey(int px, int py) {
        return ((long) py << 32) | (px & 0xffffffffL);
    }

    /** The stream seed of sample {@code sampleIndex} of pixel (px, py) under the render seed. */
    public static long streamSeed(long seed, int px, int py, long sampleIndex) {
        return mix64(mix64(mix64(seed) ^ pixelKey(px, py)) ^ sampleIndex * GOLDEN_GAMMA);
    }

    /** The value at position {@code k} ≥ 1 of the stream of {@code streamSeed}. */
    public static long at(long streamSeed, long k) {
        return mix64(streamSeed + k * GOLDEN_GAMMA);
    }

    /** A 64-bit value as a uniform double in [0, 1): its high 53 bits. */
    public static double toUnit(long bits) {
        return (bits >>> 11) * DOUBLE_UNIT;
    }
}
