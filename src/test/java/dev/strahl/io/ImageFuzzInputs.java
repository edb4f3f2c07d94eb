package dev.strahl.io;

import dev.strahl.codec.exr.ExrCompression;
import dev.strahl.codec.exr.ExrPixelType;
import dev.strahl.codec.exr.ExrWriter;
import dev.strahl.codec.HdrWriter;
import java.awt.Transparency;
import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.ComponentColorModel;
import java.awt.image.DataBuffer;
import java.awt.image.IndexColorModel;
import java.awt.image.WritableRaster;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import java.util.zip.CRC32;
import java.util.zip.Deflater;
import javax.imageio.ImageIO;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;

/**
 * Fuzzing inputs for the image readers (EXR, Radiance HDR, PNG/JPEG): files built from a small
 * grammar of each format with hostile header values (sizes, windows, codes, offsets, counts) and
 * random or half-right pixel data, and valid files (the fixtures, and files from strahl's own
 * writers and ImageIO) mutated with the text edits of {@link FuzzInputs#mutate} and binary ones
 * (little-endian and big-endian integers overwritten with hostile values, bytes set to 0 or 255).
 */
final class ImageFuzzInputs {
    private ImageFuzzInputs() {}

    private static final int[] HOSTILE_INTS = {0, 1, -1, 2, 7, 8, 16, 31, 32, 33, 127, 128, 255, 256, 0x7fff, 0x8000, 0xffff, 0x10000,
        1 << 24, 0x7fffffff, 0x80000000, 0x80000001, -2, 1000, 100_000, 46341};

    private static int hostile(SplittableRandom r) {
        return r.nextInt(4) == 0 ? r.nextInt() : HOSTILE_INTS[r.nextInt(HOSTILE_INTS.length)];
    }

    // ---- mutation --------------------------------------------------------------------------------

    /** Seeds mutated by 1 to 10 edits: text edits or binary ones, from a 64-bit choice drawn by jqwik. */
    static Arbitrary<byte[]> mutated(List<byte[]> seeds, List<String> dictionary) {
        return Combinators.combine(Arbitraries.of(seeds), Arbitraries.longs(), Arbitraries.of(1, 1, 1, 1, 2, 2, 2, 3, 3, 5, 10))
                .as((seed, choice, edits) -> {
                    SplittableRandom r = new SplittableRandom(choice);
                    byte[] b = seed;
                    for (int e = 0; e < edits; e++) {
                        b = r.nextBoolean() ? FuzzInputs.mutate(b, r, 1, dictionary) : binaryEdit(b, r);
                    }
                    return b;
                });
    }

    static byte[] binaryEdit(byte[] seed, SplittableRandom r) {
        if (seed.length < 4) {
            return seed;
        }
        byte[] b = seed.clone();
        int at = r.nextInt(b.length - 3);
        switch (r.nextInt(5)) {
            case 0 -> ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putInt(at, hostile(r));
            case 1 -> ByteBuffer.wrap(b).order(ByteOrder.BIG_ENDIAN).putInt(at, hostile(r));
            case 2 -> b[at] = (byte) (r.nextBoolean() ? 0 : 0xff);
            case 3 -> {                                             // a run of bytes scrambled
                int n = Math.min(b.length - at, 1 + r.nextInt(32));
                for (int i = 0; i < n; i++) {
                    b[at + i] = (byte) r.nextInt(256);
                }
            }
            default -> b[at] += (byte) (r.nextBoolean() ? 1 : -1);
        }
        return b;
    }

    private static Arbitrary<byte[]> generated(java.util.function.Function<SplittableRandom, byte[]> make) {
        return Arbitraries.longs().map(seed -> make.apply(new SplittableRandom(seed)));
    }

    // ---- EXR -------------------------------------------------------------------------------------

    static final List<String> EXR_WORDS = List.of("channels\0chlist\0", "compression\0compression\0", "dataWindow\0box2i\0",
            "displayWindow\0box2i\0", "lineOrder\0lineOrder\0", "type\0string\0", "tiledimage", "scanlineimage", "\0", "R\0", "\u0001",
            "\u00ff\u00ff\u00ff\u007f", "\u0000\u0000\u0000\u0080");

