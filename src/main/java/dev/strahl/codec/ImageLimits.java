package dev.strahl.codec;

import java.nio.file.Path;
import java.util.Locale;

/**
 * The size checks every image reader makes before it allocates pixel memory, so that an absurd
 * header is a one-line error and never an {@link OutOfMemoryError} or a negative array size.
 */
public final class ImageLimits {
    /** The largest Java array the readers allocate (a little below {@code Integer.MAX_VALUE}, as the JDK's own limit). */
    public static final long MAX_ARRAY = Integer.MAX_VALUE - 8;

    private ImageLimits() {
    }

    /**
     * Checks that a {@link ChannelImage} of this size can be allocated: at most {@link #MAX_ARRAY}
     * samples, and their bytes (plus {@code extraBytes} the decoder needs besides) within the heap
     * that is free, measured once more after a garbage collection if it looks too small.
     *
     * @param file       the file, for the message
     * @param width      width in pixels, from the file
     * @param height     height in pixels, from the file
     * @param channels   channels per pixel
     * @param extraBytes decoder buffers needed at the same time (0 if none)
     * @throws ImageFormatException if the image cannot be held
     */
    public static void checkAllocation(Path file, long width, long height, int channels, long extraBytes) throws ImageFormatException {
        if (width <= 0 || height <= 0) {
            throw new ImageFormatException(file, "image size must be positive, got " + width + "x" + height);
        }
        // width and height are at most 2^32 each in every format strahl reads: no overflow below
        double samples = (double) width * height * channels;
        if (samples > MAX_ARRAY) {
            throw new ImageFormatException(file, String.format(Locale.ROOT, "a %dx%d image with %d channel(s) is too large to load"
                    + " (%.3g samples; at most %d fit in one array)", width, height, channels, samples, MAX_ARRAY));
        }
        long need = (long) samples * Float.BYTES + extraBytes;
        if (need > free()) {
            System.gc();                      // what is in use may be mostly garbage: measure once more
            long free = free();
            if (need > free) {
                throw new ImageFormatException(file, String.format(Locale.ROOT, "a %dx%d image with %d channel(s) needs %s, but the"
                        + " Java heap has %s free of at most %s: give Java more memory (java -Xmx...)", width, height, channels,
                        bytes(need), bytes(free), bytes(Runtime.getRuntime().maxMemory())));
            }
        }
    }

    private static long free() {
        Runtime rt = Runtime.getRuntime();
        return rt.maxMemory() - (rt.totalMemory() - rt.freeMemory());
    }

    /** 1536 → "1.5 KiB", binary units as -Xmx counts them. */
    public static String bytes(long n) {
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
