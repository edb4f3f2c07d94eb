package dev.strahl.film;

import dev.strahl.image.Image;
import dev.strahl.integrator.FeatureTracer;

/**
 * The HDR accumulation buffer of a render: per pixel the sums of r, g, b in double precision, the
 * sum of the squared luminance of the samples (for the per-pixel variance a denoiser needs), the
 * number of samples and, optionally, the sums of the feature buffers (albedo, normal, depth: see
 * {@link FeatureTracer}). Memory is laid out tile by tile ({@value #TILE}×{@value #TILE} pixels),
 * so that a worker rendering one tile writes one contiguous block.
 *
 * <p>Each pixel is written by one thread at a time (the renderer hands out disjoint tiles), and
 * its samples are added in sample-index order, so the sums do not depend on the thread count.
 * {@link #toImage()} may be called while rendering goes on: every pixel is then the mean of the
 * samples it had at that moment.
 */
public final class Film {
    /** Edge length of a tile in pixels. */
    public static final int TILE = 32;

    private final int width;
    private final int height;
    private final int tilesX;

    private final double[] sum;
    private final double[] sumSquares;
    /** Feature sums, {@value FeatureTracer#CHANNELS} per pixel, or null without feature buffers. */
    private final double[] features;
    private final int[] count;

    /**
     * An empty film.
     *
     * @param width  width in pixels, positive
     * @param height height in pixels, positive
     */
    public Film(int width, int height) {
        this(width, height, false);
    }

    /**
     * An empty film, with or without feature buffers.
     *
     * @param width    width in pixels, positive
     * @param height   height in pixels, positive
     * @param features whether to keep the sums of the feature buffers
     */
    public Film(int width, int height, boolean features) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("film size must be positive, got " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        this.tilesX = (width + TILE - 1) / TILE;
        int tilesY = (height + TILE - 1) / TILE;
        long pixels = (long) tilesX * tilesY * TILE * TILE;
        if ((features ? FeatureTracer.CHANNELS : 3) * pixels > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("film " + width + "x" + height + " is too large");
        }
        this.sum = new double[(int) (3 * pixels)];
        this.sumSquares = new double[(int) pixels];
        this.features = features ? new double[(int) (FeatureTracer.CHANNELS * pixels)] : null;
        this.count = new int[(int) pixels];
    }

    /**
     * Bytes a film of this size needs, to refuse absurd sizes before allocating.
     *
     * @param width  width in pixels
     * @param height height in pixels
     * @return the bytes of its buffers
     */
    public static long bytesNeeded(int width, int height) {
        return bytesNeeded(width, height, false);
    }

    /**
     * Bytes a film of this size needs, with or without feature buffers.
     *
     * @param width    width in pixels
     * @param height   height in pixels
     * @param features whether it keeps feature sums
     * @return the bytes of its buffers
     */
    public static long bytesNeeded(int width, int height, boolean features) {
        long tiles = (long) ((width + TILE - 1) / TILE) * ((height + TILE - 1) / TILE);
        return tiles * TILE * TILE * (4 * 8 + 4 + (features ? FeatureTracer.CHANNELS * 8 : 0));
    }

    /**
     * Whether the film keeps feature buffers.
     *
     * @return true if {@link #addFeatures} may be called
     */
    public boolean hasFeatures() {
        return features != null;
    }

    /**
     * The width.
     *
     * @return pixels
     */
    public int width() {
        return width;
    }

    /**
     * The height.
     *
     * @return pixels
     */
    public int height() {
        return height;
    }

    /**
     * Tiles per row.
     *
     * @return the count
     */
    public int tileCountX() {
        return tilesX;
    }

    /**
     * Tiles per column.
     *
     * @return the count
     */
    public int tileCountY() {
        return (height + TILE - 1) / TILE;
    }

    /**
     * Index of pixel (x, y) in the tile-major layout.
     *
     * @param x column, from 0
     * @param y row, from 0 at the top
     * @return the index for {@link #add}
     */
    public int pixelIndex(int x, int y) {
        int tile = (y / TILE) * tilesX + x / TILE;
        return tile * TILE * TILE + (y % TILE) * TILE + (x % TILE);
    }