    /** The fixtures and files from ExrWriter in every compression and type. */
    static List<byte[]> exrSeeds() {
        List<byte[]> seeds = new ArrayList<>(resources("exr", ".exr"));
        SplittableRandom r = new SplittableRandom(5);
        int i = 0;
        for (ExrCompression c : List.of(ExrCompression.ZIP, ExrCompression.ZIPS, ExrCompression.RLE, ExrCompression.NONE)) {
            for (ExrPixelType t : List.of(ExrPixelType.HALF, ExrPixelType.FLOAT)) {
                int w = 3 + i * 5;
                int h = 2 + i * 3;
                List<ExrWriter.Channel> channels = new ArrayList<>();
                for (String name : List.of("R", "G", "B", "depth.Z")) {
                    float[] v = new float[w * h];
                    for (int k = 0; k < v.length; k++) {
                        v[k] = k % 3 == 0 ? k * 0.25f : (float) r.nextGaussian();
                    }
                    channels.add(new ExrWriter.Channel(name, v));
                }
                ByteArrayOutputStream out = new ByteArrayOutputStream();
                try {
                    ExrWriter.write(out, w, h, channels, new ExrWriter.Options(t, c));
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
                seeds.add(out.toByteArray());
                i++;
            }
        }
        return seeds;
    }

    /** EXR files from the grammar: a header of hostile attribute values, an offset table and chunks, each right or not. */
    static Arbitrary<byte[]> randomExr() {
        return generated(ImageFuzzInputs::randomExr);
    }

    private static byte[] randomExr(SplittableRandom r) {
        Le out = new Le();
        out.i32(r.nextInt(20) == 0 ? hostile(r) : 20000630);
        int[] flags = {0, 0, 0, 0x400, 0x200, 0x800, 0x1000, 0x10000};
        out.i32((r.nextInt(10) == 0 ? r.nextInt(4) : 2) | flags[r.nextInt(flags.length)]);
        int channels = r.nextInt(5);
        int bytesPerPixel = 0;
        Le chlist = new Le();
        String[] names = {"R", "G", "B", "A", "Y", "Z", "a.b", "id", "x".repeat(40), ""};
        for (int c = 0; c < channels; c++) {
            chlist.text(names[r.nextInt(names.length)]);
            int type = r.nextInt(8) == 0 ? hostile(r) : r.nextInt(3);
            bytesPerPixel += type == 1 ? 2 : 4;
            chlist.i32(type);
            chlist.i32(0);
            boolean sub = r.nextInt(10) == 0;
            chlist.i32(sub ? hostile(r) : 1);
            chlist.i32(sub ? hostile(r) : 1);
        }
        chlist.b(0);
        int compression = r.nextInt(6) == 0 ? r.nextInt(16) : r.nextInt(5);
        int x0 = r.nextInt(4) == 0 ? hostile(r) : 0;
        int y0 = r.nextInt(4) == 0 ? hostile(r) : 0;
        int w = r.nextInt(5) == 0 ? hostile(r) : 1 + r.nextInt(40);
        int h = r.nextInt(5) == 0 ? hostile(r) : 1 + r.nextInt(40);
        List<Runnable> attributes = new ArrayList<>();
        attributes.add(() -> out.attribute("channels", "chlist", chlist.bytes()));
        attributes.add(() -> out.attribute("compression", "compression", new byte[] {(byte) compression}));
        attributes.add(() -> out.attribute("dataWindow", "box2i", Le.ints(x0, y0, x0 + w - 1, y0 + h - 1)));
        attributes.add(() -> out.attribute("displayWindow", "box2i", Le.ints(0, 0, hostile(r), hostile(r))));
        attributes.add(() -> out.attribute("lineOrder", "lineOrder", new byte[] {(byte) r.nextInt(4)}));
        attributes.add(() -> out.attribute("pixelAspectRatio", "float", Le.ints(Float.floatToIntBits(1))));
        if (r.nextInt(4) == 0) {
            attributes.add(() -> out.attribute("comment" + r.nextInt(9), "string", randomBytes(r, r.nextInt(40))));
        }
        if (r.nextInt(8) == 0) {
            attributes.add(() -> out.attributeLying(names[r.nextInt(names.length)], "box2i", randomBytes(r, r.nextInt(20)), hostile(r)));
        }
        for (int i = attributes.size() - 1; i > 0; i--) {                   // any order
            java.util.Collections.swap(attributes, i, r.nextInt(i + 1));
        }
        int keep = r.nextInt(12) == 0 ? r.nextInt(attributes.size()) : attributes.size();
        attributes.subList(0, keep).forEach(Runnable::run);
        out.b(0);
        int lines = compression == 3 ? 16 : compression == 4 ? 32 : 1;
        long chunks = h > 0 && w > 0 ? Math.min(64, ((long) h + lines - 1) / lines) : r.nextInt(4);
        int tableAt = out.size();
        long[] offsets = new long[(int) chunks];
        for (int i = 0; i < chunks; i++) {
            out.i64(0);
        }
        for (int i = 0; i < chunks; i++) {
            offsets[i] = out.size();
            int y = y0 + i * lines;
            int raw = (int) Math.min(1 << 16, Math.max(0, (long) Math.min(lines, h - i * lines) * Math.max(0, w) * bytesPerPixel));
            out.i32(r.nextInt(10) == 0 ? hostile(r) : y);
            byte[] data = switch (r.nextInt(5)) {
                case 0 -> randomBytes(r, raw);
                case 1 -> zlib(randomBytes(r, r.nextInt(1 + raw)));
                case 2 -> zlib(new byte[raw]);
                case 3 -> piz(r, raw);
                default -> randomBytes(r, r.nextInt(1 + raw / 2));
            };
            out.i32(r.nextInt(10) == 0 ? hostile(r) : data.length);
            out.bytes(data);
        }
        byte[] b = out.bytes();
        ByteBuffer table = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < chunks; i++) {
            table.putLong(tableAt + 8 * i, r.nextInt(12) == 0 ? hostile(r) & 0xffffffffL : offsets[i]);
        }
        return r.nextInt(8) == 0 ? java.util.Arrays.copyOf(b, r.nextInt(b.length + 1)) : b;
    }

