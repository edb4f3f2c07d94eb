package dev.strahl.render;

import dev.strahl.denoise.AtrousFilter;
import dev.strahl.denoise.net.NeuralDenoiser;
import dev.strahl.image.Image;
import java.util.Objects;

/**
 * Denoisers for a render's image, in pure Java. Render with the feature buffers
 * ({@link RenderSettings#withAovs}: albedo and normal) for the best result.
 * <ul>
 *   <li>{@link #create()}, the default: the trained U-Net of Intel Open Image Denoise 2.5.1 (its
 *       weights for HDR colour, Apache-2.0, shipped inside strahl) with OIDN's preparation of the
 *       input and output, matching OIDN's own result within 1e-4 per pixel. It uses the albedo
 *       and normal buffers when present (the normal only together with the albedo). About 0.8
 *       CPU-seconds for a 512x512 image (the first call in a process also reads the weights
 *       and compiles the code: about 3; also about 0.9 after a render in the same JVM:
 *       docs/denoising.md, Time); large images are denoised in overlapping tiles, so
 *       memory stays bounded (at most a quarter of the heap).</li>
 *   <li>{@link #atrous()}: an edge-avoiding à-trous wavelet filter (Dammertz et al. 2010) on
 *       the image divided by the albedo, guided by the normal, depth and albedo buffers and by
 *       each pixel's variance (Schied et al. 2017); about 3x the network's error and
 *       noticeably blurrier. It reads no weights, so its first call is cheaper (about 1.7
 *       CPU-seconds at 512x512); after that about 0.8.</li>
 * </ul>
 * Both are deterministic: the same bits on any number of threads (they run on the common
 * fork-join pool). docs/denoising.md compares them with each other, with OIDN and with references.
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
    private final boolean network;

    private Denoiser(boolean network) {
        this.network = network;
    }

    /**
     * The default denoiser: Intel Open Image Denoise's trained network. Stateless and safe to
     * share; the weights are read from strahl's jar when first used (about 1.8 MB per network).
     *
     * @return the denoiser
     */
    public static Denoiser create() {
        return new Denoiser(true);
    }

    /**
     * The edge-avoiding à-trous filter: blurrier than {@link #create()}, with no weights to read.
     * Stateless and safe to share.
     *
     * @return the denoiser
     */
    public static Denoiser atrous() {
        return new Denoiser(false);
    }

    /**
     * Denoises a render's image, guided by whatever feature buffers it has (and, for the à-trous
     * filter, its variance).
     *
     * @param buffers the image, its variance and feature buffers
     * @return the denoised image, of the same size
     * @throws java.io.UncheckedIOException if the network's weights are missing from strahl's jar
     *                                      or damaged (its message is one line naming the file)
     */
    public Image denoise(RenderBuffers buffers) {
        Objects.requireNonNull(buffers, "buffers");
        Image color = buffers.color();
        int w = color.width();
        int h = color.height();
        if (network) {
            float[] clean = NeuralDenoiser.create().denoise(w, h, color.rgb(), rgbOrNull(buffers.albedo()), rgbOrNull(buffers.normal()));
            return new Image(w, h, clean);
        }
        float[] var = buffers.variance().rgb();
        float[] lumVar = new float[w * h];
        for (int p = 0; p < lumVar.length; p++) {
            lumVar[p] = var[3 * p];
        }
        var filter = new AtrousFilter(w, h, rgbOrNull(buffers.albedo()), rgbOrNull(buffers.normal()), rgbOrNull(buffers.depth()));
        return new Image(w, h, filter.filter(color.rgb(), lumVar));
    }

    /**
     * What it is, for messages: "Open Image Denoise's network" or "the à-trous filter".
     *
     * @return its name
     */
    @Override
    public String toString() {
        return network ? "Open Image Denoise's network" : "the à-trous filter";
    }

    private static float[] rgbOrNull(Image image) {
        return image == null ? null : image.rgb();
    }
}
