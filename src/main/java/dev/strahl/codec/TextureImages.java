package dev.strahl.codec;

import dev.strahl.files.FileReads;
import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.IndexColorModel;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.event.IIOReadWarningListener;
import javax.imageio.stream.ImageInputStream;

/**
 * Reads PNG and JPEG images for textures, through the JDK's ImageIO decoders, from the decoded
 * raster's samples (never {@code getRGB}, which would squeeze 16-bit samples into 8 bits and apply
 * colour conversions).
 *
 * <p><b>The result.</b> A {@link ChannelImage}, top row first, with the file's channels: {@code Y}
 * (grey), {@code Y, A}, {@code R, G, B} or {@code R, G, B, A}; a palette image is expanded to
 * {@code R, G, B} (or {@code R, G, B, A} if its palette has transparency). Samples are the stored
 * integers divided by their maximum (255, 65535, or 1, 3, 15 for 1-, 2- and 4-bit grey), so in [0, 1]
 * and exact: a 16-bit sample k reads as k / 65535f, and {@code Math.round(v * 65535)} gives k back.
 * No transfer function is undone here (colour textures are sRGB-encoded; data textures are linear:
 * the texture code decides), and the PNG gAMA chunk and embedded colour profiles are not applied.
 *
 * <p><b>Errors.</b> A file that is neither PNG nor JPEG, another image format (GIF, BMP, ...), a
 * truncated or corrupt file (including the decoders' warnings, such as a JPEG that ends early and
 * would otherwise come back half grey), a JPEG in CMYK, or a size too large for the heap (checked
 * from the header, before decoding) is an {@link ImageFormatException} with one line naming the file.
 */
public final class TextureImages {
    private static final List<String> FORMATS = List.of("png", "jpeg");
    /** Bytes of PNG rows per byte of file at the most: zlib's largest ratio (about 1032) and a margin. */
    private static final double PNG_RATIO = 1100;
    /** Pixels per byte of JPEG at the most: a Huffman-coded 8x8 block takes a bit at the least (512), and a margin. */
    private static final double JPEG_PIXELS_PER_BYTE = 2048;

    private TextureImages() {
    }