    /** Something shaped like a PIZ block: a bitmap range, bitmap bytes, a Huffman header with hostile fields, random codes. */
    private static byte[] piz(SplittableRandom r, int raw) {
        Le out = new Le();
        int first = r.nextInt(4) == 0 ? hostile(r) & 0xffff : r.nextInt(16);
        int last = r.nextInt(4) == 0 ? hostile(r) & 0xffff : first + r.nextInt(16);
        out.b(first);
        out.b(first >> 8);
        out.b(last);
        out.b(last >> 8);
        if (first <= last && last < 8192) {
            out.bytes(randomBytes(r, last - first + 1));
        }
        Le huf = new Le();
        int lo = r.nextInt(3) == 0 ? hostile(r) : r.nextInt(300);
        int hi = r.nextInt(3) == 0 ? hostile(r) : lo + r.nextInt(300);
        byte[] table = randomBytes(r, r.nextInt(200));
        byte[] codes = randomBytes(r, r.nextInt(1 + raw));
        huf.i32(lo);
        huf.i32(hi);
        huf.i32(r.nextInt(3) == 0 ? hostile(r) : table.length);
        huf.i32(r.nextInt(3) == 0 ? hostile(r) : 8 * codes.length - r.nextInt(8));
        huf.i32(0);
        huf.bytes(table);
        huf.bytes(codes);
        byte[] h = huf.bytes();
        out.i32(r.nextInt(6) == 0 ? hostile(r) : h.length);
        out.bytes(h);
        return out.bytes();
    }

    // ---- HDR -------------------------------------------------------------------------------------

    static final List<String> HDR_WORDS = List.of("#?RADIANCE\n", "FORMAT=32-bit_rle_rgbe\n", "FORMAT=32-bit_rle_xyze\n", "\n\n",
            "-Y ", "+Y ", "-X ", "+X ", "\u0002\u0002", "\u0001\u0001\u0001", "\u0080", "\u00ff", "0", "2147483647", "99999999999");

