package dev.strahl.sampling;

/**
 * The random stream of one camera sample. Its state depends only on (seed, pixel, sample index),
 * never on the thread that renders it, which makes renders bit-identical for any thread count
 * and lets a single pixel be replayed alone.
 *
 * <p>The generator is SplitMix64 (Steele, Lea &amp; Flood, "Fast Splittable Pseudorandom Number
 * Generators", OOPSLA 2014): a Weyl sequence passed through a strong 64-bit finaliser. Mutable and
 * not thread-safe; each worker owns one and re-seeds it per sample.
 */
public final class Rng {
    private static final long GOLDEN_GAMMA = 0x9e3779b97f4a7c15L;
    private static final double DOUBLE_UNIT = 0x1.0p-53;

    private long state;

    public Rng() {}

    public Rng(long seed) {
        this.state = seed;
    }

    /** SplitMix64 finaliser: a well-mixed 64-bit hash of {@code z}. */
    public static long mix64(long z) {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    /** The stream seed of sample {@code sampleIndex} of pixel (px, py) under the render seed. */
    public static long streamSeed(long seed, int px, int py, long sampleIndex) {
        long pixel = ((long) py << 32) | (px & 0xffffffffL);
        return mix64(mix64(mix64(seed) ^ pixel) ^ sampleIndex * GOLDEN_GAMMA);
    }

    /** Restarts the stream at the given seed. */
    public Rng seed(long seed) {
        this.state = seed;
        return this;
    }

    public long nextLong() {
        state += GOLDEN_GAMMA;
        return mix64(state);
    }

    /** A uniform double in [0, 1), with 53 random bits. */
    public double nextDouble() {
        return (nextLong() >>> 11) * DOUBLE_UNIT;
    }
}
