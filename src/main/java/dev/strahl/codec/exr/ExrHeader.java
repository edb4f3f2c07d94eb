package dev.strahl.codec.exr;

import static dev.strahl.codec.ImageFormatException.printable;

import dev.strahl.codec.ImageFormatException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * What strahl takes from the header of a single-part scanline EXR file. Other attributes
 * (pixelAspectRatio, screenWindow*, chromaticities, comments, ...) are skipped.
 *
 * @param channels      the channels in the order of the pixel data: sorted by name (bytewise)
 * @param compression   how the chunks are compressed
 * @param dataWindow    the pixels the file holds
 * @param displayWindow the frame the pixels belong to (informational; the data window is the image)
 * @param lineOrder     0 INCREASING_Y, 1 DECREASING_Y, 2 RANDOM_Y: the order of the chunks in the
 *                      file; chunks are placed by their own y, so any order reads the same
 */
public record ExrHeader(List<Channel> channels, ExrCompression compression, Box dataWindow, Box displayWindow, int lineOrder) {
    /** The magic number, the first four bytes of every EXR file. */
    static final int MAGIC = 20000630;
    static final int TILED = 0x200;
    static final int LONG_NAMES = 0x400;
    static final int NON_IMAGE = 0x800;
    static final int MULTI_PART = 0x1000;

    /** Sorted channels, copied. */
    public ExrHeader {
        channels = List.copyOf(channels);
    }

    /**
     * One channel of the channel list.
     *
     * @param name its name (UTF-8 in the file)
     * @param type its pixel type
     */
    public record Channel(String name, ExrPixelType type) {}

    /**
     * A box2i: inclusive pixel bounds.
     *
     * @param xMin left column
     * @param yMin top row
     * @param xMax right column, inclusive
     * @param yMax bottom row, inclusive
     */
    public record Box(int xMin, int yMin, int xMax, int yMax) {
        /** @return xMax - xMin + 1 (as long: no overflow for any ints) */
        public long width() {
            return (long) xMax - xMin + 1;
        }

        /** @return yMax - yMin + 1 */
        public long height() {
            return (long) yMax - yMin + 1;
        }

        @Override
        public String toString() {
            return "(" + xMin + ", " + yMin + ") - (" + xMax + ", " + yMax + ")";
        }
    }

    /** Bytes per scan line of all channels together. */
    long bytesPerLine() {
        long perPixel = 0;
        for (Channel c : channels) {
            perPixel += c.type.bytes();
        }
        return perPixel * dataWindow.width();
    }

    /** Bytewise (unsigned) order of UTF-8 names: the order of the pixel data (C's strcmp). */
    static final Comparator<String> NAME_ORDER = (a, b) -> {
        byte[] x = a.getBytes(StandardCharsets.UTF_8);
        byte[] y = b.getBytes(StandardCharsets.UTF_8);
        return java.util.Arrays.compareUnsigned(x, y);
    };

