package dev.strahl.sampling;

/**
 * The random numbers of one camera sample. Its state depends only on (seed, pixel, sample index),
 * never on the thread that renders it, which makes renders bit-identical for any thread count
 * and lets a single pixel be replayed alone.
 *
 * <p>The generator is SplitMix64 (Steele, Lea &amp; Flood, "Fast Splittable Pseudorandom Number
 * Generators", OOPSLA 2014): a Weyl sequence passed through a strong 64-bit finaliser.
 *
 * <p>In <em>sample mode</em> ({@link #startSample}) the first {@value #STRATIFIED_DIMENSIONS}
 * calls of {@link #nextDouble()} are instead dimensions of a stratified point set of the pixel:
 * dimensions 2k and 2k + 1 are one shuffled, Owen-scrambled Sobol (0,2)-sequence
 * ({@link OwenSobol}) per pair and pixel, so that the samples of a pixel cover each pair's unit
 * square evenly (any 2^m of them form a (0,m,2)-net) while the pairs stay independent of each
 * other and of other pixels. Every value is still uniform in [0, 1), so every estimator stays
 * unbiased; later calls continue with the SplitMix64 stream. Integrators that draw their
 * two-dimensional samples at even dimensions (as the path tracer does) gain the most.
 * {@link #nextLong()} always uses the stream. Mutable and not thread-safe; each worker owns one
 * and restarts it per sample.
 */
public final class Rng {
    private static final long GOLDEN_GAMMA = 0x9e3779b97f4a7c15L;
    private static final double DOUBLE_UNIT = 0x1.0p-53;
    /** Dimensions drawn from stratified points in sample mode: the pixel position and three path vertices of the path tracer. */
    public static final int STRATIFIED_DIMENSIONS = 8;

    private long state;
    private int limit;             // stratified dimensions of this sample: 0 outside sample mode
    private int dimension;         // the next dimension
    private int pixelSeed;
    private int sampleIndex;
    private int pair;              // the pair whose point is in pairX, pairY; -1 for none
    private int pairX, pairY;

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

    /** Restarts the stream at the given seed (plain stream, no stratified dimensions). */
    public Rng seed(long seed) {
        this.state = seed;
        this.limit = 0;
        return this;
    }

    /**
     * Starts sample {@code sampleIndex} of pixel (px, py) in sample mode: stratified dimensions
     * first, then the stream of {@link #streamSeed}.
     */
    public Rng startSample(long seed, int px, int py, int sampleIndex) {
        this.state = streamSeed(seed, px, py, sampleIndex);
        long pixel = ((long) py << 32) | (px & 0xffffffffL);
        this.pixelSeed = (int) mix64(mix64(seed + GOLDEN_GAMMA) ^ pixel);
        this.sampleIndex = sampleIndex;
        this.dimension = 0;
        this.pair = -1;
        this.limit = STRATIFIED_DIMENSIONS;
        return this;
    }

    /**
     * Skips {@code n} dimensions: an integrator that does not need a sample it usually draws
     * (no light sample at a specular surface) keeps its later pairs aligned. No effect on the
     * stream or outside sample mode.
     */
    public void skip(int n) {
        dimension += n;
    }

    /** The next dimension in sample mode (0-based), for tests. */
    int dimension() {
        return dimension;
    }

    public long nextLong() {
        state += GOLDEN_GAMMA;
        return mix64(state);
    }

    /** A uniform double in [0, 1): the next stratified dimension in sample mode, else 53 random bits of the stream. */
    public double nextDouble() {
        int d = dimension;
        if (d < limit) {
            dimension = d + 1;
            int p = d >> 1;
            if (p != pair) {
                long xy = OwenSobol.point(sampleIndex, OwenSobol.mix32(pixelSeed + p * 0x9e3779b9));
                pairX = (int) (xy >>> 32);
                pairY = (int) xy;
                pair = p;
            }
            return OwenSobol.toUnit((d & 1) == 0 ? pairX : pairY);
        }
        return (nextLong() >>> 11) * DOUBLE_UNIT;
    }
}
