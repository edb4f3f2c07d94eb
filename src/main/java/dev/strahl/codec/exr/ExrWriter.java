package dev.strahl.codec.exr;

import dev.strahl.files.AtomicFile;
import dev.strahl.codec.ChannelImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;
import java.util.zip.Deflater;

/**
 * Writes single-part scanline OpenEXR files that the OpenEXR library (and {@link ExrReader}) read:
 * any list of named channels, HALF (the default) or FLOAT samples, compressed with ZIP (the
 * default: 16 lines per chunk), ZIPS, RLE or NONE. The data and display windows are
 * (0, 0) - (width − 1, height − 1), lines are written top to bottom (INCREASING_Y), and channels
 * are sorted by name as the format requires, whatever order they are given in. Chunks that a
 * compression would not make smaller are stored uncompressed, as the format allows.
 *
 * <p>HALF conversion rounds to the nearest half, ties to even; magnitudes from 65520 up become
 * infinite (see {@link Half#fromFloat}): write FLOAT channels for values that large (depth).
 *
 * <p>Typical use, a render with its feature buffers for a denoiser:
 * <pre>{@code
 * ExrWriter.write(path, w, h, List.of(
 *         new ExrWriter.Channel("R", r), new ExrWriter.Channel("G", g), new ExrWriter.Channel("B", b),
 *         new ExrWriter.Channel("albedo.R", ar), ..., new ExrWriter.Channel("normal.X", nx), ...,
 *         new ExrWriter.Channel("depth.Z", z, ExrPixelType.FLOAT)),
 *     ExrWriter.Options.DEFAULT);
 * }</pre>
 */
public final class ExrWriter {

    /**
     * One channel to write.
     *
     * @param name   its name: 1 to 255 bytes of UTF-8, no NUL; names longer than 31 bytes set the
     *               file's long-names flag
     * @param values width · height samples, rows from the top, each left to right (not copied)
     * @param type   HALF or FLOAT, or null for the {@link Options#type() options'} type
     */
    public record Channel(String name, float[] values, ExrPixelType type) {
        /** Checks the name and type. */
        public Channel {
            Objects.requireNonNull(name, "name");
            Objects.requireNonNull(values, "values");
            int bytes = name.getBytes(StandardCharsets.UTF_8).length;
            if (bytes == 0 || bytes > 255 || name.indexOf('\0') >= 0) {
                throw new IllegalArgumentException("an EXR channel name must be 1 to 255 bytes without NUL, got '" + name + "'");
            }
            if (type == ExrPixelType.UINT) {
                throw new IllegalArgumentException("channel '" + name + "': strahl writes HALF or FLOAT channels, not UINT");
            }
        }

        /**
         * A channel of the options' type.
         *
         * @param name   its name
         * @param values width · height samples, rows from the top
         */
        public Channel(String name, float[] values) {
            this(name, values, null);
        }
    }

    /**
     * How to write.
     *
     * @param type        the sample type of channels that do not name their own: HALF or FLOAT
     * @param compression NONE, RLE, ZIPS or ZIP
     */
    public record Options(ExrPixelType type, ExrCompression compression) {
        /** HALF samples, ZIP compression. */
        public static final Options DEFAULT = new Options(ExrPixelType.HALF, ExrCompression.ZIP);

        /** Checks that strahl can write these. */
        public Options {
            if (type != ExrPixelType.HALF && type != ExrPixelType.FLOAT) {
                throw new IllegalArgumentException("strahl writes HALF or FLOAT EXR channels, not " + type);
            }
            if (compression != ExrCompression.NONE && compression != ExrCompression.RLE && compression != ExrCompression.ZIPS
                    && compression != ExrCompression.ZIP) {
                throw new IllegalArgumentException("strahl writes EXR compression NONE, RLE, ZIPS or ZIP, not " + compression);
            }
        }
    }

    private ExrWriter() {
    }

