package dev.strahl.render;

import dev.strahl.film.Film;
import dev.strahl.image.Image;
import java.util.Objects;

/**
 * What a render leaves beside its image: the variance of every pixel's mean and the feature
 * buffers it was asked to keep ({@link RenderSettings.Output#aovs()}); everything the EXR output writes
 * and a {@link Denoiser} is guided by. All images have the size of the render.
 *
 * @param color    the image: the mean radiance of every pixel
 * @param variance the variance of every pixel's mean luminance (the same value in r, g and b; 0
 *                 where a pixel has fewer than two samples)
 * @param albedo   the mean {@linkplain Aov#ALBEDO albedo}, or null if not kept
 * @param normal   the mean {@linkplain Aov#NORMAL normal} (x, y, z in r, g, b; not renormalised),
 *                 or null if not kept
 * @param depth    the mean {@linkplain Aov#DEPTH depth} in r, g and b alike, or null if not kept
 * @param samples  the {@linkplain Aov#SPP number of samples} of every pixel in r, g and b alike, or null if not kept
 */
public record RenderBuffers(Image color, Image variance, Image albedo, Image normal, Image depth, Image samples) {

    /**
     * Checks that the images are there where they must be and have one size.
     *
     * @param color    the image
     * @param variance the variance of each pixel's mean luminance
     * @param albedo   the albedo, or null
     * @param normal   the normals, or null
     * @param depth    the depth, or null
     * @param samples  the samples per pixel, or null
     */
    public RenderBuffers {
        Objects.requireNonNull(color, "color");
        Objects.requireNonNull(variance, "variance");
        for (Image i : new Image[] {variance, albedo, normal, depth, samples}) {
            if (i != null && (i.width() != color.width() || i.height() != color.height())) {
                throw new IllegalArgumentException("buffer of " + i.width() + "x" + i.height() + " beside an image of "
                        + color.width() + "x" + color.height());
            }
        }
    }

    /**
     * Buffers without the sample counts.
     *
     * @param color    the image
     * @param variance the variance of each pixel's mean luminance
     * @param albedo   the albedo, or null
     * @param normal   the normals, or null
     * @param depth    the depth, or null
     */
    public RenderBuffers(Image color, Image variance, Image albedo, Image normal, Image depth) {
        this(color, variance, albedo, normal, depth, null);
    }

    /**
     * Buffers of an image alone: zero variance, no feature buffers (a denoiser then filters by
     * colour only).
     *
     * @param color the image
     * @return the buffers
     */
    public static RenderBuffers of(Image color) {
        return new RenderBuffers(color, new Image(color.width(), color.height(), new float[3 * color.width() * color.height()]),
                null, null, null);
    }

    /**
     * One feature buffer.
     *
     * @param aov which
     * @return its image, or null if it was not kept
     */
    public Image aov(Aov aov) {
        return switch (aov) {
            case ALBEDO -> albedo;
            case NORMAL -> normal;
            case DEPTH -> depth;
            case SPP -> samples;
        };
    }

    /**
     * The relative error of every pixel's mean, the quantity a noise threshold
     * ({@link RenderSettings#withNoiseThreshold}) bounds: the standard error of its mean luminance
     * over that luminance, or over 0.05 where the pixel is darker (docs/integrators.md, "Render until
     * clean"). From the image and the variance, so from floats: within their rounding of what the
     * render decides by.
     *
     * @return a new image with the error (0.01 = 1 %) in r, g and b alike
     */
    public Image relativeError() {
        float[] rgb = color.rgb(), var = variance.rgb();
        float[] e = new float[rgb.length];
        for (int i = 0; i < rgb.length; i += 3) {
            e[i] = e[i + 1] = e[i + 2] = (float) NoiseTarget.relativeError(Film.luminance(rgb[i], rgb[i + 1], rgb[i + 2]), var[i]);
        }
        return new Image(color.width(), color.height(), e);
    }

    /**
     * These buffers with another image (a denoised one), the rest unchanged.
     *
     * @param image the new image, of the same size
     * @return new buffers
     */
    public RenderBuffers withColor(Image image) {
        return new RenderBuffers(image, variance, albedo, normal, depth, samples);
    }
}
