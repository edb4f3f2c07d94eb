package dev.strahl.codec;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Counts the scans of a JPEG file before it is decoded. A progressive JPEG's decoder passes over
 * every block of the image once per scan, and nothing in the format bounds the number of scans: a
 * 125 kB file that repeats one refinement scan 2000 times over a 4000x4000 image took the JDK's
 * decoder 146 s. Real files have about ten scans (libjpeg's progressive script for colour has ten).
 */
final class JpegScans {
    /** More scans than any encoder writes: spectral selection and successive approximation for 3 components fit in far fewer. */
    static final int MAX_SCANS = 256;
    /** Pixels times scans the decoder may pass over: at about 5 ns each on a loaded 2-core machine, some 25 s. */
    static final double MAX_PIXEL_SCANS = 5e9;

    private JpegScans() {
    }

    /** Refuses a JPEG whose scans, over an image of {@code width} x {@code height}, would take the decoder too long. */
    static void check(Path file, int width, int height) throws IOException {
        int scans = count(file);
        double work = (double) width * height * scans;
        if (scans > MAX_SCANS || work > MAX_PIXEL_SCANS) {
            throw new ImageFormatException(file, String.format(java.util.Locale.ROOT, "a %dx%d JPEG image of %d scans: decoding it"
                    + " would pass over %.3g pixels (strahl decodes at most %d scans and %.0e pixels times scans)", width, height, scans,
                    work, MAX_SCANS, MAX_PIXEL_SCANS));
        }
    }

    /**
     * The start-of-scan markers of a JPEG file: segments are skipped by their lengths, the
     * entropy-coded data after a scan header byte by byte up to the next marker (FF followed by
     * neither a stuffed 00 nor a restart marker). Stops at the end of the image or of the file.
     */
    static int count(Path file) throws IOException {
        int scans = 0;
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file), 1 << 16)) {
            if (in.read() != 0xFF || in.read() != 0xD8) {
                return 0;
            }
            int b = in.read();
            while (b >= 0) {
                if (b != 0xFF) {                             // entropy-coded data (or junk): on to a marker
                    b = in.read();
                    continue;
                }
                int marker = in.read();
                while (marker == 0xFF) {                     // fill bytes
                    marker = in.read();
                }
                if (marker < 0 || marker == 0xD9) {
                    break;
                }
                if (marker == 0x00 || marker >= 0xD0 && marker <= 0xD7 || marker == 0x01) {
                    b = in.read();                           // a stuffed byte, a restart marker, TEM: no length
                    continue;
                }
                int length = in.read() << 8 | in.read();
                if (length < 2) {
                    break;
                }
                in.skipNBytes(length - 2);
                if (marker == 0xDA) {
                    scans++;
                }
                b = in.read();
            }
        } catch (java.io.EOFException e) {
            // cut short: the decoder will say so; the scans so far count
        }
        return scans;
    }
}
