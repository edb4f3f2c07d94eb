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
        checkArraySize(file, width, height, channels);
        String shortfall = heapShortfall(width * height * channels * Float.BYTES + extraBytes);
        if (shortfall != null) {
            throw new ImageFormatException(file, String.format(Locale.ROOT, "a %dx%d image with %d channel(s) %s", width, height,
                    channels, shortfall));
        }
    }

    /**
     * Whether {@code need} bytes fit in the heap that is free (measured once more after a garbage
     * collection if they seem not to: what is in use may be mostly garbage).
     *
     * @param need bytes about to be allocated
     * @return null if they fit, else the end of a message: "needs 2.1 GiB, but the Java heap has 1.9
     *         GiB free of at most 2.0 GiB: give Java more memory (java -Xmx...)"
     */
    public static String heapShortfall(long need) {
        if (need <= free()) {
            return null;
        }
        System.gc();
        long free = free();
        return need <= free ? null : String.format(Locale.ROOT, "needs %s, but the Java heap has %s free of at most %s: give Java"
                + " more memory (java -Xmx...)", bytes(need), bytes(Math.max(0, free)), bytes(Runtime.getRuntime().maxMemory()));
    }

    /**
     * Checks that an image of this size has positive sides and fits in one Java array of floats,
     * whatever the heap.
     *
     * @param file     the file, for the message
     * @param width    width in pixels, from the file
     * @param height   height in pixels, from the file
     * @param channels channels per pixel
     * @throws ImageFormatException if it does not
     */
    public static void checkArraySize(Path file, long width, long height, int channels) throws ImageFormatException {
        if (width <= 0 || height <= 0) {
            throw new ImageFormatException(file, "image size must be positive, got " + width + "x" + height);
        }
        // width and height are at most 2^32 each in every format strahl reads: no overflow below
        double samples = (double) width * height * channels;
        if (samples > MAX_ARRAY) {
            throw new ImageFormatException(file, String.format(Locale.ROOT, "a %dx%d image with %d channel(s) is too large to load"
                    + " (%.3g samples; at most %d fit in one array)", width, height, channels, samples, MAX_ARRAY));
        }
    }

    /**
     * Checks a header's claim against the file: pixel data of {@code pixelBytes} cannot come out of
     * a file of {@code fileBytes} when its coding packs at most {@code ratio} bytes of pixels into
     * one byte of file (1 for raw samples; zlib about 1032). So a bomb, a few bytes that claim an
     * enormous image, is refused for what it is before the heap is even asked.
     *
     * @param file       the file, for the message
     * @param width      width from the header
     * @param height     height from the header
     * @param pixelBytes the bytes of pixel data the header implies
     * @param fileBytes  the file's length
     * @param ratio      the coding's largest ratio of pixel bytes to file bytes
     * @param coding     the coding's name, for the message ("ZIP compression")
     * @throws ImageFormatException if the file is too short for its claim
     */
    public static void checkFileHolds(Path file, long width, long height, double pixelBytes, long fileBytes, double ratio,
            String coding) throws ImageFormatException {
        if (pixelBytes > ratio * fileBytes) {
            throw new ImageFormatException(file, String.format(Locale.ROOT, "the header claims a %dx%d image (%.3g bytes of pixels),"
                    + " more than this %d-byte file can hold with %s: it is truncated, corrupt or a decompression bomb", width, height,
                    pixelBytes, fileBytes, coding));
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
