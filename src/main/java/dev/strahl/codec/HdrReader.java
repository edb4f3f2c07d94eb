package dev.strahl.codec;

import dev.strahl.files.FileReads;
import static dev.strahl.codec.ImageFormatException.printable;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads Radiance RGBE pictures ({@code .hdr}, {@code .pic}), the usual format of environment maps.
 *
 * <p><b>The format.</b> A text header: a first line starting with {@code #?} (usually
 * {@code #?RADIANCE} or {@code #?RGBE}), then lines of {@code NAME=value} or comments, ended by an
 * empty line; {@code FORMAT} must be {@code 32-bit_rle_rgbe} if present (XYZE pictures are refused),
 * other lines (EXPOSURE, GAMMA, PRIMARIES, ...) are ignored: the pixels are taken as the
 * radiance they store. Then the resolution line, {@code -Y H +X W} for the usual top-to-bottom rows; the
 * other seven orientations ({@code +Y H +X W} bottom-up, {@code -X}, and the transposed
 * {@code ±X W ±Y H}) are turned into the same top-row-first layout. Then the scanlines, each either
 * flat (four bytes per pixel: mantissas r, g, b and a shared exponent e) or, for scanlines of 8 to
 * 32767 pixels, new-style run-length encoded: the bytes 2, 2 and the scanline length as a 15-bit
 * big-endian number, then the r, g, b and e bytes of the scanline one component after the other,
 * each as counts c &gt; 128 (a run: the next byte c − 128 times) and 1 ≤ c ≤ 128 (c literal
 * bytes). Old-style run-length encoding (a pixel 1, 1, 1, n repeating the one before) is not
 * decoded: such pixels are read as they are, as stb_image and Bruce Walter's widely copied
 * {@code rgbe.c} do; a file that then comes out short says it may be that.
 *
 * <p><b>Values.</b> A pixel (r, g, b, e) is (r, g, b) · 2^(e − 136), and black if e = 0, exactly
 * as Mitsuba 3 decodes RGBE (DESIGN.md §3; Radiance itself adds ½ to each mantissa); every such
 * value is a float, so the conversion is exact.
 *
 * <p>The result is a {@link ChannelImage} with channels R, G, B, top row first.
 */
public final class HdrReader {
    private static final int MAX_HEADER = 1 << 20;
    private static final String OLD_STYLE = " (or it uses old-style run-length encoding, pixels 1 1 1 n, which strahl does not read)";
    private static final Pattern RESOLUTION = Pattern.compile("([-+])([XY]) +(\\d{1,10}) +([-+])([XY]) +(\\d{1,10})");

    private HdrReader() {
    }

    /**
     * Reads a file.
     *
     * @param file a Radiance RGBE picture
     * @return its pixels, channels R, G, B
     * @throws ImageFormatException if the file is not a readable RGBE picture (one line: the file,
     *                              the header line or scanline and byte, what is wrong)
     * @throws IOException          if it cannot be read at all
     */
    public static ChannelImage read(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new ImageFormatException(file, "is a directory, not an HDR file");
        }
        long size = Files.size(file);
        FileReads.note(file);
        try (Input in = new Input(file, new BufferedInputStream(Files.newInputStream(file), 1 << 16))) {
            return read(in, size);
        }
    }

    private static ChannelImage read(Input in, long size) throws IOException {
        // ---- header: lines up to an empty one, then the resolution line
        int lineNumber = 1;
        String first = in.line(1);
        if (!first.startsWith("#?")) {
            throw in.error(1, "not a Radiance HDR file (expected a first line such as '#?RADIANCE', found '" + printable(first) + "')");
        }
        for (String line = in.line(++lineNumber); !line.isEmpty(); line = in.line(++lineNumber)) {
            if (line.startsWith("FORMAT=")) {
                String format = line.substring(7).trim();
                if (format.equals("32-bit_rle_xyze")) {
                    throw in.error(lineNumber, "XYZE pictures are not supported (strahl reads FORMAT=32-bit_rle_rgbe)");
                }
                if (!format.equals("32-bit_rle_rgbe")) {
                    throw in.error(lineNumber, "unknown pixel format '" + printable(format) + "' (strahl reads 32-bit_rle_rgbe)");
                }
            }
            if (in.position() > MAX_HEADER) {
                throw in.error(lineNumber, "no end of the header (an empty line) in the first " + MAX_HEADER + " bytes");
            }
        }
        String resolution = in.line(++lineNumber).trim();
        Matcher m = RESOLUTION.matcher(resolution);
        if (!m.matches() || m.group(2).equals(m.group(5))) {
            throw in.error(lineNumber, "bad resolution line '" + printable(resolution) + "' (expected e.g. '-Y 512 +X 1024')");
        }
        long scanlines = Long.parseLong(m.group(3));
        long length = Long.parseLong(m.group(6));
        if (scanlines < 1 || length < 1 || scanlines > Integer.MAX_VALUE || length > Integer.MAX_VALUE) {
            throw in.error(lineNumber, "bad image size in '" + resolution + "' (each must be from 1 to " + Integer.MAX_VALUE + ")");
        }
        boolean rowsAreScanlines = m.group(2).equals("Y");
        int width = (int) (rowsAreScanlines ? length : scanlines);
        int height = (int) (rowsAreScanlines ? scanlines : length);

        // every scanline takes some bytes: refuse what the file cannot hold before allocating
        long minScanline = length < 8 || length > 0x7fff ? 4 * length : Math.min(4 * length, 4 + 8 * ((length + 127) / 128));
        long left = size - in.position();
        if ((double) scanlines * minScanline > left) {
            throw in.error(lineNumber, "the file is truncated: " + scanlines + " scanlines of " + length + " pixels need at least "
                    + (long) ((double) scanlines * minScanline) + " bytes, but " + left + " follow the header"
                    + (looksOldStyle(in.peek(1 << 16), length) ? OLD_STYLE : ""));
        }
        ImageLimits.checkAllocation(in.file, width, height, 3, 4 * length);

        // ---- pixels
        float[] data = new float[3 * width * height];
        byte[] rgbe = new byte[(int) (4 * length)];
        boolean firstDown = (rowsAreScanlines ? m.group(1) : m.group(4)).equals("-");  // rows top to bottom
        boolean firstRight = (rowsAreScanlines ? m.group(4) : m.group(1)).equals("+");  // columns left to right
        boolean sawOldRun = false;
        for (int s = 0; s < scanlines; s++) {
            sawOldRun |= scanline(in, s, rgbe, (int) length, sawOldRun);
            for (int i = 0; i < length; i++) {
                int along = rowsAreScanlines ? i : s;      // column before flipping
                int across = rowsAreScanlines ? s : i;     // row before flipping
                int x = firstRight ? along : width - 1 - along;
                int y = firstDown ? across : height - 1 - across;
                int e = rgbe[4 * i + 3] & 0xff;
                int o = 3 * (y * width + x);
                for (int c = 0; c < 3; c++) {
                    data[o + c] = e == 0 ? 0f : Math.scalb((float) (rgbe[4 * i + c] & 0xff), e - 136);
                }
            }
        }
        return new ChannelImage(width, height, List.of("R", "G", "B"), data);
    }

    /** Reads scanline {@code s} into {@code rgbe} (r, g, b, e per pixel); true if it holds a 1,1,1,n pixel. */
    private static boolean scanline(Input in, int s, byte[] rgbe, int length, boolean sawOldRun) throws IOException {
        long start = in.position();
        String where = "scanline " + s + " (byte " + start + ")";
        if (length < 8 || length > 0x7fff) {
            return flat(in, rgbe, 0, length, where, sawOldRun);
        }
        in.bytes(rgbe, 0, 4, where, sawOldRun);
        if (rgbe[0] != 2 || rgbe[1] != 2 || (rgbe[2] & 0x80) != 0) {
            return flat(in, rgbe, 1, length, where, sawOldRun);    // the four bytes were the first pixel
        }
        int declared = (rgbe[2] & 0xff) << 8 | (rgbe[3] & 0xff);
        if (declared != length) {
            throw in.error(where + ": run-length encoded scanline of " + declared + " pixels, the image's are " + length);
        }
        for (int c = 0; c < 4; c++) {
            for (int i = 0; i < length; ) {
                int count = in.u8(where);
                if (count > 128) {
                    int run = count - 128;
                    if (run > length - i) {
                        throw in.error(where + ": a run of " + run + " goes past the end of the " + length + "-pixel scanline");
                    }
                    byte b = (byte) in.u8(where);
                    for (int k = 0; k < run; k++) {
                        rgbe[4 * (i++) + c] = b;
                    }
                } else {
                    if (count == 0) {
                        throw in.error(where + ": a count of 0 in the run-length code");
                    }
                    if (count > length - i) {
                        throw in.error(where + ": " + count + " literal bytes go past the end of the " + length + "-pixel scanline");
                    }
                    for (int k = 0; k < count; k++) {
                        rgbe[4 * (i++) + c] = (byte) in.u8(where);
                    }
                }
            }
        }
        return false;
    }

    private static boolean flat(Input in, byte[] rgbe, int from, int length, String where, boolean sawOldRun) throws IOException {
        boolean oldRun = from == 1 && rgbe[0] == 1 && rgbe[1] == 1 && rgbe[2] == 1;
        in.bytes(rgbe, 4 * from, 4 * (length - from), where, sawOldRun);
        for (int i = from; i < length && !oldRun; i++) {
            oldRun = rgbe[4 * i] == 1 && rgbe[4 * i + 1] == 1 && rgbe[4 * i + 2] == 1;
        }
        return oldRun;
    }

    /** True if the data start with a flat scanline and hold a pixel 1, 1, 1, n: an old-style repeat, probably. */
    private static boolean looksOldStyle(byte[] data, long length) {
        if (data.length >= 4 && length >= 8 && length <= 0x7fff && data[0] == 2 && data[1] == 2 && (data[2] & 0x80) == 0) {
            return false;                    // a new-style run-length encoded scanline
        }
        for (int i = 0; i + 3 < data.length; i += 4) {
            if (data[i] == 1 && data[i + 1] == 1 && data[i + 2] == 1) {
                return true;
            }
        }
        return false;
    }

    /** Bytes and header lines with the position, for messages; the end of the file is an {@link ImageFormatException}. */
    private static final class Input implements AutoCloseable {
        final Path file;
        private final InputStream in;
        private long position;

        Input(Path file, InputStream in) {
            this.file = file;
            this.in = in;
        }

        long position() {
            return position;
        }

        ImageFormatException error(int line, String message) {
            return new ImageFormatException(file, line, message);
        }

        ImageFormatException error(String message) {
            return new ImageFormatException(file, message);
        }

        /** A header line without its '\n' (ISO-8859-1, so any byte is a character). */
        String line(int number) throws IOException {
            StringBuilder sb = new StringBuilder();
            while (true) {
                int c = in.read();
                if (c < 0) {
                    throw error(number, "the file ends inside the header: it is truncated, or not a Radiance HDR file");
                }
                position++;
                if (c == '\n') {
                    return sb.toString();
                }
                if (sb.length() > MAX_HEADER) {
                    throw error(number, "a header line longer than " + MAX_HEADER + " bytes: not a Radiance HDR file");
                }
                sb.append((char) c);
            }
        }

        int u8(String where) throws IOException {
            int c = in.read();
            if (c < 0) {
                throw error(where + ": the file ends inside the scanline: it is truncated");
            }
            position++;
            return c;
        }

        void bytes(byte[] b, int off, int n, String where, boolean sawOldRun) throws IOException {
            int got = in.readNBytes(b, off, n);
            position += got;
            if (got < n) {
                throw error(where + ": the file ends inside the scanline: it is truncated" + (sawOldRun ? OLD_STYLE : ""));
            }
        }

        /** Up to {@code n} of the next bytes, without consuming them. */
        byte[] peek(int n) throws IOException {
            in.mark(n);
            byte[] b = in.readNBytes(n);
            in.reset();
            return b;
        }

        @Override
        public void close() throws IOException {
            in.close();
        }
    }
}