    /** The fixtures and HdrWriter's files of several widths (flat and run-length encoded). */
    static List<byte[]> hdrSeeds() {
        List<byte[]> seeds = new ArrayList<>(resources("hdr", ".hdr"));
        SplittableRandom r = new SplittableRandom(6);
        for (int w : new int[] {1, 5, 8, 30, 130}) {
            int h = 1 + w % 4;
            float[] rgb = new float[3 * w * h];
            for (int i = 0; i < rgb.length; i++) {
                rgb[i] = i % 4 == 0 ? 1f : (float) Math.exp(r.nextGaussian() * 3);
            }
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            try {
                HdrWriter.write(out, w, h, rgb);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            seeds.add(out.toByteArray());
        }
        return seeds;
    }

    static Arbitrary<byte[]> randomHdr() {
        return generated(ImageFuzzInputs::randomHdr);
    }

    private static byte[] randomHdr(SplittableRandom r) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        String[] first = {"#?RADIANCE", "#?RADIANCE", "#?RGBE", "#?", "#!RADIANCE", "", "RADIANCE"};
        String[] lines = {"FORMAT=32-bit_rle_rgbe", "FORMAT=32-bit_rle_xyze", "FORMAT=", "EXPOSURE=1.5", "GAMMA=2.2", "# made by hand",
            "PRIMARIES=0.64 0.33 0.3 0.6 0.15 0.06 0.3333 0.3333", "SOFTWARE=\u0000\u00ff"};
        StringBuilder head = new StringBuilder(first[r.nextInt(first.length)]).append('\n');
        for (int i = r.nextInt(4); i > 0; i--) {
            head.append(lines[r.nextInt(lines.length)]).append('\n');
        }
        if (r.nextInt(10) != 0) {
            head.append('\n');
        }
        int[] sizes = {1, 2, 3, 7, 8, 9, 16, 127, 128, 129, 32767, 32768, 0, -1};
        int w = r.nextInt(3) == 0 ? sizes[r.nextInt(sizes.length)] : 1 + r.nextInt(40);
        int h = r.nextInt(3) == 0 ? sizes[r.nextInt(sizes.length)] : 1 + r.nextInt(6);
        String[] orientations = {"-Y %2$s +X %1$s", "+Y %2$s +X %1$s", "-Y %2$s -X %1$s", "+X %1$s -Y %2$s", "-Y %2$s", "-Y %2$s +Y %1$s",
            "-Y  %2$s  +X  %1$s", "-Y %2$s +X 99999999999"};
        String orientation = orientations[r.nextInt(r.nextInt(4) == 0 ? orientations.length : 1)];
        head.append(String.format(orientation, w, h)).append('\n');
        out.writeBytes(head.toString().getBytes(StandardCharsets.ISO_8859_1));
        boolean transposed = orientation.startsWith("+X");
        int length = Math.max(0, transposed ? h : w);
        int scanlines = Math.min(8, Math.max(0, transposed ? w : h));
        for (int s = 0; s < scanlines; s++) {
            switch (r.nextInt(4)) {
                case 0 -> out.writeBytes(randomBytes(r, 4 * Math.min(length, 2000)));         // flat
                case 1 -> {                                                                    // run-length encoded, maybe wrong
                    int declared = r.nextInt(5) == 0 ? r.nextInt(0x8000) : length;
                    out.writeBytes(new byte[] {2, 2, (byte) (declared >> 8), (byte) declared});
                    for (int c = 0; c < 4; c++) {
                        for (int i = 0; i < Math.min(length, 2000); ) {
                            if (r.nextBoolean()) {
                                int run = 1 + r.nextInt(r.nextInt(20) == 0 ? 127 : Math.max(1, Math.min(127, length - i)));
                                out.write(128 + run);
                                out.write(r.nextInt(256));
                                i += run;
                            } else {
                                int n = 1 + r.nextInt(r.nextInt(20) == 0 ? 128 : Math.max(1, Math.min(128, length - i)));
                                out.write(r.nextInt(20) == 0 ? 0 : n);
                                out.writeBytes(randomBytes(r, n));
                                i += n;
                            }
                        }
                    }
                }
                case 2 -> {                                                                    // old-style repeats
                    out.writeBytes(new byte[] {(byte) 200, 100, 50, (byte) 130});
                    out.writeBytes(new byte[] {1, 1, 1, (byte) r.nextInt(256)});
                }
                default -> out.writeBytes(randomBytes(r, r.nextInt(64)));
            }
        }
        return out.toByteArray();
    }

    // ---- PNG and JPEG ----------------------------------------------------------------------------

