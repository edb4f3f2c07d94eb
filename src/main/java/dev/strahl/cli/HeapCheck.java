package dev.strahl.cli;

import dev.strahl.codec.ImageLimits;
import dev.strahl.denoise.net.NeuralDenoiser;
import dev.strahl.film.Film;
import java.util.Locale;
import java.util.function.LongSupplier;

/**
 * Refuses a render that cannot fit in the Java heap before anything is allocated ({@code render},
 * and {@code view} for every scene it shows): its film ({@link Film#bytesNeeded}, with the feature
 * sums when it keeps them: 7 doubles, 56 bytes a pixel) and every other buffer that holds a value
 * per pixel.
 */
final class HeapCheck {
    /**
     * Bytes per pixel besides the film's sums and counts: the mean image handed out after each
     * pass and written at the end (r, g, b floats, copied once on the way) and the 8-bit image the
     * PNG encoder works on.
     */
    static final long IMAGE_BYTES_PER_PIXEL = 2 * 12 + 4;
    /**
     * With feature buffers, besides the film's feature sums: the variance and the albedo, normal and
     * depth images the render hands out at its end (4 images of 3 floats) and the EXR writer's
     * copies of the 7 feature channels.
     */
    static final long FEATURE_BYTES_PER_PIXEL = 4 * 12 + 7 * 4;
    /**
     * The à-trous filter (denoise.AtrousFilter and render.Denoiser): its guides (8 floats and a flag),
     * its working images (14 floats), the weights of its 5×5 kernel (25 floats), its result (3 floats)
     * and the image made of it (3 floats), and the luminance variance (1 float). The network, the
     * default, needs {@link NeuralDenoiser#bytesNeeded} (its largest tile: at most a quarter of the
     * heap); a render that denoises is counted with the larger of the two.
     */
    static final long DENOISE_BYTES_PER_PIXEL = 8 * 4 + 1 + 14 * 4 + 25 * 4 + 3 * 4 + 12 + 4;

    private HeapCheck() {}

    /** Bytes a render of this size needs for its film and images, without feature buffers. */
    static long filmBytes(int width, int height) {
        return renderBytes(width, height, false, false);
    }

    /** Bytes a render of this size needs: its film and every per-pixel buffer, with the feature buffers and the denoiser's if it keeps them. */
    static long renderBytes(int width, int height, boolean features, boolean denoise) {
        long perPixel = IMAGE_BYTES_PER_PIXEL + (features ? FEATURE_BYTES_PER_PIXEL : 0);
        return Film.bytesNeeded(width, height, features) + perPixel * width * (long) height + (denoise ? denoiseBytes(width, height) : 0);
    }

    /** The larger of what the à-trous filter and the network need. */
    static long denoiseBytes(int width, int height) {
        return Math.max(DENOISE_BYTES_PER_PIXEL * width * (long) height, NeuralDenoiser.create().bytesNeeded(width, height));
    }

    /**
     * Throws if a {@code width}×{@code height} render without feature buffers cannot fit in what the heap has left.
     *
     * @param heapMax  the heap's maximum ({@link Runtime#maxMemory()})
     * @param heapUsed bytes in use now
     */
    static void checkFilm(int width, int height, long heapMax, long heapUsed) {
        check(width, height, renderBytes(width, height, false, false), heapMax, heapUsed);
    }

    private static void check(int width, int height, long need, long heapMax, long heapUsed) {
        long free = heapMax - heapUsed;
        if (need > free) {
            throw new IllegalArgumentException(String.format(Locale.ROOT,
                    "a %dx%d image needs %s for its film and image buffers, but the Java heap has %s free of at most %s;"
                            + " render a smaller image or give Java more memory (java -Xmx...)",
                    width, height, ImageLimits.bytes(need), ImageLimits.bytes(Math.max(0, free)), ImageLimits.bytes(heapMax)));
        }
    }

    /** {@link #checkRender} without feature buffers. */
    static void checkFilm(int width, int height) {
        checkRender(width, height, false, false);
    }

    /**
     * Checks against the running JVM's heap. What the heap has in use may be mostly garbage (a
     * viewer that has shown many frames), so a render that does not seem to fit is measured once
     * more after a collection before it is refused.
     */
    static void checkRender(int width, int height, boolean features, boolean denoise) {
        Runtime rt = Runtime.getRuntime();
        checkRender(width, height, features, denoise, rt.maxMemory(), () -> rt.totalMemory() - rt.freeMemory(), System::gc);
    }

    /**
     * Throws if a {@code width}×{@code height} render without feature buffers cannot fit in what
     * the heap has left, asking {@code collect} to free garbage and measuring again before it gives up.
     *
     * @param heapMax  the heap's maximum
     * @param heapUsed bytes in use now
     * @param collect  frees what it can (a garbage collection)
     */
    static void checkFilm(int width, int height, long heapMax, LongSupplier heapUsed, Runnable collect) {
        checkRender(width, height, false, false, heapMax, heapUsed, collect);
    }

    static void checkRender(int width, int height, boolean features, boolean denoise, long heapMax, LongSupplier heapUsed, Runnable collect) {
        long need = renderBytes(width, height, features, denoise);
        if (need > heapMax - heapUsed.getAsLong()) {
            collect.run();
        }
        check(width, height, need, heapMax, heapUsed.getAsLong());
    }
}
