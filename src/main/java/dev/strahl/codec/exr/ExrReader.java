package dev.strahl.codec.exr;

import dev.strahl.files.FileReads;
import dev.strahl.codec.ChannelImage;
import dev.strahl.codec.ImageFormatException;
import dev.strahl.codec.ImageLimits;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Locale;
import java.util.zip.Inflater;

/**
 * Reads OpenEXR images: single-part scanline files (not tiled, multi-part or deep), compressed
 * with NONE, RLE, ZIPS, ZIP or PIZ, with any set of full-resolution channels of type HALF, FLOAT
 * or UINT. The file layout follows the OpenEXR documentation ("OpenEXR File Layout"); the
 * compressions are described in {@link ExrCodecs} and {@link Piz}. docs/image-formats.md lists
 * what is refused and how.
 *
 * <p><b>The image.</b> The pixels of the data window, whose top-left pixel (xMin, yMin) becomes
 * (0, 0) of the returned {@link ChannelImage}: the window's offset and the display window are
 * reported in {@link ExrImage#header()}, not applied (nothing outside the data window is made
 * up). Rows run top to bottom whatever the file's lineOrder (chunks are placed by their y).
 * Channels keep their names and come in the order of the file, sorted by name; HALF samples become
 * the equal float, UINT samples the nearest float.
 *
 * <p><b>Errors.</b> Everything wrong with a file is an {@link ImageFormatException} of one line
 * naming the file and, where it applies, the chunk and byte. Sizes are checked before any
 * allocation: the offset table against the file length, the image against what the file could
 * decompress to at the compression's largest ratio, and then against the heap.
 */
public final class ExrReader {
    /**
     * Upper bounds of uncompressed/compressed size: zlib (deflate) cannot exceed about 1032:1, a
     * PIZ run of 256 words costs at least 9 bits (about 455:1), an RLE run of 128 bytes 2 bytes.
     */
    private static final double ZLIB_RATIO = 1100;
    private static final double RLE_RATIO = 64;

    private ExrReader() {
    }

    /**
     * A file's header and its pixels.
     *
     * @param header           what the header says (channel types, compression, windows, line order)
     * @param pixels           the data window's pixels
     * @param compressedChunks how many chunks were stored compressed (the others were stored as
     *                         they are, as writers do where compression does not pay)
     */
    public record ExrImage(ExrHeader header, ChannelImage pixels, int compressedChunks) {}

    /**
     * Reads all channels of a file.
     *
     * @param file an EXR file
     * @return its data window's pixels, laid out as {@link ChannelImage} says
     * @throws ImageFormatException if the file is not a readable EXR image
     * @throws IOException          if it cannot be read at all
     */
    public static ChannelImage read(Path file) throws IOException {
        return readFile(file).pixels();
    }

    /**
     * Reads a file's colour as linear RGB: channels R, G, B, or Y as grey; other channels (A
     * among them) are dropped.
     *
     * @param file an EXR file
     * @return a three-channel image R, G, B
     * @throws ImageFormatException if the file is not a readable EXR image or has no colour channels
     * @throws IOException          if it cannot be read at all
     */
    public static ChannelImage readRgb(Path file) throws IOException {
        ChannelImage all = read(file);
        if (!all.hasColour()) {
            throw new ImageFormatException(file, "the EXR image has no colour channels (R, G, B or Y); its channels are "
                    + dev.strahl.codec.Printable.text(String.join(", ", all.channels()), 80));
        }
        return all.rgb();
    }

