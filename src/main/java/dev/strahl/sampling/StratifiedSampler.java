package dev.strahl.sampling;

/**
 * The render's default sampler: the first {@value #STRATIFIED_DIMENSIONS} dimensions of a sample
 * are {@value #STRATIFIED_PAIRS} pairs of stratified points, the rest a {@link SplitMix64} stream.
 *
 * <p>Pair k (dimensions 2k and 2k + 1) of pixel p is point {@code sampleIndex} of a shuffled,
 * Owen-scrambled Sobol (0,2)-sequence ({@link OwenSobol}) with its own seed per pixel and pair:
 * the samples of a pixel cover each pair's unit square evenly (any 2^m of them from index 0 form
 * a (0,m,2)-net), while pairs and pixels stay independent of each other. Every value is uniform in
 * [0, 1), so every estimator stays unbiased. Pair 0 is the film position; the path tracer's first
 * vertex fills the other three (docs/performance.md): the light sample's point, (light choice,
 * BSDF lobe choice) and the BSDF direction.
 *
 * <p>{@link #get2D} at an odd dimension below {@value #STRATIFIED_DIMENSIONS} leaves that
 * dimension unused and takes the next whole pair. Dimension d ≥ {@value #STRATIFIED_DIMENSIONS}
 * is position d − {@value #STRATIFIED_DIMENSIONS} + 1 of the stream of (seed, pixel, sample
 * index), the same stream as {@link IndependentSampler}'s; there {@link #get2D} takes the next two
 * dimensions, since every dimension is independent anyway.
 */
public final class StratifiedSampler extends StreamSampler {
    /** Dimensions drawn from stratified points: the pixel position and the path tracer's first vertex. */
    public static final int STRATIFIED_DIMENSIONS = 8;
    static final int STRATIFIED_PAIRS = STRATIFIED_DIMENSIONS / 2;

    private final long seed;
    private final long pixelSeedBase;
    private int pixelSeed;
    private int sampleIndex;
    private int pair;              // the pair whose point is in pairX, pairY; -1 for none
    private int pairX, pairY;

    /** A sampler for the pixel samples of a render with this seed. */
    public StratifiedSampler(long seed) {
        super(STRATIFIED_DIMENSIONS);
        this.seed = seed;
        this.pixelSeedBase = SplitMix64.mix64(seed + SplitMix64.GOLDEN_GAMMA);
    }

    @Override
    public void startPixelSample(int px, int py, int sampleIndex) {
        this.stream = SplitMix64.streamSeed(seed, px, py, sampleIndex);
        this.pixelSeed = (int) SplitMix64.mix64(pixelSeedBase ^ SplitMix64.pixelKey(px, py));
        this.sampleIndex = sampleIndex;
        this.dimension = FIRST_INTEGRATOR_DIMENSION;
        this.pair = -1;
    }

    @Override
    public Sample2D getPixel2D(Sample2D dest) {
        return point(0, dest);
    }

    @Override
    public double get1D() {
        int d = dimension++;
        if (d < STRATIFIED_DIMENSIONS) {
            int p = d >> 1;
            if (p != pair) {
                long xy = OwenSobol.point(sampleIndex, pairSeed(p));
                pairX = (int) (xy >>> 32);
                pairY = (int) xy;
                pair = p;
            }
            return OwenSobol.toUnit((d & 1) == 0 ? pairX : pairY);
        }
        return streamValue(d);
    }

    @Override
    public Sample2D get2D(Sample2D dest) {
        int d = dimension;
        if (d < STRATIFIED_DIMENSIONS) {
            d = (d + 1) & ~1;                      // an odd dimension stays unused: pairs start on even ones
            if (d < STRATIFIED_DIMENSIONS) {
                dimension = d + 2;
                return point(d >> 1, dest);
            }
        }
        return streamPair(d, dest);
    }

    private int pairSeed(int p) {
        return OwenSobol.mix32(pixelSeed + p * 0x9e3779b9);
    }

    private Sample2D point(int p, Sample2D dest) {
        long xy = OwenSobol.point(sampleIndex, pairSeed(p));
        dest.u1 = OwenSobol.toUnit((int) (xy >>> 32));
        dest.u2 = OwenSobol.toUnit((int) xy);
        return dest;
    }
}
