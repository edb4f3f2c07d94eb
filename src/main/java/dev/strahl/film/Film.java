package dev.strahl.film;

import dev.strahl.image.Image;

/**
 * The HDR accumulation buffer of a render: per pixel the sums of r, g, b in double precision and
 * the number of samples. Memory is laid out tile by tile ({@value #TILE}×{@value #TILE} pixels),
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
    private final int[] count;

    /**
     * An empty film.
     *
     * @param width  width in pixels, positive
     * @param height height in pixels, positive
     */
    public Film(int width, int height) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("film size must be positive, got " + width + "x" + height);
        }
        this.width = width;
        this.height = height;
        this.tilesX = (width + TILE - 1) / TILE;
        int tilesY = (height + TILE - 1) / TILE;
        long pixels = (long) tilesX * tilesY * TILE * TILE;
        if (3 * pixels > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("film " + width + "x" + height + " is too large");
        }
        this.sum = new double[(int) (3 * pixels)];
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
        long tiles = (long) ((width + TILE - 1) / TILE) * ((height + TILE - 1) / TILE);
        return tiles * TILE * TILE * (3 * 8 + 4);
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
        count[pixelIndex]++;
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
     * {@code sumsDest[0..2]}, and its sample count is returned. Only consistent while nothing
     * renders into the film (between passes, or after the render).
     *
     * @param x        column
     * @param y        row
     * @param sumsDest receives the r, g, b sums
     * @return the pixel's sample count
     */
    public int pixelState(int x, int y, double[] sumsDest) {
        int p = pixelIndex(x, y);
        sumsDest[0] = sum[3 * p];
        sumsDest[1] = sum[3 * p + 1];
        sumsDest[2] = sum[3 * p + 2];
        return count[p];
    }

    /**
     * Sets pixel (x, y) to a state saved by {@link #pixelState}: the sums of its first
     * {@code samples} samples. Rendering then continues each pixel from the sample index it has
     * reached, so a restored film gives the same bits as one that was never saved.
     *
     * @param x       column
     * @param y       row
     * @param samples the pixel's sample count
     * @param r       the sum of its red values
     * @param g       the sum of its green values
     * @param b       the sum of its blue values
     * @throws IllegalArgumentException if {@code samples} is negative
     */
    public void restorePixel(int x, int y, int samples, double r, double g, double b) {
        if (samples < 0) {
            throw new IllegalArgumentException("sample count must not be negative, got " + samples);
        }
        int p = pixelIndex(x, y);
        sum[3 * p] = r;
        sum[3 * p + 1] = g;
        sum[3 * p + 2] = b;
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
}
