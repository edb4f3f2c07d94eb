package dev.strahl.cli;

import dev.strahl.film.Film;
import dev.strahl.codec.ImageLimits;
import java.util.Locale;
import java.util.function.LongSupplier;

/** Refuses a film that cannot fit in the Java heap before anything is allocated ({@code render}, and {@code view} for every scene it shows). */
final class HeapCheck {
    /**
     * Bytes per pixel besides the film's sums and counts: the mean image handed out after each
     * pass and written at the end (r, g, b floats, copied once on the way) and the 8-bit image the
     * PNG encoder works on.
     */
    static final long IMAGE_BYTES_PER_PIXEL = 2 * 12 + 4;

    private HeapCheck() {}

    /** Bytes a render of this size needs for its film and images. */
    static long filmBytes(int width, int height) {
        return Film.bytesNeeded(width, height) + IMAGE_BYTES_PER_PIXEL * width * (long) height;
    }

    /**
     * Throws if a {@code width}×{@code height} render cannot fit in what the heap has left.
     *
     * @param heapMax  the heap's maximum ({@link Runtime#maxMemory()})
     * @param heapUsed bytes in use now
     */
    static void checkFilm(int width, int height, long heapMax, long heapUsed) {
        long need = filmBytes(width, height);
        long free = heapMax - heapUsed;
        if (need > free) {
            throw new IllegalArgumentException(String.format(Locale.ROOT,
                    "a %dx%d image needs %s for its film and image buffers, but the Java heap has %s free of at most %s;"
                            + " render a smaller image or give Java more memory (java -Xmx...)",
                    width, height, ImageLimits.bytes(need), ImageLimits.bytes(Math.max(0, free)), ImageLimits.bytes(heapMax)));
        }
    }

    /**
     * Checks against the running JVM's heap. What the heap has in use may be mostly garbage (a
     * viewer that has shown many frames), so a film that does not seem to fit is measured once more
     * after a collection before it is refused.
     */
    static void checkFilm(int width, int height) {
        Runtime rt = Runtime.getRuntime();
        checkFilm(width, height, rt.maxMemory(), () -> rt.totalMemory() - rt.freeMemory(), System::gc);
    }

    /**
     * Throws if a {@code width}×{@code height} render cannot fit in what the heap has left, asking
     * {@code collect} to free garbage and measuring again before it gives up.
     *
     * @param heapMax  the heap's maximum
     * @param heapUsed bytes in use now
     * @param collect  frees what it can (a garbage collection)
     */
    static void checkFilm(int width, int height, long heapMax, LongSupplier heapUsed, Runnable collect) {
        if (filmBytes(width, height) > heapMax - heapUsed.getAsLong()) {
            collect.run();
        }
        checkFilm(width, height, heapMax, heapUsed.getAsLong());
    }
}
