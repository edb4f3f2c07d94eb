package dev.strahl.codec;

import dev.strahl.files.FileReads;
import static dev.strahl.codec.ImageFormatException.printable;

import dev.strahl.image.Image;
import java.io.IOException;
import java.math.BigInteger;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.regex.Pattern;

/**
 * Reads Portable Float Map images (the format of the reference renders and of
 * {@code strahl render -o x.pfm}).
 *
 * <p>The format: an ASCII header of four whitespace-separated tokens — {@code PF} (three
 * channels) or {@code Pf} (one channel), width, height, and a non-zero scale whose sign gives the
 * byte order (negative: little-endian, positive: big-endian) — then exactly one whitespace
 * character, then the pixels as 32-bit floats, rows from the bottom of the image to the top. The
 * magnitude of the scale is informational and ignored, as most readers do. A CR LF after the
 * scale is accepted as one line break; bytes after the pixel data are ignored.
 */
public final class PfmReader {

    /** A header longer than this is not a PFM header (real ones are about 20 bytes). */
    private static final int MAX_HEADER = 1024;
    private static final int CHUNK_BYTES = 1 << 20;
    private static final Pattern DECIMAL = Pattern.compile("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?");
    private static final Pattern UNSIGNED = Pattern.compile("\\+?\\d{1,10}");

    private PfmReader() {
    }