    /**
     * Reads a file with its header.
     *
     * @param file an EXR file
     * @return header and pixels
     * @throws ImageFormatException if the file is not a readable EXR image
     * @throws IOException          if it cannot be read at all
     */
    public static ExrImage readFile(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new ImageFormatException(file, "is a directory, not an EXR file");
        }
        dev.strahl.files.FileReads.note(file);
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            ExrInput in = new ExrInput(file, channel);
            ExrHeader header = ExrHeader.read(in);
            return readPixels(in, header);
        }
    }

    private static ExrImage readPixels(ExrInput in, ExrHeader h) throws IOException {
        long width = h.dataWindow().width();
        long height = h.dataWindow().height();
        int linesPerChunk = h.compression().linesPerChunk();
        long chunks = (height + linesPerChunk - 1) / linesPerChunk;
        long tableStart = in.position();
        if (chunks * 16 > in.remaining()) {          // 8 bytes in the table, 8 of y and size per chunk
            throw in.error(tableStart, "the file is truncated: the data window " + h.dataWindow() + " needs " + chunks + " chunks of "
                    + h.compression() + " data (at least " + chunks * 16 + " bytes), but " + in.remaining() + " bytes follow the header"
                    + " (it claims a " + width + "x" + height + " image)");
        }
        double ratio = switch (h.compression()) {
            case NONE -> 1;
            case RLE -> RLE_RATIO;
            default -> ZLIB_RATIO;
        };
        ImageLimits.checkFileHolds(in.file(), width, height, (double) h.bytesPerLine() * height, in.size(), ratio,
                h.compression() + " compression");
        double chunkBytes = (double) h.bytesPerLine() * Math.min(linesPerChunk, height);
        if (chunkBytes > ImageLimits.MAX_ARRAY) {
            throw in.error(String.format(Locale.ROOT, "a chunk of %.3g bytes is too large to decode", chunkBytes));
        }
        int maxRaw = (int) chunkBytes;
        ImageLimits.checkAllocation(in.file(), width, height, h.channels().size(), 3L * maxRaw);

        long[] offsets = new long[(int) chunks];
        for (int i = 0; i < chunks; i++) {
            offsets[i] = in.u64("the offset table");
            checkOffset(in, h, offsets, i, in.position() + 8 * (chunks - i - 1));
        }
        ChunkDecoder decoder = new ChunkDecoder(in, h, maxRaw, in.position());
        try {
            for (int i = 0; i < chunks; i++) {
                decoder.chunk(i, offsets[i]);
            }
        } finally {
            decoder.close();
        }
        return new ExrImage(h, new ChannelImage((int) width, (int) height, h.channels().stream().map(ExrHeader.Channel::name).toList(),
                decoder.data), decoder.compressed);
    }

    /**
     * Checks entry {@code i} of the offset table before anything is read there: inside the pixel
     * data (from {@code tableEnd} to the end of the file, room for a chunk's y and size at least),
     * and after (INCREASING_Y) or before (DECREASING_Y) the previous chunk's, as the line order
     * says the chunks are stored; RANDOM_Y chunks may lie in any order.
     */
    private static void checkOffset(ExrInput in, ExrHeader h, long[] offsets, int i, long tableEnd) throws ImageFormatException {
        long offset = offsets[i];
        long y = (long) h.dataWindow().yMin() + (long) i * h.compression().linesPerChunk();
        if (offset < tableEnd || offset > in.size() - 8) {
            throw in.error("chunk " + i + " (y = " + y + "): its offset " + Long.toUnsignedString(offset)
                    + " in the offset table is outside the pixel data (bytes " + tableEnd + " to " + in.size() + ")");
        }
        if (i > 0 && h.lineOrder() != 2) {
            boolean increasing = h.lineOrder() == 0;
            long previous = offsets[i - 1];
            if (increasing ? offset < previous + 8 : offset > previous - 8) {
                throw in.error("chunk " + i + " (y = " + y + "): its offset " + offset + " in the offset table is not "
                        + (increasing ? "after" : "before") + " chunk " + (i - 1) + "'s (" + previous + "), but the file's lineOrder is "
                        + (increasing ? "INCREASING_Y" : "DECREASING_Y") + ": the table is corrupt");
            }
        }
    }

    /** Reads, decompresses and converts one chunk after the other into {@link #data}. */
    private static final class ChunkDecoder {
        final ExrInput in;
        final ExrHeader h;
        final long tableEnd;
        final int width;
        final int channels;
        final long bytesPerLine;
        final float[] data;
        final byte[] raw;
        final byte[] scratch;
        byte[] packed = new byte[0];
        int compressed;
        final Inflater inflater = new Inflater();
        final Piz.Scratch piz = new Piz.Scratch();

        ChunkDecoder(ExrInput in, ExrHeader h, int maxRaw, long tableEnd) {
            this.in = in;
            this.h = h;
            this.tableEnd = tableEnd;
            this.width = (int) h.dataWindow().width();
            this.channels = h.channels().size();
            this.bytesPerLine = h.bytesPerLine();
            this.data = new float[Math.toIntExact((long) width * h.dataWindow().height() * channels)];
            this.raw = new byte[maxRaw];
            this.scratch = new byte[maxRaw];
        }

        void close() {
            inflater.end();
        }

        void chunk(int index, long offset) throws IOException {
            int linesPerChunk = h.compression().linesPerChunk();
            long expectedY = (long) h.dataWindow().yMin() + (long) index * linesPerChunk;
            in.seek(offset);                      // inside the file: checkOffset
            int y = in.i32("the y of chunk " + index);
            int size = in.i32("the data size of chunk " + index);
            if (y != expectedY) {
                throw in.error(offset, "chunk " + index + " starts with y = " + y + ", expected " + expectedY);
            }
            int lines = (int) Math.min(linesPerChunk, (long) h.dataWindow().yMax() - y + 1);
            int rawSize = (int) (lines * bytesPerLine);
            if (size <= 0 || size > rawSize || (h.compression() == ExrCompression.NONE && size != rawSize)) {
                throw in.error(offset, "chunk " + index + " (y = " + y + ") claims " + Integer.toUnsignedString(size)
                        + " bytes of pixel data; its " + lines + " line(s) need " + rawSize + " uncompressed");
            }
            if (size > in.remaining()) {
                throw in.error(offset, "the file ends inside chunk " + index + " (y = " + y + ", " + size + " bytes from byte "
                        + in.position() + "; the file has " + in.size() + "): it is truncated");
            }
            if (size == rawSize) {                 // stored uncompressed (NONE, or compression did not pay)
                in.readFully(raw, size);
            } else {
                if (packed.length < size) {
                    packed = new byte[size];
                }
                in.readFully(packed, size);
                try {
                    decompress(size, rawSize, lines);
                } catch (CorruptDataException e) {
                    throw in.error(offset, "chunk " + index + " (y = " + y + ", " + h.compression() + "): " + e.getMessage());
                }
                compressed++;
            }
            convert(raw, y - h.dataWindow().yMin(), lines);
        }

        private void decompress(int size, int rawSize, int lines) throws CorruptDataException {
            switch (h.compression()) {
                case RLE -> {
                    ExrCodecs.rleDecode(packed, size, scratch, rawSize);
                    ExrCodecs.fromPredicted(scratch, raw, rawSize);
                }
                case ZIPS, ZIP -> {
                    ExrCodecs.inflate(inflater, packed, size, scratch, rawSize);
                    ExrCodecs.fromPredicted(scratch, raw, rawSize);
                }
                case PIZ -> Piz.decode(packed, size, raw, rawSize, width, lines, h.channels(), piz);
                default -> throw new IllegalStateException("not a readable compression: " + h.compression());
            }
        }

        /** Scan lines of channels of samples, little-endian, into the interleaved floats. */
        private void convert(byte[] source, int firstRow, int lines) {
            ByteBuffer b = ByteBuffer.wrap(source).order(ByteOrder.LITTLE_ENDIAN);
            int at = 0;
            List<ExrHeader.Channel> list = h.channels();
            for (int line = 0; line < lines; line++) {
                int rowStart = (firstRow + line) * width * channels;
                for (int c = 0; c < channels; c++) {
                    int dst = rowStart + c;
                    switch (list.get(c).type()) {
                        case HALF -> {
                            for (int x = 0; x < width; x++, at += 2, dst += channels) {
                                data[dst] = Half.toFloat(b.getShort(at) & 0xffff);
                            }
                        }
                        case FLOAT -> {
                            for (int x = 0; x < width; x++, at += 4, dst += channels) {
                                data[dst] = b.getFloat(at);
                            }
                        }
                        case UINT -> {
                            for (int x = 0; x < width; x++, at += 4, dst += channels) {
                                data[dst] = (float) (b.getInt(at) & 0xffffffffL);
                            }
                        }
                        default -> throw new IllegalStateException();
                    }
                }
            }
        }
    }
}
