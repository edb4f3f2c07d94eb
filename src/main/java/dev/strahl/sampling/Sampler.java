package dev.strahl.sampling;

/**
 * The random numbers of one camera sample, in pbrt-v4's manner: a sampler is started for sample
 * {@code sampleIndex} of pixel (px, py) under the seed it was made with, and each call then takes
 * the next <em>dimension</em> (or pair of dimensions) of that sample. The numbers depend only on
 * (seed, pixel, sample index, dimension), never on the thread or the order pixels are rendered
 * in, so renders are bit-identical on any number of threads and a pixel can be replayed alone.
 *
 * <p><b>Dimensions.</b> Dimensions 0 and 1 are the film position within the pixel
 * ({@link #getPixel2D}); an integrator's calls number the rest from 2 on: {@link #get1D} takes
 * the next dimension, {@link #get2D} the next two. A stratified sampler gives its first
 * dimensions as pairs (2k, 2k + 1) of a stratified point set; a {@link #get2D} that would start
 * on an odd dimension there leaves that dimension unused and takes the next pair, so that two
 * numbers asked for together are always one stratified point, and two {@link #get1D} calls in a
 * row share a pair. So an integrator gets stratification by asking for what belongs together in
 * one call, and keeps its layout by drawing the same calls in the same order at every vertex,
 * whether or not a vertex uses all of them (the path tracer's layout: docs/performance.md).
 *
 * <p><b>No allocation.</b> {@link #get2D} and {@link #getPixel2D} write into a {@link Sample2D}
 * the caller owns. A returned record would allocate wherever the JIT does not inline the call and
 * scalar-replace it (the interpreter, C1, a call site that sees several samplers), and two
 * numbers packed into a {@code long} would carry 32 bits each where the streams give 53.
 *
 * <p>Mutable and not thread-safe: each worker thread owns one and restarts it per sample. Not
 * sealed: besides {@link StratifiedSampler} and {@link IndependentSampler}, the tests implement
 * it to record which code draws which dimension.
 */
public interface Sampler {

    /** The first dimension an integrator draws: 0 and 1 are the pixel's film position. */
    int FIRST_INTEGRATOR_DIMENSION = 2;

    /** Starts sample {@code sampleIndex} of pixel (px, py): the next call draws dimension {@value #FIRST_INTEGRATOR_DIMENSION}. */
    void startPixelSample(int px, int py, int sampleIndex);

    /** Dimensions 0 and 1 of the sample, the position within the pixel, into {@code dest}; draws nothing else. */
    Sample2D getPixel2D(Sample2D dest);

    /** The next dimension: a uniform number in [0, 1). */
    double get1D();

    /** The next pair of dimensions, into {@code dest}: uniform in [0, 1)², a stratified point where the sampler has one. */
    Sample2D get2D(Sample2D dest);
}