    /**
     * Reads a PFM file.
     *
     * @param file the file to read
     * @return the image, top row first; a one-channel ({@code Pf}) file gives a gray image (r = g = b)
     * @throws ImageFormatException if the file is not a well-formed PFM file (one line that starts with
     *                              the file name); sizes in the header are checked against the file
     *                              length and the heap before any pixel memory is allocated
     * @throws IOException          if the file cannot be read at all
     */
    public static Image read(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw malformed(file, "is a directory, not a PFM file");
        }
        FileReads.note(file);
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
            long size = ch.size();
            ByteBuffer head = ByteBuffer.allocate((int) Math.min(size, MAX_HEADER));
            readFully(ch, head, file);
            head.flip();
            Header hd = Header.parse(head, size, file);
            float[] rgb = new float[(int) (3 * hd.pixels())];
            ch.position(hd.dataOffset());
            readPixels(ch, hd, rgb, file);
            return new Image(hd.width(), hd.height(), rgb);
        }
    }

    /** Reads the pixel data in chunks, turning the bottom-up rows top-down and gray into rgb. */
    private static void readPixels(FileChannel ch, Header hd, float[] rgb, Path file) throws IOException {
        int rowFloats = hd.channels() * hd.width();
        int step = 3 / hd.channels();          // destination floats per source float
        long remaining = hd.dataBytes();
        ByteBuffer buf = ByteBuffer.allocate((int) Math.min(remaining, CHUNK_BYTES)).order(hd.order());
        float[] chunk = new float[buf.capacity() / Float.BYTES];
        int y = hd.height() - 1;
        int dst = 3 * y * hd.width();
        int inRow = 0;
        while (remaining > 0) {
            buf.clear().limit((int) Math.min(remaining, buf.capacity()));
            readFully(ch, buf, file);
            buf.flip();
            int n = buf.remaining() / Float.BYTES;
            buf.asFloatBuffer().get(chunk, 0, n);
            remaining -= buf.remaining();
            for (int i = 0; i < n; i++) {
                float v = chunk[i];
                rgb[dst] = v;
                if (step == 3) {
                    rgb[dst + 1] = v;
                    rgb[dst + 2] = v;
                }
                dst += step;
                if (++inRow == rowFloats) {  // next file row is the image row above
                    inRow = 0;
                    y--;
                    dst = 3 * y * hd.width();
                }
            }
        }
    }

    /** Fills {@code buf} to its limit; a file that ends early is malformed (or shrank while read). */
    private static void readFully(FileChannel ch, ByteBuffer buf, Path file) throws IOException {
        while (buf.hasRemaining()) {
            if (ch.read(buf) < 0) {
                throw malformed(file, "unexpected end of file");
            }
        }
    }

    private static ImageFormatException malformed(Path file, String message) {
        return new ImageFormatException(file, message);
    }

    /** The parsed header; {@code dataOffset} is where the pixels start. */
    private record Header(int channels, int width, int height, ByteOrder order, long dataOffset) {

        long pixels() {
            return (long) width * height;
        }

        long dataBytes() {
            return pixels() * channels * Float.BYTES;
        }

        /** Parses and validates the header in {@code head} (the first bytes of a file of {@code size} bytes). */
        static Header parse(ByteBuffer head, long size, Path file) throws IOException {
            Tokens t = new Tokens(head, size, file);
            String magic = t.next("the 'PF' or 'Pf' tag");
            int channels;
            if (magic.equals("PF")) {
                channels = 3;
            } else if (magic.equals("Pf")) {
                channels = 1;
            } else {
                throw malformed(file, "not a PFM file (expected 'PF' or 'Pf' at the start, found '" + printable(magic) + "')");
            }
            int width = dimension(t.next("the width"), "width", file);
            int height = dimension(t.next("the height"), "height", file);
            String scaleText = t.next("the scale");
            double scale = DECIMAL.matcher(scaleText).matches() ? Double.parseDouble(scaleText) : Double.NaN;
            if (!(Double.isFinite(scale) && scale != 0)) {
                throw malformed(file, "invalid PFM scale '" + printable(scaleText)
                        + "' (must be a non-zero number; negative means little-endian)");
            }
            long dataOffset = t.endOfHeader();

            // Check the claimed size against the file before trusting it with an allocation.
            // width·height < 2^62 cannot overflow; the byte count is formed only once it is known
            // to be at most the file length.
            long pixels = (long) width * height;
            long bytesPerPixel = (long) channels * Float.BYTES;
            long available = size - dataOffset;
            if (pixels > available / bytesPerPixel) {
                throw malformed(file, "truncated PFM data: a " + width + "x" + height + " image with "
                        + channels + " channel(s) needs " + BigInteger.valueOf(pixels).multiply(BigInteger.valueOf(bytesPerPixel))
                        + " bytes of pixels, but only " + available + " follow the header");
            }
            ImageLimits.checkAllocation(file, width, height, 3, 0);
            if (t.crlfAmbiguous() && available - 1 >= pixels * bytesPerPixel) {
                dataOffset++;                // "\r\n" after the scale is one line break
            }
            Header hd = new Header(channels, width, height,
                    scale < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN, dataOffset);
            return hd;
        }

        private static int dimension(String text, String what, Path file) throws IOException {
            long v = UNSIGNED.matcher(text).matches() ? Long.parseLong(text) : -1;
            if (v <= 0 || v > Integer.MAX_VALUE) {
                throw malformed(file, "invalid PFM " + what + " '" + printable(text) + "' (must be a positive integer)");
            }
            return (int) v;
        }
    }

    /** Splits the header bytes into whitespace-separated ASCII tokens. */
    private static final class Tokens {
        private final ByteBuffer head;
        private final long size;
        private final Path file;
        private int pos;

        Tokens(ByteBuffer head, long size, Path file) {
            this.head = head;
            this.size = size;
            this.file = file;
        }

        String next(String what) throws IOException {
            while (pos < head.limit() && isSpace(head.get(pos))) {
                pos++;
            }
            int start = pos;
            while (pos < head.limit() && !isSpace(head.get(pos))) {
                pos++;
            }
            if (pos == head.limit()) {       // a token must be followed by whitespace
                throw malformed(file, head.limit() < size
                        ? "not a PFM file (no valid header in the first " + MAX_HEADER + " bytes)"
                        : "truncated PFM header (the file ends before " + what + ")");
            }
            byte[] bytes = new byte[pos - start];
            head.get(start, bytes);
            return new String(bytes, StandardCharsets.ISO_8859_1);
        }

        /** Offset of the first pixel byte: one whitespace character after the last token. */
        long endOfHeader() {
            return pos + 1;
        }

        /** True if the header ends in "\r\n", which may be one line break or "\r" and a pixel byte. */
        boolean crlfAmbiguous() {
            return head.get(pos) == '\r' && pos + 1 < head.limit() && head.get(pos + 1) == '\n';
        }

        private static boolean isSpace(byte b) {
            return b == ' ' || b == '\t' || b == '\n' || b == '\r' || b == 0x0b || b == '\f';
        }
    }
}