    /**
     * Reads a PNG or JPEG file (recognised by its content, not its name).
     *
     * @param file the image
     * @return its samples, as described above
     * @throws ImageFormatException if the file is not a readable PNG or JPEG image
     * @throws IOException          if it cannot be read at all
     */
    public static ChannelImage read(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new ImageFormatException(file, "is a directory, not an image");
        }
        if (!Files.isReadable(file)) {
            Files.newByteChannel(file).close();       // the usual NoSuchFileException or AccessDeniedException
        }
        FileReads.note(file);
        long length = Files.size(file);
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            if (in == null) {
                throw new ImageFormatException(file, "cannot be opened as an image");
            }
            ImageReader reader = reader(file, in);
            try {
                String format = reader.getFormatName().toUpperCase(Locale.ROOT);
                int[] ihdr = format.equals("PNG") ? pngDepthAndColourType(in) : null;
                return decode(file, length, reader, format, ihdr);
            } finally {
                reader.dispose();
            }
        }
    }

    /** The PNG or JPEG decoder for the stream, chosen by its first bytes. */
    private static ImageReader reader(Path file, ImageInputStream in) throws IOException {
        List<String> others = new ArrayList<>();
        Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
        while (readers.hasNext()) {
            ImageReader r = readers.next();
            String format = r.getFormatName().toLowerCase(Locale.ROOT);
            if (FORMATS.contains(format)) {
                r.setInput(in, true, true);
                return r;
            }
            others.add(format.toUpperCase(Locale.ROOT));
            r.dispose();
        }
        throw new ImageFormatException(file, others.isEmpty() ? notATexture(in)
                : "a " + others.get(0) + " image: strahl reads PNG and JPEG textures");
    }

    /** What a file that no ImageIO decoder takes is, told by its first bytes: strahl's other image formats are named. */
    private static String notATexture(ImageInputStream in) throws IOException {
        byte[] head = new byte[4];
        in.seek(0);
        int n = in.read(head);
        String kind = n < 2 ? null
                : n == 4 && head[0] == 0x76 && head[1] == 0x2f && head[2] == 0x31 && head[3] == 0x01 ? "an OpenEXR image"
                : head[0] == '#' && head[1] == '?' ? "a Radiance HDR image"
                : head[0] == 'P' && (head[1] == 'F' || head[1] == 'f') ? "a PFM image"
                : null;
        return kind == null ? "not a PNG or JPEG image (strahl reads PNG and JPEG textures)"
                : kind + ": strahl reads PNG and JPEG textures (.exr, .hdr and .pfm are for environment maps)";
    }

    /**
     * The bit depth and colour type of a PNG (bytes 24 and 25 of the file: the IHDR chunk is always
     * first), or null if the file is too short. ImageIO decodes grey of 1, 2 and 4 bits into a palette
     * image, which must come back as grey, not RGB; and the size check needs the bits per pixel.
     */
    private static int[] pngDepthAndColourType(ImageInputStream in) throws IOException {
        in.mark();
        try {
            in.seek(24);
            int bits = in.read();
            int colourType = in.read();
            return colourType < 0 ? null : new int[] {bits, colourType};
        } finally {
            in.reset();
        }
    }

    /**
     * Checks the size the header claims before the decoder allocates anything: against one array,
     * against the file (a PNG's zlib data expand at most about 1032 times; a JPEG codes every 8x8
     * block in one bit at the least), against the time a JPEG's scans take ({@link JpegScans}), and
     * against the heap, which must hold the decoder's raster, the float samples and the texture's
     * second copy of them (flipped, or sRGB-decoded).
     */
    private static void checkSize(Path file, long length, String format, int[] ihdr, int width, int height) throws IOException {
        int channels = 3;                    // a JPEG's, at the most (grey or colour; CMYK is refused)
        int rasterBytes = 3;                 // the decoder's bytes per pixel
        if (ihdr != null) {
            int samplesPerPixel = switch (ihdr[1]) {
                case 2 -> 3;
                case 4 -> 2;
                case 6 -> 4;
                default -> 1;                // grey, or palette indices
            };
            channels = ihdr[1] == 3 ? 4 : samplesPerPixel;                 // a palette expands to RGB(A)
            rasterBytes = samplesPerPixel * (ihdr[0] > 8 ? 2 : 1);
            double rowBytes = 1 + Math.ceil((double) width * samplesPerPixel * Math.max(1, ihdr[0]) / 8);
            ImageLimits.checkArraySize(file, width, height, channels);
            ImageLimits.checkFileHolds(file, width, height, rowBytes * height, length, PNG_RATIO, "PNG's zlib compression");
        } else {
            ImageLimits.checkArraySize(file, width, height, channels);
            if (format.equals("JPEG")) {
                ImageLimits.checkFileHolds(file, width, height, (double) width * height, length, JPEG_PIXELS_PER_BYTE,
                        "JPEG coding (one bit per 8x8 block at the least)");
                JpegScans.check(file, width, height);
            }
        }
        long pixels = (long) width * height;
        // the raster, the float samples, and the texture's second copy of them
        ImageLimits.checkAllocation(file, width, height, channels, rasterBytes * pixels + 4L * channels * pixels);
    }

    private static ChannelImage decode(Path file, long length, ImageReader reader, String format, int[] ihdr)
            throws ImageFormatException {
        List<String> warnings = new ArrayList<>();
        reader.addIIOReadWarningListener((IIOReadWarningListener) (source, warning) -> warnings.add(warning));
        BufferedImage image;
        try {
            checkSize(file, length, format, ihdr, reader.getWidth(0), reader.getHeight(0));
            image = reader.read(0);
        } catch (ImageFormatException e) {
            throw e;
        } catch (IOException e) {
            throw new ImageFormatException(file, "corrupt or truncated " + format + " image (" + message(e) + ")", e);
        } catch (RuntimeException e) {
            // ImageIO's decoders answer some malformed files with unchecked exceptions
            throw new ImageFormatException(file, "corrupt " + format + " image (the decoder failed: " + message(e) + ")", e);
        }
        if (!warnings.isEmpty()) {
            throw new ImageFormatException(file, "corrupt or truncated " + format + " image (" + Printable.text(warnings.get(0), 120) + ")");
        }
        int greyBits = ihdr != null && ihdr[1] == 0 && ihdr[0] > 0 ? ihdr[0] : 0;
        return samples(image, greyBits);
    }

    private static String message(Throwable e) {
        String m = e.getMessage();
        Throwable cause = e.getCause();
        if (cause != null && cause.getMessage() != null && !cause.getMessage().equals(m)) {
            m = (m == null ? "" : m + ": ") + cause.getMessage();
        } else if (cause != null && m == null) {
            m = cause.getClass().getSimpleName();
        }
        return m == null ? e.getClass().getSimpleName() : Printable.text(m, 120);
    }

    private static ChannelImage samples(BufferedImage image, int greyBits) {
        int w = image.getWidth();
        int h = image.getHeight();
        Raster raster = image.getRaster();
        ColorModel cm = image.getColorModel();
        if (cm instanceof IndexColorModel && greyBits > 0 && greyBits < 8 && raster.getNumBands() == 1) {
            return greyIndices(raster, greyBits, w, h);
        }
        if (cm instanceof IndexColorModel palette) {
            return expandPalette(raster, palette, w, h);
        }
        int n = raster.getNumBands();
        float[] data = new float[n * w * h];
        int[] row = new int[w];
        for (int b = 0; b < n; b++) {
            float max = (1 << raster.getSampleModel().getSampleSize(b)) - 1;
            for (int y = 0; y < h; y++) {
                raster.getSamples(0, y, w, 1, b, row);
                for (int x = 0; x < w; x++) {
                    data[(y * w + x) * n + b] = row[x] / max;     // correctly rounded: k / 65535f exactly
                }
            }
        }
        return new ChannelImage(w, h, names(n), data);
    }

    private static ChannelImage expandPalette(Raster raster, IndexColorModel palette, int w, int h) {
        int n = palette.hasAlpha() ? 4 : 3;
        float[][] entries = new float[palette.getMapSize()][n];
        for (int i = 0; i < entries.length; i++) {
            entries[i][0] = palette.getRed(i) / 255f;
            entries[i][1] = palette.getGreen(i) / 255f;
            entries[i][2] = palette.getBlue(i) / 255f;
            if (n == 4) {
                entries[i][3] = palette.getAlpha(i) / 255f;
            }
        }
        float[] data = new float[n * w * h];
        int[] row = new int[w];
        for (int y = 0; y < h; y++) {
            raster.getSamples(0, y, w, 1, 0, row);
            for (int x = 0; x < w; x++) {
                // an index past the palette (a corrupt file) reads as the last entry
                System.arraycopy(entries[Math.min(row[x], entries.length - 1)], 0, data, (y * w + x) * n, n);
            }
        }
        return new ChannelImage(w, h, names(n), data);
    }

    /** A grey PNG of 1, 2 or 4 bits, which ImageIO gives as indices into a grey ramp: the index is the grey level. */
    private static ChannelImage greyIndices(Raster raster, int bits, int w, int h) {
        float max = (1 << bits) - 1;
        float[] data = new float[w * h];
        int[] row = new int[w];
        for (int y = 0; y < h; y++) {
            raster.getSamples(0, y, w, 1, 0, row);
            for (int x = 0; x < w; x++) {
                data[y * w + x] = Math.min(row[x], max) / max;
            }
        }
        return new ChannelImage(w, h, List.of("Y"), data);
    }

    private static List<String> names(int n) {
        return switch (n) {
            case 1 -> List.of("Y");
            case 2 -> List.of("Y", "A");
            case 3 -> List.of("R", "G", "B");
            case 4 -> List.of("R", "G", "B", "A");
            default -> {
                List<String> names = new ArrayList<>();
                for (int i = 0; i < n; i++) {
                    names.add("C" + i);
                }
                yield names;
            }
        };
    }
}