    /**
     * Writes a file atomically ({@link AtomicFile}: the target is replaced only by a complete file).
     *
     * @param out      the file
     * @param width    width in pixels, positive
     * @param height   height in pixels, positive
     * @param channels the channels, at least one, distinct names
     * @param options  sample type and compression
     * @throws IOException if writing fails (the target is then unchanged)
     */
    public static void write(Path out, int width, int height, List<Channel> channels, Options options) throws IOException {
        List<Channel> sorted = checked(width, height, channels);
        AtomicFile.write(out, os -> write(os, width, height, sorted, options));
    }

    /**
     * Writes all channels of an image atomically, each as the options' type.
     *
     * @param out     the file
     * @param image   the image (its channel names become the file's)
     * @param options sample type and compression
     * @throws IOException if writing fails (the target is then unchanged)
     */
    public static void write(Path out, ChannelImage image, Options options) throws IOException {
        int n = image.channelCount();
        int pixels = image.width() * image.height();
        float[] all = image.data();
        List<Channel> channels = new ArrayList<>();
        for (int c = 0; c < n; c++) {
            float[] v = new float[pixels];
            for (int p = 0; p < pixels; p++) {
                v[p] = all[p * n + c];
            }
            channels.add(new Channel(image.channels().get(c), v));
        }
        write(out, image.width(), image.height(), channels, options);
    }

    /**
     * Writes the file's bytes to a stream (which is not closed).
     *
     * @param os       the stream
     * @param width    width in pixels, positive
     * @param height   height in pixels, positive
     * @param channels the channels, at least one, distinct names
     * @param options  sample type and compression
     * @throws IOException if the stream fails
     */
    public static void write(OutputStream os, int width, int height, List<Channel> channels, Options options) throws IOException {
        List<Channel> sorted = checked(width, height, channels);
        ExrPixelType[] types = new ExrPixelType[sorted.size()];
        long bytesPerPixel = 0;
        for (int c = 0; c < types.length; c++) {
            types[c] = sorted.get(c).type() != null ? sorted.get(c).type() : options.type();
            bytesPerPixel += types[c].bytes();
        }
        int linesPerChunk = options.compression().linesPerChunk();
        long chunkBytes = bytesPerPixel * width * Math.min(linesPerChunk, height);
        if (chunkBytes > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("an EXR chunk of " + chunkBytes + " bytes is too large: the image is too wide");
        }
        byte[] header = header(width, height, sorted, types, options.compression());
        int chunks = (height + linesPerChunk - 1) / linesPerChunk;

        // Chunks are encoded first: the offset table before them needs their sizes.
        byte[] raw = new byte[(int) chunkBytes];
        byte[] predicted = new byte[raw.length];
        byte[] packed = new byte[raw.length + raw.length / 127 + 2];
        List<byte[]> encoded = new ArrayList<>(chunks);
        Deflater deflater = new Deflater(Deflater.DEFAULT_COMPRESSION);
        try {
            for (int i = 0; i < chunks; i++) {
                int y = i * linesPerChunk;
                int lines = Math.min(linesPerChunk, height - y);
                int n = fillRaw(raw, sorted, types, width, y, lines);
                int size = switch (options.compression()) {
                    case RLE -> {
                        ExrCodecs.toPredicted(raw, predicted, n);
                        int k = ExrCodecs.rleEncode(predicted, n, packed);
                        yield k < n ? k : -1;
                    }
                    case ZIPS, ZIP -> {
                        ExrCodecs.toPredicted(raw, predicted, n);
                        yield ExrCodecs.deflate(deflater, predicted, n, packed);
                    }
                    default -> -1;
                };
                ByteBuffer chunk = ByteBuffer.allocate(8 + (size < 0 ? n : size)).order(ByteOrder.LITTLE_ENDIAN);
                chunk.putInt(y).putInt(size < 0 ? n : size).put(size < 0 ? raw : packed, 0, size < 0 ? n : size);
                encoded.add(chunk.array());
            }
        } finally {
            deflater.end();
        }
        ByteBuffer table = ByteBuffer.allocate(8 * chunks).order(ByteOrder.LITTLE_ENDIAN);
        long offset = header.length + 8L * chunks;
        for (byte[] chunk : encoded) {
            table.putLong(offset);
            offset += chunk.length;
        }
        os.write(header);
        os.write(table.array());
        for (byte[] chunk : encoded) {
            os.write(chunk);
        }
    }

