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
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            if (in == null) {
                throw new ImageFormatException(file, "cannot be opened as an image");
            }
            ImageReader reader = reader(file, in);
            try {
                String format = reader.getFormatName().toUpperCase(Locale.ROOT);
                int greyBits = format.equals("PNG") ? greyBitDepth(in) : 0;
                return decode(file, reader, format, greyBits);
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
        throw new ImageFormatException(file, others.isEmpty()
                ? "not a PNG or JPEG image (strahl reads PNG and JPEG textures)"
                : "a " + others.get(0) + " image: strahl reads PNG and JPEG textures");
    }

    /**
     * The bit depth of a grey PNG (IHDR colour type 0), else 0: ImageIO decodes grey of 1, 2 and 4
     * bits into a palette image, which must come back as grey, not RGB. The IHDR chunk is always
     * first: its bit depth and colour type are bytes 24 and 25 of the file.
     */
    private static int greyBitDepth(ImageInputStream in) throws IOException {
        in.mark();
        try {
            in.seek(24);
            int bits = in.read();
            int colourType = in.read();
            return colourType == 0 && bits > 0 ? bits : 0;
        } finally {
            in.reset();
        }
    }

    private static ChannelImage decode(Path file, ImageReader reader, String format, int greyBits) throws ImageFormatException {
        List<String> warnings = new ArrayList<>();
        reader.addIIOReadWarningListener((IIOReadWarningListener) (source, warning) -> warnings.add(warning));
        BufferedImage image;
        try {
            int width = reader.getWidth(0);
            int height = reader.getHeight(0);
            // the decoder's raster (up to 4 bands of 16 bits) and the floats (up to 4 channels)
            ImageLimits.checkAllocation(file, width, height, 4, 8L * width * height);
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
            throw new ImageFormatException(file, "corrupt or truncated " + format + " image (" + warnings.get(0) + ")");
        }
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
        return m == null ? e.getClass().getSimpleName() : m.replace('\n', ' ');
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