    static final List<String> PNG_WORDS = List.of("IHDR", "IDAT", "IEND", "PLTE", "tRNS", "gAMA", "iCCP", "\u0089PNG\r\n\u001a\n",
            "\u00ff\u00d8\u00ff", "\u00ff\u00d9", "\u00ff\u00c0", "\u00ff\u00da");

    /** PNGs of every colour type and depth, and JPEGs (colour and grey), written with ImageIO. */
    static List<byte[]> pngSeeds() {
        List<byte[]> seeds = new ArrayList<>();
        SplittableRandom r = new SplittableRandom(7);
        for (int bands : new int[] {1, 2, 3, 4}) {
            for (int type : new int[] {DataBuffer.TYPE_BYTE, DataBuffer.TYPE_USHORT}) {
                ColorSpace cs = ColorSpace.getInstance(bands >= 3 ? ColorSpace.CS_sRGB : ColorSpace.CS_GRAY);
                boolean alpha = bands % 2 == 0;
                ComponentColorModel cm = new ComponentColorModel(cs, alpha, false, alpha ? Transparency.TRANSLUCENT : Transparency.OPAQUE,
                        type);
                WritableRaster raster = cm.createCompatibleWritableRaster(5 + bands, 3 + bands);
                fill(raster, r);
                seeds.add(encode(new BufferedImage(cm, raster, false, null), "png"));
            }
        }
        byte[] lut = new byte[16];
        for (int i = 0; i < 16; i++) {
            lut[i] = (byte) (i * 17);
        }
        BufferedImage palette = new BufferedImage(9, 4, BufferedImage.TYPE_BYTE_BINARY, new IndexColorModel(4, 16, lut, lut.clone(),
                new byte[16], lut.clone()));
        fill(palette.getRaster(), r);
        seeds.add(encode(palette, "png"));
        BufferedImage indexed = new BufferedImage(11, 6, BufferedImage.TYPE_BYTE_INDEXED);
        fill(indexed.getRaster(), r);
        seeds.add(encode(indexed, "png"));
        BufferedImage colour = new BufferedImage(24, 17, BufferedImage.TYPE_3BYTE_BGR);
        fill(colour.getRaster(), r);
        seeds.add(encode(colour, "jpeg"));
        BufferedImage grey = new BufferedImage(9, 16, BufferedImage.TYPE_BYTE_GRAY);
        fill(grey.getRaster(), r);
        seeds.add(encode(grey, "jpeg"));
        return seeds;
    }

    private static void fill(WritableRaster raster, SplittableRandom r) {
        int max = (1 << raster.getSampleModel().getSampleSize(0)) - 1;
        for (int y = 0; y < raster.getHeight(); y++) {
            for (int x = 0; x < raster.getWidth(); x++) {
                for (int b = 0; b < raster.getNumBands(); b++) {
                    raster.setSample(x, y, b, x % 3 == 0 ? max / 2 : r.nextInt(max + 1));
                }
            }
        }
    }

    private static byte[] encode(BufferedImage img, String format) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            if (!ImageIO.write(img, format, out)) {
                throw new IllegalStateException("no " + format + " writer for " + img);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }

    /** PNGs from chunks: IHDR with hostile sizes, depths and colour types, maybe PLTE and tRNS, IDAT of zlib data, IEND; CRCs right. */
    static Arbitrary<byte[]> randomPng() {
        return generated(ImageFuzzInputs::randomPng);
    }

