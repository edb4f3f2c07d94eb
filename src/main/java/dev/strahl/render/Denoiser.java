package dev.strahl.render;

import dev.strahl.denoise.AtrousFilter;
import dev.strahl.image.Image;
import java.util.Objects;

/**
 * strahl's own denoiser, in pure Java: an edge-avoiding à-trous wavelet filter (Dammertz et al.
 * 2010) on the image divided by the albedo, its edges kept by the normal, depth and albedo
 * buffers and by each pixel's variance (the luminance weight of Schied et al. 2017). Render with
 * the feature buffers ({@link RenderSettings#withAovs}) for the best result; without them it
 * filters by colour and variance alone. Textures stay sharp (the albedo is divided out before
 * filtering and multiplied back after), the weights are normalised (no colour shift), and the
 * result is the same bits on any number of threads. docs/denoising.md shows what it does against
 * references and against Intel Open Image Denoise.
 *
 * <pre>{@code
 * RenderSettings s = RenderSettings.defaults().withSamplesPerPixel(16).withAovs(EnumSet.allOf(Aov.class));
 * try (RenderJob job = RenderJob.start(scene, s)) {
 *     RenderBuffers buffers = job.awaitBuffers();
 *     Image clean = Denoiser.create().denoise(buffers);
 * }
 * }</pre>
 */
public final class Denoiser {

    private Denoiser() {
    }

    /**
     * The denoiser. Stateless and safe to share; it filters on the common fork-join pool.
     *
     * @return a denoiser
     */
    public static Denoiser create() {
        return new Denoiser();
    }

    /**
     * Denoises a render's image, guided by whatever feature buffers it has and by its variance.
     *
     * @param buffers the image, its variance and feature buffers
     * @return the denoised image, of the same size
     */
    public Image denoise(RenderBuffers buffers) {
        Objects.requireNonNull(buffers, "buffers");
        Image color = buffers.color();
        int w = color.width();
        int h = color.height();
        float[] var = buffers.variance().rgb();
        float[] lumVar = new float[w * h];
        for (int p = 0; p < lumVar.length; p++) {
            lumVar[p] = var[3 * p];
        }
        var filter = new AtrousFilter(w, h, rgbOrNull(buffers.albedo()), rgbOrNull(buffers.normal()), rgbOrNull(buffers.depth()));
        return new Image(w, h, filter.filter(color.rgb(), lumVar));
    }

    private static float[] rgbOrNull(Image image) {
        return image == null ? null : image.rgb();
    }
}