    private static List<Channel> checked(int width, int height, List<Channel> channels) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("image size must be positive, got " + width + "x" + height);
        }
        if (channels.isEmpty()) {
            throw new IllegalArgumentException("an EXR file needs at least one channel");
        }
        HashSet<String> names = new HashSet<>();
        for (Channel c : channels) {
            if (!names.add(c.name())) {
                throw new IllegalArgumentException("channel '" + c.name() + "' is given twice");
            }
            if (c.values().length != (long) width * height) {
                throw new IllegalArgumentException("channel '" + c.name() + "' has " + c.values().length + " values, a " + width + "x"
                        + height + " image needs " + (long) width * height);
            }
        }
        List<Channel> sorted = new ArrayList<>(channels);
        sorted.sort(Comparator.comparing(Channel::name, ExrHeader.NAME_ORDER));
        return sorted;
    }

    /** Lines {@code y .. y + lines − 1}: for each line, each channel's samples left to right, little-endian. */
    private static int fillRaw(byte[] raw, List<Channel> channels, ExrPixelType[] types, int width, int y, int lines) {
        ByteBuffer b = ByteBuffer.wrap(raw).order(ByteOrder.LITTLE_ENDIAN);
        for (int line = y; line < y + lines; line++) {
            int row = line * width;
            for (int c = 0; c < types.length; c++) {
                float[] v = channels.get(c).values();
                if (types[c] == ExrPixelType.HALF) {
                    for (int x = 0; x < width; x++) {
                        b.putShort((short) Half.fromFloat(v[row + x]));
                    }
                } else {
                    for (int x = 0; x < width; x++) {
                        b.putFloat(v[row + x]);
                    }
                }
            }
        }
        return b.position();
    }

    /** Magic number, version field and the header's attributes in the order of their names, then the NUL byte. */
    private static byte[] header(int width, int height, List<Channel> channels, ExrPixelType[] types, ExrCompression compression) {
        boolean longNames = false;
        ByteArrayOutputStream chlist = new ByteArrayOutputStream();
        for (int c = 0; c < types.length; c++) {
            byte[] name = channels.get(c).name().getBytes(StandardCharsets.UTF_8);
            longNames |= name.length > 31;
            chlist.writeBytes(name);
            chlist.write(0);
            chlist.writeBytes(le(types[c].code(), 0, 1, 1));     // type; pLinear 0 and 3 reserved bytes; x and y sampling
        }
        chlist.write(0);
        Attributes a = new Attributes();
        a.add("channels", "chlist", chlist.toByteArray());
        a.add("compression", "compression", new byte[] {(byte) compression.code()});
        a.add("dataWindow", "box2i", le(0, 0, width - 1, height - 1));
        a.add("displayWindow", "box2i", le(0, 0, width - 1, height - 1));
        a.add("lineOrder", "lineOrder", new byte[] {0});
        a.add("pixelAspectRatio", "float", le(Float.floatToIntBits(1f)));
        a.add("screenWindowCenter", "v2f", le(0, 0));
        a.add("screenWindowWidth", "float", le(Float.floatToIntBits(1f)));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(le(ExrHeader.MAGIC, 2 | (longNames ? ExrHeader.LONG_NAMES : 0)));
        out.writeBytes(a.bytes.toByteArray());
        out.write(0);
        return out.toByteArray();
    }

    private static byte[] le(int... values) {
        ByteBuffer b = ByteBuffer.allocate(4 * values.length).order(ByteOrder.LITTLE_ENDIAN);
        for (int v : values) {
            b.putInt(v);
        }
        return b.array();
    }

    private static final class Attributes {
        final ByteArrayOutputStream bytes = new ByteArrayOutputStream();

        void add(String name, String type, byte[] value) {
            bytes.writeBytes(name.getBytes(StandardCharsets.US_ASCII));
            bytes.write(0);
            bytes.writeBytes(type.getBytes(StandardCharsets.US_ASCII));
            bytes.write(0);
            bytes.writeBytes(le(value.length));
            bytes.writeBytes(value);
        }
    }
}