    /** Reads magic number, version field and header; the input is left at the offset table. */
    static ExrHeader read(ExrInput in) throws IOException {
        if (in.size() < 4 || in.i32("the magic number") != MAGIC) {
            throw in.error("not an OpenEXR file (it does not start with the magic number 76 2f 31 01)");
        }
        int versionField = in.i32("the version field");
        int version = versionField & 0xff;
        int flags = versionField & ~0xff;
        if (version < 1 || version > 2) {
            throw in.error("EXR format version " + version + " is not supported (strahl reads version 2 files)");
        }
        if ((flags & MULTI_PART) != 0) {
            throw in.error("multi-part EXR files are not supported (strahl reads single-part scanline images)");
        }
        if ((flags & NON_IMAGE) != 0) {
            throw in.error("deep EXR files are not supported (strahl reads single-part scanline images)");
        }
        if ((flags & TILED) != 0) {
            throw in.error("tiled EXR files are not supported (strahl reads single-part scanline images)");
        }
        if ((flags & ~LONG_NAMES) != 0) {
            throw in.error(String.format("unknown flags 0x%x in the EXR version field (the file needs a newer reader)", flags & ~LONG_NAMES));
        }
        int maxName = (flags & LONG_NAMES) != 0 ? 255 : 31;

        List<Channel> channels = null;
        ExrCompression compression = null;
        Box dataWindow = null;
        Box displayWindow = null;
        int lineOrder = -1;
        Set<String> seen = new HashSet<>();
        while (true) {
            long at = in.position();
            String name = in.cstring(maxName, "an attribute name");
            if (name.isEmpty()) {
                break;                       // the NUL byte that ends the header
            }
            String type = in.cstring(maxName, "the type of attribute '" + printable(name) + "'");
            int size = in.i32("the size of attribute '" + printable(name) + "'");
            if (size < 0 || size > in.remaining()) {
                throw in.error(at, "attribute '" + printable(name) + "' claims " + Integer.toUnsignedString(size) + " bytes, but "
                        + in.remaining() + " follow");
            }
            if (!seen.add(name)) {
                throw in.error(at, "attribute '" + printable(name) + "' appears twice");
            }
            long end = in.position() + size;
            switch (name) {
                case "channels" -> channels = channelList(in, expect(in, at, name, type, "chlist", size, -1), end);
                case "compression" -> {
                    expect(in, at, name, type, "compression", size, 1);
                    int code = in.u8(name);
                    compression = ExrCompression.ofCode(code);
                    if (compression == null) {
                        throw in.error(at, "unknown EXR compression code " + code);
                    }
                }
                case "dataWindow" -> dataWindow = box(in, expect(in, at, name, type, "box2i", size, 16), name);
                case "displayWindow" -> displayWindow = box(in, expect(in, at, name, type, "box2i", size, 16), name);
                case "lineOrder" -> {
                    expect(in, at, name, type, "lineOrder", size, 1);
                    lineOrder = in.u8(name);
                    if (lineOrder > 2) {
                        throw in.error(at, "unknown lineOrder " + lineOrder + " (expected 0, 1 or 2)");
                    }
                }
                case "type" -> {
                    String kind = new String(in.bytes(size, "attribute 'type'"), StandardCharsets.ISO_8859_1);
                    if (!type.equals("string") || !kind.equals("scanlineimage")) {
                        throw in.error(at, "the part's type is '" + printable(kind) + "'; strahl reads only scanline images ('scanlineimage')");
                    }
                }
                default -> in.skip(size, "attribute '" + printable(name) + "'");
            }
            if (in.position() != end) {
                throw in.error(at, "attribute '" + printable(name) + "' is " + size + " bytes long, but its value takes " + (in.position() - at)
                        + " bytes from the name on");
            }
        }
        if (channels == null || compression == null || dataWindow == null) {
            throw in.error("the EXR header lacks the required attribute '" + (channels == null ? "channels"
                    : compression == null ? "compression" : "dataWindow") + "'");
        }
        if (!compression.readable()) {
            throw in.error("EXR compression " + compression + " is not supported (strahl reads NONE, RLE, ZIPS, ZIP, PIZ)");
        }
        checkWindow(in, "data window", dataWindow);
        if (displayWindow != null) {
            checkWindow(in, "display window", displayWindow);
        }
        return new ExrHeader(channels, compression, dataWindow, displayWindow == null ? dataWindow : displayWindow,
                lineOrder < 0 ? 0 : lineOrder);
    }

    /** A window whose maximum lies before its minimum (an inverted window: a negative size) is refused, naming the size it implies. */
    private static void checkWindow(ExrInput in, String what, Box w) throws ImageFormatException {
        if (w.width() <= 0 || w.height() <= 0) {
            throw in.error("the " + what + " " + w + " is empty: it is inverted (" + (w.width() <= 0 ? "xMax < xMin" : "yMax < yMin")
                    + ") and describes a " + w.width() + "x" + w.height() + " image");
        }
    }

    /** Checks an attribute's type (and size, unless -1); returns the size. */
    private static int expect(ExrInput in, long at, String name, String type, String wanted, int size, int wantedSize)
            throws IOException {
        if (!type.equals(wanted)) {
            throw in.error(at, "attribute '" + printable(name) + "' has type '" + printable(type) + "', expected '" + wanted + "'");
        }
        if (wantedSize >= 0 && size != wantedSize) {
            throw in.error(at, "attribute '" + printable(name) + "' has " + size + " bytes, expected " + wantedSize);
        }
        return size;
    }

    private static Box box(ExrInput in, int size, String name) throws IOException {
        return new Box(in.i32(name), in.i32(name), in.i32(name), in.i32(name));
    }

    /** Parses a chlist; the channels come back sorted by name, the order of the pixel data. */
    private static List<Channel> channelList(ExrInput in, int size, long end) throws IOException {
        List<Channel> list = new ArrayList<>();
        Set<String> names = new HashSet<>();
        while (true) {
            if (in.position() >= end) {
                throw in.error(in.position(), "the channel list has no terminating NUL byte within its " + size + " bytes");
            }
            long at = in.position();
            String name = in.cstring(255, "a channel name");
            if (name.isEmpty()) {
                break;
            }
            int code = in.i32("channel '" + printable(name) + "'");
            ExrPixelType type = ExrPixelType.ofCode(code);
            if (type == null) {
                throw in.error(at, "channel '" + printable(name) + "' has unknown pixel type " + code + " (0 UINT, 1 HALF, 2 FLOAT)");
            }
            in.skip(4, "channel '" + printable(name) + "'");            // pLinear and three reserved bytes
            int xSampling = in.i32("channel '" + printable(name) + "'");
            int ySampling = in.i32("channel '" + printable(name) + "'");
            if (xSampling != 1 || ySampling != 1) {
                throw in.error(at, "channel '" + printable(name) + "' is subsampled (" + xSampling + "x" + ySampling
                        + "); strahl reads only channels with a sample for every pixel");
            }
            if (!names.add(name)) {
                throw in.error(at, "channel '" + printable(name) + "' appears twice");
            }
            list.add(new Channel(name, type));
        }
        if (list.isEmpty()) {
            throw in.error("the EXR file has no channels");
        }
        list.sort(Comparator.comparing(Channel::name, NAME_ORDER));
        return list;
    }
}
