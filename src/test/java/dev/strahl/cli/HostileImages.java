package dev.strahl.cli;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32;
import java.util.zip.Deflater;
import javax.imageio.ImageIO;

/**
 * Truncated, corrupt, unsupported and bomb image files of every format strahl reads (EXR in its five
 * compressions and the ones it names as unsupported, Radiance HDR flat and run-length encoded, PFM,
 * PNG, JPEG), made from the test fixtures or from scratch. Each comes with the fragments its one-line
 * error must hold besides the file's name (the element at fault, the size a bomb claims).
 */
final class HostileImages {
    /** A hostile file: its name (the extension tells the format), its bytes, and what its error line must say. */
    record Hostile(String name, byte[] bytes, List<String> fragments) {
        String format() {
            return name.substring(name.lastIndexOf('.') + 1);
        }

        @Override
        public String toString() {
            return name;
        }
    }

    private HostileImages() {}

    static Hostile hostile(String name, byte[] bytes, String... fragments) {
        return new Hostile(name, bytes, List.of(fragments));
    }

    static byte[] fixture(String name) {
        try {
            return Files.readAllBytes(Path.of("src/test/resources", name));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static List<Hostile> all() {
        List<Hostile> all = new ArrayList<>();
        all.addAll(exr());
        all.addAll(hdr());
        all.addAll(pfm());
        all.addAll(png());
        all.addAll(jpeg());
        return all;
    }

    // ---- EXR ---------------------------------------------------------------------------------------

    /** Where a scanline EXR file keeps its attributes' values, and its offset table. */
    record ExrLayout(Map<String, Integer> values, int table) {
        static ExrLayout of(byte[] b) {
            Map<String, Integer> values = new LinkedHashMap<>();
            int p = 8;
            while (b[p] != 0) {
                int e = p;
                while (b[e] != 0) {
                    e++;
                }
                String name = new String(b, p, e - p, StandardCharsets.US_ASCII);
                p = e + 1;
                while (b[p] != 0) {
                    p++;
                }
                p++;
                int size = le(b).getInt(p);
                values.put(name, p + 4);
                p += 4 + size;
            }
            return new ExrLayout(values, p + 1);
        }

        int chunk(byte[] b, int i) {
            return (int) le(b).getLong(table + 8 * i);
        }
    }

    static ByteBuffer le(byte[] b) {
        return ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
    }

    static List<Hostile> exr() {
        List<Hostile> out = new ArrayList<>();
        for (String c : List.of("none", "rle", "zips", "zip", "piz")) {
            byte[] ok = fixture("exr/mixed-" + c + ".exr");
            ExrLayout l = ExrLayout.of(ok);
            out.add(hostile(c + "-cut-in-header.exr", Arrays.copyOf(ok, 100), "truncated"));
            out.add(hostile(c + "-cut-in-table.exr", Arrays.copyOf(ok, l.table + 12), "truncated"));
            out.add(hostile(c + "-cut-in-pixels.exr", Arrays.copyOf(ok, ok.length - 40), "truncated"));
            byte[] wrongY = ok.clone();
            le(wrongY).putInt(l.chunk(ok, 1), 12345);
            out.add(hostile(c + "-chunk-y.exr", wrongY, "chunk 1", "y = 12345"));
            byte[] size = ok.clone();
            le(size).putInt(l.chunk(ok, 1) + 4, 0x7fff0000);
            out.add(hostile(c + "-chunk-size.exr", size, "chunk 1"));
            byte[] outside = ok.clone();
            le(outside).putLong(l.table + 8, 1L << 40);
            out.add(hostile(c + "-offset-outside.exr", outside, "chunk 1", "outside the pixel data"));
            byte[] swapped = ok.clone();
            le(swapped).putLong(l.table, l.chunk(ok, 1)).putLong(l.table + 8, l.chunk(ok, 0));
            out.add(hostile(c + "-offsets-swapped.exr", swapped, "chunk 1", "the table is corrupt"));
        }
        out.addAll(corruptData());
        byte[] ok = fixture("exr/rgba-half-zip.exr");
        ExrLayout l = ExrLayout.of(ok);
        String[] unsupported = {"PXR24", "B44", "B44A", "DWAA", "DWAB"};
        for (int i = 0; i < unsupported.length; i++) {
            byte[] b = ok.clone();
            b[l.values.get("compression")] = (byte) (5 + i);
            out.add(hostile(unsupported[i].toLowerCase() + ".exr", b, "EXR compression " + unsupported[i] + " is not supported"));
        }
        out.add(hostile("b44-by-openexr.exr", fixture("exr/refused-b44.exr"), "B44"));
        out.add(hostile("tiled.exr", fixture("exr/refused-tiled.exr"), "tiled"));
        out.add(hostile("two-parts.exr", fixture("exr/refused-two-parts.exr"), "multi-part"));
        out.add(hostile("inverted-window.exr", window(ok, l, 10, 0, 2, 4), "inverted"));
        out.add(hostile("negative-window.exr", window(ok, l, 0, 0, -2_000_000_000, 4), "inverted"));
        out.add(hostile("bomb-200000.exr", window(ok, l, 0, 0, 199_999, 199_999), "200000x200000"));
        out.add(hostile("bomb-widest.exr", window(ok, l, Integer.MIN_VALUE, 0, Integer.MAX_VALUE, 0), "4294967296x1"));
        byte[] magic = ok.clone();
        magic[0] = 0x1b;
        out.add(hostile("not-exr.exr", magic, "not an OpenEXR file"));
        return out;
    }

    /**
     * Compressed pixel data that do not decode: a corrupt zlib stream (ZIPS, ZIP), an RLE run longer
     * than the chunk, a PIZ chunk scrambled. (Corrupt data of a chunk stored raw, as NONE or where
     * compression did not pay, are only other pixel values: no reader can tell.)
     */
    private static List<Hostile> corruptData() {
        List<Hostile> out = new ArrayList<>();
        for (String c : List.of("zips", "zip")) {
            byte[] b = fixture("exr/mixed-" + c + ".exr");
            int data = ExrLayout.of(b).chunk(b, 0) + 8;
            for (int i = 0; i < 24; i++) {
                b[data + 6 + i] ^= (byte) (0x5a + 7 * i);
            }
            out.add(hostile(c + "-data-scrambled.exr", b, "chunk 0", c.toUpperCase()));
        }
        byte[] rle = fixture("exr/mixed-rle.exr");
        rle[ExrLayout.of(rle).chunk(rle, 0) + 8] = 127;           // a run of 128 bytes, in a chunk of 90
        out.add(hostile("rle-run-too-long.exr", rle, "chunk 0", "RLE"));
        byte[] piz = fixture("exr/piz-wide-range.exr");
        int data = ExrLayout.of(piz).chunk(piz, 0) + 8;
        for (int i = 0; i < 64; i++) {
            piz[data + 2000 + i] ^= (byte) (0x5a + 7 * i);
        }
        out.add(hostile("piz-data-scrambled.exr", piz, "chunk 0", "PIZ"));
        return out;
    }

    private static byte[] window(byte[] ok, ExrLayout l, int xMin, int yMin, int xMax, int yMax) {
        byte[] b = ok.clone();
        le(b).putInt(l.values.get("dataWindow"), xMin).putInt(l.values.get("dataWindow") + 4, yMin)
                .putInt(l.values.get("dataWindow") + 8, xMax).putInt(l.values.get("dataWindow") + 12, yMax);
        return b;
    }

    // ---- HDR ---------------------------------------------------------------------------------------

    static List<Hostile> hdr() {
        List<Hostile> out = new ArrayList<>();
        byte[] flat = fixture("hdr/opencv-flat.hdr");
        byte[] rle = fixture("hdr/opencv-rle.hdr");
        out.add(hostile("flat-cut.hdr", Arrays.copyOf(flat, flat.length * 2 / 3), "truncated"));
        out.add(hostile("rle-cut.hdr", Arrays.copyOf(rle, rle.length * 2 / 3), "truncated"));
        out.add(hostile("header-cut.hdr", Arrays.copyOf(rle, 20), "truncated"));
        String head = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 16\n";
        byte[] overflow = concat(head.getBytes(StandardCharsets.US_ASCII), new byte[] {2, 2, 0, 16, (byte) (128 + 100), 7}, new byte[40]);
        out.add(hostile("rle-run-overflow.hdr", overflow, "scanline 0", "goes past the end of the 16-pixel scanline"));
        byte[] literal = concat(head.getBytes(StandardCharsets.US_ASCII), new byte[] {2, 2, 0, 16, 100, 1, 2, 3}, new byte[40]);
        out.add(hostile("rle-literal-overflow.hdr", literal, "scanline 0", "go past the end of the 16-pixel scanline"));
        out.add(hostile("bomb-60000.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 60000 +X 60000\n".getBytes(StandardCharsets.US_ASCII),
                "60000 scanlines of 60000 pixels"));
        out.add(hostile("zero-size.hdr", "#?RADIANCE\n\n-Y 0 +X 8\n\0\0\0\0".getBytes(StandardCharsets.US_ASCII), "bad image size"));
        out.add(hostile("bad-resolution.hdr", "#?RADIANCE\n\n-Y 8 \u001b[31m+X 8\n".getBytes(StandardCharsets.ISO_8859_1),
                "bad resolution line"));
        out.add(hostile("binary.hdr", new byte[] {0x7f, 'E', 'L', 'F', 2, 1, 1, 0, '\n', 0x1b, '[', '2', 'J'}, "not a Radiance HDR file"));
        out.add(hostile("xyze.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\1\1\1\1".getBytes(StandardCharsets.US_ASCII),
                "XYZE"));
        return out;
    }

    // ---- PFM ---------------------------------------------------------------------------------------

    static List<Hostile> pfm() {
        byte[] twelve = new byte[12 * 4];
        return List.of(
                hostile("cut.pfm", concat("PF\n4 4\n-1\n".getBytes(StandardCharsets.US_ASCII), twelve), "truncated PFM data"),
                hostile("bomb.pfm", concat("PF\n100000 100000\n-1\n".getBytes(StandardCharsets.US_ASCII), twelve), "100000x100000"),
                hostile("binary.pfm", new byte[] {'P', 'F', 0x1b, '[', '3', '1', 'm', '\n', 1, 2, 3, '\n'}, "PFM"),
                hostile("zero.pfm", concat("Pf\n0 4\n-1\n".getBytes(StandardCharsets.US_ASCII), twelve), "invalid PFM width '0'"),
                hostile("nan-scale.pfm", concat("PF\n1 1\nNaN\n".getBytes(StandardCharsets.US_ASCII), twelve), "invalid PFM scale"));
    }

    // ---- PNG ---------------------------------------------------------------------------------------

    static byte[] pngOf(BufferedImage image, String format) {
        try {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ImageIO.write(image, format, out);
            return out.toByteArray();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** A noisy image, so that its PNG and JPEG data fill the file. */
    static BufferedImage noisy(int w, int h) {
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        java.util.SplittableRandom r = new java.util.SplittableRandom(3);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                image.setRGB(x, y, r.nextInt(1 << 24));
            }
        }
        return image;
    }

    /** A PNG chunk with its CRC. */
    static byte[] chunk(String type, byte[] data) {
        ByteBuffer b = ByteBuffer.allocate(12 + data.length);
        b.putInt(data.length).put(type.getBytes(StandardCharsets.US_ASCII)).put(data);
        CRC32 crc = new CRC32();
        crc.update(b.array(), 4, 4 + data.length);
        b.putInt((int) crc.getValue());
        return b.array();
    }

    static byte[] png(int width, int height, int bits, int colourType, byte[] idat) {
        byte[] ihdr = ByteBuffer.allocate(13).putInt(width).putInt(height).put((byte) bits).put((byte) colourType).put(new byte[3]).array();
        return concat(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}, chunk("IHDR", ihdr), chunk("IDAT", idat),
                chunk("IEND", new byte[0]));
    }

    /**
     * A real decompression bomb: an 8000x8000 RGBA PNG of zeros, about 250 kB, that decodes to 256 MB
     * of samples and four times that in floats: more than a 2 GB heap holds for a texture.
     */
    static byte[] zlibBomb() {
        int w = 8000;
        int h = 8000;
        byte[] row = new byte[1 + 4 * w];
        Deflater deflater = new Deflater(9);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        byte[] buffer = new byte[1 << 16];
        for (int y = 0; y < h; y++) {
            deflater.setInput(row);
            while (!deflater.needsInput()) {
                out.write(buffer, 0, deflater.deflate(buffer));
            }
        }
        deflater.finish();
        while (!deflater.finished()) {
            out.write(buffer, 0, deflater.deflate(buffer));
        }
        deflater.end();
        return png(w, h, 8, 6, out.toByteArray());
    }

    static List<Hostile> png() {
        byte[] ok = pngOf(noisy(64, 48), "png");
        byte[] scrambled = ok.clone();
        for (int i = 0; i < 40; i++) {
            scrambled[ok.length / 2 + i] ^= (byte) (0x35 + 11 * i);
        }
        java.util.zip.Deflater d = new java.util.zip.Deflater();
        d.setInput(new byte[100]);
        d.finish();
        byte[] small = new byte[64];
        int n = d.deflate(small);
        byte[] tinyIdat = Arrays.copyOf(small, n);
        return List.of(
                hostile("cut.png", Arrays.copyOf(ok, ok.length / 2), "PNG"),
                hostile("header-cut.png", Arrays.copyOf(ok, 30), "PNG"),
                hostile("scrambled.png", scrambled, "PNG"),
                hostile("bomb-60000.png", png(60_000, 60_000, 8, 2, tinyIdat), "60000x60000"),
                hostile("bomb-8000-of-74-bytes.png", png(8000, 8000, 8, 6, tinyIdat), "8000x8000"),
                hostile("zlib-bomb-8000.png", zlibBomb(), "8000x8000"),
                hostile("zero-width.png", png(0, 8, 8, 2, tinyIdat), "PNG"),
                hostile("gif.png", pngOf(new BufferedImage(4, 4, BufferedImage.TYPE_BYTE_INDEXED), "gif"), "a GIF image"),
                hostile("exr-inside.png", fixture("exr/rgba-half-zip.exr"), "OpenEXR"),
                hostile("binary.png", new byte[] {0x1b, '[', '2', 'J', 0, 1, 2, 3, 4, 5, 6, 7, 8}, "not a PNG or JPEG image"));
    }

    // ---- JPEG --------------------------------------------------------------------------------------

    static List<Hostile> jpeg() {
        byte[] ok = pngOf(noisy(64, 48), "jpeg");
        byte[] scrambled = ok.clone();
        for (int i = 0; i < 64; i++) {
            scrambled[ok.length / 2 + i] = (byte) 0xff;
        }
        // a JPEG whose frame header claims 65000x65000: the SOF0 height and width of the real file patched
        byte[] bomb = ok.clone();
        for (int i = 2; i + 8 < bomb.length; i++) {
            if ((bomb[i] & 0xff) == 0xff && (bomb[i + 1] & 0xff) == 0xc0) {
                ByteBuffer.wrap(bomb).putShort(i + 5, (short) 65000).putShort(i + 7, (short) 65000);
                break;
            }
        }
        return List.of(
                hostile("scan-bomb.jpg", scanBomb(), "300 scans"),
                hostile("cut.jpg", Arrays.copyOf(ok, ok.length / 2), "JPEG"),
                hostile("header-cut.jpg", Arrays.copyOf(ok, 100), "JPEG"),
                hostile("scrambled.jpg", scrambled, "JPEG"),
                hostile("bomb-65000.jpg", bomb, "65000x65000"));
    }

    /**
     * A progressive JPEG whose last scan is repeated until it has 300: the decoder passes over the
     * whole image once per scan (a 4000x4000 one of 2000 scans, 125 kB, took it 146 s).
     */
    static byte[] scanBomb() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (var stream = ImageIO.createImageOutputStream(out)) {
            var writer = ImageIO.getImageWritersByFormatName("jpeg").next();
            var param = writer.getDefaultWriteParam();
            param.setProgressiveMode(javax.imageio.ImageWriteParam.MODE_DEFAULT);
            writer.setOutput(stream);
            writer.write(null, new javax.imageio.IIOImage(noisy(64, 64), null, null), param);
            writer.dispose();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        byte[] b = out.toByteArray();
        int lastScan = -1;
        for (int i = 2; i + 1 < b.length; i++) {
            if ((b[i] & 0xff) == 0xff && (b[i + 1] & 0xff) == 0xda) {
                lastScan = i;
            }
        }
        int end = b.length - 2;                          // the EOI marker
        ByteArrayOutputStream bomb = new ByteArrayOutputStream();
        bomb.write(b, 0, end);
        int scans = 0;
        for (int i = 2; i + 1 < end; i++) {
            scans += (b[i] & 0xff) == 0xff && (b[i + 1] & 0xff) == 0xda ? 1 : 0;
        }
        for (; scans < 300; scans++) {
            bomb.write(b, lastScan, end - lastScan);
        }
        bomb.write(b, end, 2);
        return bomb.toByteArray();
    }

    static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] p : parts) {
            out.writeBytes(p);
        }
        return out.toByteArray();
    }
}
