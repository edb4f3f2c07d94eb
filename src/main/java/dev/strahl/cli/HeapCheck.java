package dev.strahl.cli;

import dev.strahl.film.Film;
import java.util.Locale;

/** Refuses a film that cannot fit in the Java heap before anything is allocated. */
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
                    width, height, bytes(need), bytes(Math.max(0, free)), bytes(heapMax)));
        }
    }

    /** Checks against the running JVM's heap. */
    static void checkFilm(int width, int height) {
        Runtime rt = Runtime.getRuntime();
        checkFilm(width, height, rt.maxMemory(), rt.totalMemory() - rt.freeMemory());
    }

    /** 1536 → "1.5 KiB", binary units as -Xmx counts them. */
    static String bytes(long n) {
        String[] units = {"bytes", "KiB", "MiB", "GiB", "TiB"};
        double v = n;
        int u = 0;
        while (v >= 1024 && u < units.length - 1) {
            v /= 1024;
            u++;
        }
        return u == 0 ? n + " bytes" : String.format(Locale.ROOT, "%.1f %s", v, units[u]);
    }
}
