package dev.strahl.render;

import dev.strahl.film.Film;

/**
 * Adaptive sampling towards a noise threshold T ({@link RenderSettings.Sampling#noiseThreshold()}):
 * which pixels still take samples, decided at fixed sample counts from the film's sums alone.
 *
 * <p><b>The measure.</b> A pixel's error is e = σ / max(μ, {@value #FLOOR}): σ² is the variance of
 * the mean of its samples' luminance ({@link Film#varianceOfMean}: their unbiased variance over their
 * count), μ that mean. So e is the relative standard error of the pixel's mean, and a pixel darker
 * than the floor is held to the absolute error T·{@value #FLOOR} instead (a black pixel is done at once).
 *
 * <p><b>The decisions.</b> Every pixel first takes {@value #MIN_SAMPLES} samples. Then, at the
 * boundaries {@link #nextBoundary} gives (48, 64, … every 16 samples up to 128, then every quarter
 * of the count so far in multiples of 16), each pixel still rendering is found converged when the
 * largest e in the {@value #WINDOW}×{@value #WINDOW} pixels around it is at most T: a pixel stops only
 * when its neighbours look converged too, so a rare bright path one of them has seen keeps the
 * neighbourhood sampling. A converged pixel takes no more samples (a tile whose pixels all have is
 * skipped); the render ends when no pixel is left, at the sample count or at the time limit.
 *
 * <p><b>Same bits.</b> A decision depends only on the film's sums at a boundary, which are the same
 * bits on any thread count, pass size or cluster; every pixel still rendering holds the boundary's
 * count, so a pass goes on from one sample index for all. The state is the last boundary and the
 * mask of pixels still rendering: a checkpoint saves both ({@link #state()}), since a pass that has
 * gone past the boundary has overwritten the sums the mask was decided from.
 */
final class NoiseTarget {
    /** Samples every pixel takes before the first decision. */
    static final int MIN_SAMPLES = 32;
    /** The luminance below which a pixel's error is measured against this instead of its mean (1 is white in a PNG). */
    static final double FLOOR = 0.05;
    /** Edge of the square of pixels whose largest error decides a pixel. */
    static final int WINDOW = 5;

    private final Film film;
    private final double threshold;
    /** Per pixel, in the film's layout: whether it still takes samples (read by render threads during a pass). */
    private final boolean[] rendering;
    private final int[] renderingInTile;
    /** The last boundary decided at; 0 before the first (guarded by this). */
    private int boundary;
    private int left;
    private volatile double convergedFraction;
    /** Samples the film will hold at the end as estimated at the last decision; 0 before the first. */
    private volatile double estimatedTotal;

    /** A fresh render: every pixel renders. */
    NoiseTarget(Film film, double threshold) {
        this(film, threshold, 0, null);
    }

