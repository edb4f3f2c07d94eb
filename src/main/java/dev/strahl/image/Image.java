package dev.strahl.image;

import java.util.Arrays;

/**
 * A linear HDR image: {@code rgb} holds r, g, b floats per pixel, row by row from the top-left
 * pixel (film y grows downwards). Immutable: the array is copied in and out.
 *
 * @param width  width in pixels, positive
 * @param height height in pixels, positive
 * @param rgb    3 · width · height floats, linear radiance
 */
public record Image(int width, int height, float[] rgb) {

    /**
     * Checks the size against the array and copies it.
     *
     * @param width  width in pixels, positive
     * @param height height in pixels, positive
     * @param rgb    3 · width · height floats, linear radiance
     */
    public Image {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("image size must be positive, got " + width + "x" + height);
        }
        if (rgb.length != 3L * width * height) {
            throw new IllegalArgumentException("expected " + 3L * width * height + " floats for " + width + "x" + height + ", got " + rgb.length);
        }
        rgb = rgb.clone();
    }

    /**
     * The pixels: r, g, b per pixel, row by row from the top-left pixel, linear radiance.
     *
     * @return a copy
     */
    @Override
    public float[] rgb() {
        return rgb.clone();
    }

        /**
     * One channel of one pixel.
     *
     * @param x column, from 0
     * @param y row, from 0 at the top
     * @param c channel: 0 = r, 1 = g, 2 = b
     * @return the value
     */
    public float get(int x, int y, int c) {
        return rgb[3 * (y * width + x) + c];
    }

    /**
     * The mean of each channel over the image.
     *
     * @return {r, g, b}
     */
    public double[] mean() {
        double[] m = new double[3];
        for (int i = 0; i < rgb.length; i++) {
            m[i % 3] += rgb[i];
        }
        int n = width * height;
        return new double[] {m[0] / n, m[1] / n, m[2] / n};
    }

    /**
     * The image box-filtered by an integer factor (each output pixel is the mean of factor² pixels).
     *
     * @param factor divides both width and height
     * @return the smaller image
     */
    public Image downsample(int factor) {
        if (factor <= 0 || width % factor != 0 || height % factor != 0) {
            throw new IllegalArgumentException("cannot downsample " + width + "x" + height + " by " + factor);
        }
        int w = width / factor, h = height / factor;
        float[] out = new float[3 * w * h];
        double norm = 1.0 / (factor * factor);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                for (int c = 0; c < 3; c++) {
                    double s = 0;
                    for (int dy = 0; dy < factor; dy++) {
                        for (int dx = 0; dx < factor; dx++) {
                            s += get(x * factor + dx, y * factor + dy, c);
                        }
                    }
                    out[3 * (y * w + x) + c] = (float) (s * norm);
                }
            }
        }
        return new Image(w, h, out);
    }

    /**
     * Relative mean squared error against a reference: mean over pixels and channels of
     * (this − ref)² / (ref² + 0.01), the measure used with the reference images.
     *
     * @param ref the reference, of the same size
     * @return the relative MSE
     */
    public double relMse(Image ref) {
        if (ref.width != width || ref.height != height) {
            throw new IllegalArgumentException("sizes differ: " + width + "x" + height + " vs " + ref.width + "x" + ref.height);
        }
        double s = 0;
        for (int i = 0; i < rgb.length; i++) {
            double d = rgb[i] - ref.rgb[i];
            s += d * d / ((double) ref.rgb[i] * ref.rgb[i] + 0.01);
        }
        return s / rgb.length;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Image i && i.width == width && i.height == height && Arrays.equals(i.rgb, rgb);
    }

    @Override
    public int hashCode() {
        return 31 * (31 * width + height) + Arrays.hashCode(rgb);
    }

    @Override
    public String toString() {
        return "Image[" + width + "x" + height + "]";
    }
}