    /**
     * Adds one sample's radiance to a pixel given by {@link #pixelIndex}. Not thread-safe: each
     * pixel must be written by one thread at a time.
     *
     * @param pixelIndex the pixel
     * @param r          red radiance
     * @param g          green radiance
     * @param b          blue radiance
     */
    public void add(int pixelIndex, double r, double g, double b) {
        int k = 3 * pixelIndex;
        sum[k] += r;
        sum[k + 1] += g;
        sum[k + 2] += b;
        double y = luminance(r, g, b);
        sumSquares[pixelIndex] += y * y;
        count[pixelIndex]++;
    }

    /**
     * Adds one sample's features ({@value FeatureTracer#CHANNELS} values from {@code f}) to a pixel; call it
     * with {@link #add} for the same sample. Not thread-safe, like {@link #add}.
     *
     * @param pixelIndex the pixel
     * @param f          albedo r, g, b, normal x, y, z, depth
     * @throws IllegalStateException if the film keeps no features
     */
    public void addFeatures(int pixelIndex, double[] f) {
        if (features == null) {
            throw new IllegalStateException("this film keeps no feature buffers");
        }
        int k = FeatureTracer.CHANNELS * pixelIndex;
        for (int i = 0; i < FeatureTracer.CHANNELS; i++) {
            features[k + i] += f[i];
        }
    }

    /** Rec. 709 luminance of linear RGB: the quantity whose variance the film keeps. */
    public static double luminance(double r, double g, double b) {
        return 0.2126 * r + 0.7152 * g + 0.0722 * b;
    }