    /**
     * A render resumed at a boundary with its mask ({@link State}), or fresh with {@code mask} null.
     *
     * @throws IllegalArgumentException if the mask is not of the film's size
     */
    NoiseTarget(Film film, double threshold, int boundary, boolean[] mask) {
        if (!(threshold > 0)) {
            throw new IllegalArgumentException("a noise target needs a positive threshold, got " + threshold);
        }
        this.film = film;
        this.threshold = threshold;
        this.boundary = boundary;
        int tiles = film.tileCountX() * film.tileCountY();
        this.rendering = new boolean[tiles * Film.TILE * Film.TILE];
        this.renderingInTile = new int[tiles];
        if (mask != null && mask.length != film.width() * film.height()) {
            throw new IllegalArgumentException("a mask of " + mask.length + " pixels for a film of " + film.width() + "x" + film.height());
        }
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                if (mask == null || mask[y * film.width() + x]) {
                    int p = film.pixelIndex(x, y);
                    rendering[p] = true;
                    renderingInTile[p / (Film.TILE * Film.TILE)]++;
                    left++;
                }
            }
        }
        convergedFraction = 1 - left / ((double) film.width() * film.height());
    }

    /**
     * The relative error of a pixel's mean: the one definition of what the threshold bounds.
     *
     * @param mean           the mean luminance of its samples
     * @param varianceOfMean the variance of that mean
     * @return σ / max(μ, {@value #FLOOR})
     */
    static double relativeError(double mean, double varianceOfMean) {
        return Math.sqrt(varianceOfMean) / Math.max(mean, FLOOR);
    }

    /** The boundary after {@code b}: {@value #MIN_SAMPLES} first, then steps of 16 up to 128, then of b/4 in multiples of 16. */
    static int nextBoundary(int b) {
        return b < MIN_SAMPLES ? MIN_SAMPLES : b + 16 * Math.max(1, b / 64);
    }

    /** The count the pixels still rendering go to next: the next boundary, or {@code spp} if it comes first. */
    synchronized int goal(int spp) {
        return Math.min(spp, nextBoundary(boundary));
    }

    /** Whether reaching {@link #goal} means a decision (the next boundary is not beyond {@code spp}). */
    synchronized boolean decidesAt(int goal) {
        return goal == nextBoundary(boundary);
    }

    /** The fewest samples a pixel still rendering holds; {@link Integer#MAX_VALUE} when none is left. */
    synchronized int start() {
        int min = Integer.MAX_VALUE;
        for (int p = 0; p < rendering.length; p++) {
            if (rendering[p]) {
                min = Math.min(min, film.sampleCountAt(p));
            }
        }
        return min;
    }

    /** Whether a pixel (its film index) takes samples in this pass. */
    boolean renders(int pixelIndex) {
        return rendering[pixelIndex];
    }

    /** Whether any pixel of a tile (numbered row by row) takes samples in this pass. */
    boolean rendersTile(int tile) {
        return renderingInTile[tile] > 0;
    }

    /**
     * Decides at the next boundary, which every pixel still rendering has reached: those whose
     * window's largest error is at most the threshold stop. Call it only while nothing renders
     * into the film.
     *
     * @param spp the most samples a pixel may take (for the estimate of what is left)
     * @return whether any pixel is left
     */
    synchronized boolean decide(int spp) {
        boundary = nextBoundary(boundary);
        int w = film.width(), h = film.height(), r = WINDOW / 2;
        float[][] err = new float[WINDOW][w];          // the errors of the last WINDOW rows, a ring
        double total = 0;
        for (int y = -r; y < h; y++) {
            if (y + r < h) {
                float[] row = err[(y + r) % WINDOW];
                for (int x = 0; x < w; x++) {
                    int p = film.pixelIndex(x, y + r);
                    row[x] = (float) relativeError(film.meanLuminance(p), film.varianceOfMean(p));
                }
            }
            if (y < 0) {
                continue;
            }
            for (int x = 0; x < w; x++) {
                int p = film.pixelIndex(x, y);
                int n = film.sampleCountAt(p);
                total += n;
                if (!rendering[p]) {
                    continue;
                }
                double e = 0;
                for (int yy = Math.max(0, y - r); yy <= Math.min(h - 1, y + r); yy++) {
                    float[] row = err[yy % WINDOW];
                    for (int xx = Math.max(0, x - r); xx <= Math.min(w - 1, x + r); xx++) {
                        e = Math.max(e, row[xx]);
                    }
                }
                if (e <= threshold) {
                    rendering[p] = false;
                    renderingInTile[p / (Film.TILE * Film.TILE)]--;
                    left--;
                } else {
                    // e falls as 1/sqrt(n): about n·(e/T)² samples in all, no more than spp
                    total += Math.max(0, Math.min(spp, n * (e / threshold) * (e / threshold)) - n);
                }
            }
        }
        convergedFraction = 1 - left / ((double) w * h);
        estimatedTotal = total;
        return left > 0;
    }

    /** Share of the pixels found converged so far (0 before the first decision). */
    double convergedFraction() {
        return convergedFraction;
    }

    /** Samples the film will hold at the end, as estimated at the last decision; 0 before the first. */
    double estimatedTotalSamples() {
        return estimatedTotal;
    }

    /**
     * What a checkpoint saves: the last boundary, and per pixel row by row whether it still renders.
     *
     * @param boundary the last boundary decided at (0 before the first)
     * @param mask     per pixel, row by row: true if it still takes samples
     */
    record State(int boundary, boolean[] mask) {
        /** The mask a bit per pixel, most significant first, the last byte padded with zeros: a checkpoint's form. */
        byte[] packedMask() {
            byte[] bytes = new byte[(mask.length + 7) / 8];
            for (int i = 0; i < mask.length; i++) {
                if (mask[i]) {
                    bytes[i >> 3] |= (byte) (0x80 >>> (i & 7));
                }
            }
            return bytes;
        }

        /** The state of a boundary and the first {@code pixels} bits of a {@link #packedMask}. */
        static State unpacked(int boundary, byte[] bits, int pixels) {
            boolean[] mask = new boolean[pixels];
            for (int i = 0; i < pixels; i++) {
                mask[i] = (bits[i >> 3] & (0x80 >>> (i & 7))) != 0;
            }
            return new State(boundary, mask);
        }
    }

    /** The state now; consistent while nothing renders into the film (a checkpoint holds the workers). */
    synchronized State state() {
        boolean[] mask = new boolean[film.width() * film.height()];
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                mask[y * film.width() + x] = rendering[film.pixelIndex(x, y)];
            }
        }
        return new State(boundary, mask);
    }
}
