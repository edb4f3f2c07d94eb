package dev.strahl.codec;

import dev.strahl.files.AtomicFile;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/**
 * Writes Radiance RGBE pictures ({@code .hdr}) that {@link HdrReader}, Mitsuba 3, Radiance and the
 * usual tools read: header {@code #?RADIANCE}, {@code FORMAT=32-bit_rle_rgbe}, resolution
 * {@code -Y H +X W} (rows top to bottom), scanlines run-length encoded (new style) where the width
 * allows it (8 to 32767 pixels), flat otherwise.
 *
 * <p><b>Encoding.</b> A pixel becomes mantissas m = round(v · 2^(136 − e)) for the exponent e that
 * puts the largest component's mantissa in 128..255 (rounded to nearest: the reader's decoding
 * m · 2^(e − 136) then errs by at most half a step, and a step is at most 2^-7 of the largest
 * component);
 * components far below the largest lose their low bits, as in every RGBE file. Values below
 * 2^-128 use e = 1 with smaller mantissas, and round to black below 2^-136. Values that RGBE cannot
 * hold — negative, NaN, infinite, or from 255·2^119 (about 1.7e38) up — are an
 * {@link IllegalArgumentException} naming the pixel: an environment map with them is a bug in what
 * made it, not something to hide by clamping.
 */
public final class HdrWriter {
    private static final int MIN_RUN = 4;

    private HdrWriter() {
    }

    /**
     * Writes a file atomically ({@link AtomicFile}).
     *
     * @param out    the file
     * @param width  width in pixels, positive
     * @param height height in pixels, positive
     * @param rgb    3 · width · height linear values, r, g, b per pixel, rows from the top (not changed)
     * @throws IOException if writing fails (the target is then unchanged)
     */
    public static void write(Path out, int width, int height, float[] rgb) throws IOException {
        check(width, height, rgb);
        AtomicFile.write(out, os -> write(os, width, height, rgb));
    }

    /**
     * Writes an image's colour ({@link ChannelImage#rgb()}) atomically.
     *
     * @param out   the file
     * @param image an image with R, G, B or Y channels
     * @throws IOException if writing fails (the target is then unchanged)
     */
    public static void write(Path out, ChannelImage image) throws IOException {
        write(out, image.width(), image.height(), image.rgb().data());
    }

    /**
     * Writes the picture to a stream, which is not closed.
     *
     * @param os     the stream
     * @param width  width in pixels, positive
     * @param height height in pixels, positive
     * @param rgb    3 · width · height linear values, rows from the top
     * @throws IOException if the stream fails
     */
    public static void write(OutputStream os, int width, int height, float[] rgb) throws IOException {
        check(width, height, rgb);
        os.write(("#?RADIANCE\n# written by strahl\nFORMAT=32-bit_rle_rgbe\n\n-Y " + height + " +X " + width + "\n")
                .getBytes(StandardCharsets.US_ASCII));
        byte[] line = new byte[4 * width];
        byte[] encoded = new byte[4 + 4 * (width + width / 128 + 1)];
        boolean rle = width >= 8 && width <= 0x7fff;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                encode(rgb, 3 * (y * width + x), line, 4 * x, x, y);
            }
            if (!rle) {
                os.write(line);
                continue;
            }
            int n = 0;
            encoded[n++] = 2;
            encoded[n++] = 2;
            encoded[n++] = (byte) (width >> 8);
            encoded[n++] = (byte) width;
            for (int c = 0; c < 4; c++) {
                n = runLength(line, c, width, encoded, n);
            }
            os.write(encoded, 0, n);
        }
    }

    private static void check(int width, int height, float[] rgb) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("image size must be positive, got " + width + "x" + height);
        }
        if (rgb.length != 3L * width * height) {
            throw new IllegalArgumentException("expected " + 3L * width * height + " values for " + width + "x" + height + ", got "
                    + rgb.length);
        }
    }

    /** The RGBE bytes of the pixel at {@code rgb[i..i+2]} into {@code out[o..o+3]}. */
    static void encode(float[] rgb, int i, byte[] out, int o, int x, int y) {
        float max = 0;
        for (int c = 0; c < 3; c++) {
            float v = rgb[i + c];
            if (!(v >= 0) || v == Float.POSITIVE_INFINITY) {
                throw new IllegalArgumentException("pixel (" + x + ", " + y + ") has " + "RGB".charAt(c) + " = " + v
                        + ": RGBE holds only finite values >= 0");
            }
            max = Math.max(max, v);
        }
        // the exponent that puts max · 2^(136 − e) in [128, 256); at least 1 (0 means black)
        int e = max < 0x1p-128f ? 1 : Math.getExponent(max) + 129;
        long[] m = mantissas(rgb, i, e);
        if (Math.max(m[0], Math.max(m[1], m[2])) > 255) {  // rounded up to 256: one exponent more
            e++;
            m = mantissas(rgb, i, e);
        }
        if (e > 255) {
            throw new IllegalArgumentException("pixel (" + x + ", " + y + ") has a value of " + max
                    + ", beyond what RGBE holds (less than 255·2^119, about 1.7e38)");
        }
        if (m[0] == 0 && m[1] == 0 && m[2] == 0) {
            e = 0;                                          // black
        }
        out[o] = (byte) m[0];
        out[o + 1] = (byte) m[1];
        out[o + 2] = (byte) m[2];
        out[o + 3] = (byte) e;
    }

    private static long[] mantissas(float[] rgb, int i, int e) {
        double scale = Math.scalb(1.0, 136 - e);
        return new long[] {Math.round(rgb[i] * scale), Math.round(rgb[i + 1] * scale), Math.round(rgb[i + 2] * scale)};
    }

    /** Run-length codes component {@code c} of a scanline: runs of 4 to 127 equal bytes, literals of up to 128. */
    private static int runLength(byte[] line, int c, int width, byte[] out, int n) {
        int i = 0;
        while (i < width) {
            int run = 1;
            while (i + run < width && run < 127 && line[4 * (i + run) + c] == line[4 * i + c]) {
                run++;
            }
            if (run >= MIN_RUN) {
                out[n++] = (byte) (128 + run);
                out[n++] = line[4 * i + c];
                i += run;
                continue;
            }
            // literals up to the next run of MIN_RUN (or 128 bytes)
            int start = i;
            while (i < width && i - start < 128) {
                int r = 1;
                while (i + r < width && r < MIN_RUN && line[4 * (i + r) + c] == line[4 * i + c]) {
                    r++;
                }
                if (r >= MIN_RUN) {
                    break;
                }
                i++;
            }
            out[n++] = (byte) (i - start);
            for (int k = start; k < i; k++) {
                out[n++] = line[4 * k + c];
            }
        }
        return n;
    }
}