    private static byte[] randomPng(SplittableRandom r) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
        int w = r.nextInt(4) == 0 ? hostile(r) : 1 + r.nextInt(30);
        int h = r.nextInt(4) == 0 ? hostile(r) : 1 + r.nextInt(30);
        int[] depths = {1, 2, 4, 8, 16, 3, 0};
        int[] types = {0, 2, 3, 4, 6, 1, 7};
        int depth = depths[r.nextInt(r.nextInt(6) == 0 ? depths.length : 5)];
        int colourType = types[r.nextInt(r.nextInt(6) == 0 ? types.length : 5)];
        ByteBuffer ihdr = ByteBuffer.allocate(13).putInt(w).putInt(h).put((byte) depth).put((byte) colourType).put((byte) 0)
                .put((byte) 0).put((byte) (r.nextInt(5) == 0 ? 1 : 0));
        chunk(out, "IHDR", ihdr.array());
        if (colourType == 3 || r.nextInt(6) == 0) {
            chunk(out, "PLTE", randomBytes(r, 3 * (r.nextInt(5) == 0 ? r.nextInt(300) : 1 + r.nextInt(1 << Math.min(8, Math.max(1, depth))))));
        }
        if (r.nextInt(4) == 0) {
            chunk(out, "tRNS", randomBytes(r, r.nextInt(20)));
        }
        if (r.nextInt(6) == 0) {
            chunk(out, "gAMA", randomBytes(r, 4));
        }
        long rowBytes = ((long) Math.max(0, w) * Math.max(1, depth) * 4 + 7) / 8 + 1;
        int raw = (int) Math.min(1 << 16, rowBytes * Math.max(0, Math.min(h, 64)));
        byte[] pixels = randomBytes(r, raw);
        for (long i = 0; i < pixels.length; i += rowBytes) {
            pixels[(int) i] = (byte) r.nextInt(r.nextInt(10) == 0 ? 256 : 5);     // filter type
        }
        byte[] idat = r.nextInt(8) == 0 ? randomBytes(r, r.nextInt(100)) : zlib(pixels);
        int parts = 1 + r.nextInt(3);
        for (int p = 0; p < parts; p++) {
            chunk(out, "IDAT", java.util.Arrays.copyOfRange(idat, p * idat.length / parts, (p + 1) * idat.length / parts));
        }
        if (r.nextInt(6) != 0) {
            chunk(out, "IEND", new byte[0]);
        }
        return out.toByteArray();
    }

    private static void chunk(ByteArrayOutputStream out, String type, byte[] data) {
        byte[] t = type.getBytes(StandardCharsets.US_ASCII);
        out.writeBytes(ByteBuffer.allocate(4).putInt(data.length).array());
        out.writeBytes(t);
        out.writeBytes(data);
        CRC32 crc = new CRC32();
        crc.update(t);
        crc.update(data);
        out.writeBytes(ByteBuffer.allocate(4).putInt((int) crc.getValue()).array());
    }

    // ---- helpers ---------------------------------------------------------------------------------

    private static List<byte[]> resources(String dir, String extension) {
        try (Stream<Path> files = Files.list(Path.of("src", "test", "resources", dir))) {
            List<byte[]> out = new ArrayList<>();
            for (Path p : files.filter(f -> f.toString().endsWith(extension)).sorted().toList()) {
                out.add(Files.readAllBytes(p));
            }
            return out;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static byte[] randomBytes(SplittableRandom r, int n) {
        byte[] b = new byte[n];
        for (int i = 0; i < n; i++) {
            b[i] = (byte) (r.nextInt(3) == 0 ? 0 : r.nextInt(256));
        }
        return b;
    }

    private static byte[] zlib(byte[] data) {
        Deflater d = new Deflater();
        d.setInput(data);
        d.finish();
        byte[] buf = new byte[data.length + 64];
        int n = d.deflate(buf);
        d.end();
        return java.util.Arrays.copyOf(buf, n);
    }

    /** A little-endian byte builder. */
    private static final class Le {
        private final ByteArrayOutputStream out = new ByteArrayOutputStream();

        static byte[] ints(int... v) {
            ByteBuffer b = ByteBuffer.allocate(4 * v.length).order(ByteOrder.LITTLE_ENDIAN);
            for (int i : v) {
                b.putInt(i);
            }
            return b.array();
        }

        void b(int v) {
            out.write(v);
        }

        void i32(int v) {
            out.writeBytes(ints(v));
        }

        void i64(long v) {
            out.writeBytes(ByteBuffer.allocate(8).order(ByteOrder.LITTLE_ENDIAN).putLong(v).array());
        }

        void bytes(byte[] b) {
            out.writeBytes(b);
        }

        void text(String s) {
            out.writeBytes(s.getBytes(StandardCharsets.UTF_8));
            out.write(0);
        }

        void attribute(String name, String type, byte[] value) {
            attributeLying(name, type, value, value.length);
        }

        void attributeLying(String name, String type, byte[] value, int size) {
            text(name);
            text(type);
            i32(size);
            bytes(value);
        }

        int size() {
            return out.size();
        }

        byte[] bytes() {
            return out.toByteArray();
        }
    }
}