    /** Samples taken over all pixels. */
    public long totalSamples() {
        long n = 0;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                n += sampleCount(x, y);
            }
        }
        return n;
    }

    /**
     * Number of samples pixel (x, y) has received.
     *
     * @param x column
     * @param y row
     * @return the count
     */
    public int sampleCount(int x, int y) {
        return count[pixelIndex(x, y)];
    }

    /**
     * Number of samples a pixel has received.
     *
     * @param pixelIndex the pixel, as given by {@link #pixelIndex}
     * @return the count
     */
    public int sampleCountAt(int pixelIndex) {
        return count[pixelIndex];
    }

    /**
     * The fewest samples any pixel has received: every pixel holds at least this many.
     *
     * @return the smallest sample count
     */
    public int minSampleCount() {
        int min = Integer.MAX_VALUE;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                min = Math.min(min, count[pixelIndex(x, y)]);
            }
        }
        return min;
    }

    /**
     * The saved state of pixel (x, y), for checkpoints: its r, g, b sums go into
     * {@code sumsDest[0..2]}, its sum of squared luminance into {@code sumsDest[3]}, with feature
     * buffers their {@value FeatureTracer#CHANNELS} sums into {@code sumsDest[4..10]}, and its sample count is
     * returned. Only consistent while nothing
     * renders into the film (between passes, or after the render).
     *
     * @param x        column
     * @param y        row
     * @param sumsDest receives the sums: 4 values, or 4 + {@value FeatureTracer#CHANNELS} with feature buffers
     * @return the pixel's sample count
     */
    public int pixelState(int x, int y, double[] sumsDest) {
        int p = pixelIndex(x, y);
        sumsDest[0] = sum[3 * p];
        sumsDest[1] = sum[3 * p + 1];
        sumsDest[2] = sum[3 * p + 2];
        sumsDest[3] = sumSquares[p];
        if (features != null) {
            System.arraycopy(features, FeatureTracer.CHANNELS * p, sumsDest, 4, FeatureTracer.CHANNELS);
        }
        return count[p];
    }

    /**
     * How many sums {@link #pixelState} writes per pixel.
     *
     * @return 4, or 4 + {@value FeatureTracer#CHANNELS} with feature buffers
     */
    public int stateSums() {
        return features != null ? 4 + FeatureTracer.CHANNELS : 4;
    }

    /**
     * Sets pixel (x, y) to a state saved by {@link #pixelState}: {@link #stateSums()} sums in the
     * order {@code pixelState} writes them.
     *
     * @param x       column
     * @param y       row
     * @param samples the pixel's sample count
     * @param sums    r, g, b, squared luminance and (with feature buffers) the feature sums
     * @throws IllegalArgumentException if {@code samples} is negative or too few sums are given
     */
    public void restorePixel(int x, int y, int samples, double[] sums) {
        if (samples < 0) {
            throw new IllegalArgumentException("sample count must not be negative, got " + samples);
        }
        if (sums.length < stateSums()) {
            throw new IllegalArgumentException(stateSums() + " sums per pixel expected, got " + sums.length);
        }
        int p = pixelIndex(x, y);
        sum[3 * p] = sums[0];
        sum[3 * p + 1] = sums[1];
        sum[3 * p + 2] = sums[2];
        sumSquares[p] = sums[3];
        if (features != null) {
            System.arraycopy(sums, 4, features, FeatureTracer.CHANNELS * p, FeatureTracer.CHANNELS);
        }
        count[p] = samples;
    }

    /**
     * The mean radiance per pixel, in row-major order; pixels without samples are black.
     *
     * @return a new image
     */
    public Image toImage() {
        float[] rgb = new float[3 * width * height];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int p = pixelIndex(x, y);
                int n = count[p];
                if (n > 0) {
                    double inv = 1.0 / n;
                    int o = 3 * (y * width + x);
                    rgb[o] = (float) (sum[3 * p] * inv);
                    rgb[o + 1] = (float) (sum[3 * p + 1] * inv);
                    rgb[o + 2] = (float) (sum[3 * p + 2] * inv);
                }
            }
        }
        return new Image(width, height, rgb);
    }

    /**
     * The variance of each pixel's mean luminance ({@link #varianceOfMean}) in r, g and b alike, in
     * row-major order like {@link #toImage()}.
     *
     * @return a new image
     */
    public Image varianceImage() {
        float[] v = new float[3 * width * height];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int o = 3 * (y * width + x);
                v[o] = v[o + 1] = v[o + 2] = (float) varianceOfMean(pixelIndex(x, y));
            }
        }
        return new Image(width, height, v);
    }

    /**
     * The variance of a pixel's mean luminance: its samples' unbiased variance divided by their
     * count, (Σy² − (Σy)²/n) / ((n − 1) n); 0 with fewer than two samples.
     *
     * @param pixelIndex the pixel, as given by {@link #pixelIndex}
     * @return the variance, not negative
     */
    public double varianceOfMean(int pixelIndex) {
        int n = count[pixelIndex];
        if (n < 2) {
            return 0;
        }
        double s = luminance(sum[3 * pixelIndex], sum[3 * pixelIndex + 1], sum[3 * pixelIndex + 2]);
        return Math.max(0, (sumSquares[pixelIndex] - s * s / n) / ((n - 1.0) * n));
    }

    /**
     * A pixel's mean luminance.
     *
     * @param pixelIndex the pixel, as given by {@link #pixelIndex}
     * @return the mean of its samples' luminance; 0 without samples
     */
    public double meanLuminance(int pixelIndex) {
        int n = count[pixelIndex];
        return n > 0 ? luminance(sum[3 * pixelIndex], sum[3 * pixelIndex + 1], sum[3 * pixelIndex + 2]) / n : 0;
    }

    /**
     * The mean of a feature buffer per pixel: albedo (offset 0) or normal (offset 3) as three
     * channels, or depth (offset 6) in all three channels.
     *
     * @param offset 0 (albedo), 3 (normal) or 6 (depth)
     * @return a new image
     * @throws IllegalStateException if the film keeps no features
     */
    public Image featureImage(int offset) {
        if (features == null) {
            throw new IllegalStateException("this film keeps no feature buffers");
        }
        if (offset != 0 && offset != 3 && offset != 6) {
            throw new IllegalArgumentException("feature offset must be 0, 3 or 6, got " + offset);
        }
        float[] v = new float[3 * width * height];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int p = pixelIndex(x, y);
                int n = count[p];
                if (n > 0) {
                    int o = 3 * (y * width + x);
                    int k = FeatureTracer.CHANNELS * p + offset;
                    for (int c = 0; c < 3; c++) {
                        v[o + c] = (float) (features[offset == 6 ? k : k + c] / n);
                    }
                }
            }
        }
        return new Image(width, height, v);
    }
}
