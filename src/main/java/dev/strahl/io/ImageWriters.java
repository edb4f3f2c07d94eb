package dev.strahl.io;

import dev.strahl.color.DisplayEncoding;
import dev.strahl.image.Image;
import dev.strahl.image.ToneMapping;
import dev.strahl.codec.exr.ExrCompression;
import dev.strahl.codec.exr.ExrPixelType;
import dev.strahl.codec.exr.ExrWriter;
import dev.strahl.files.AtomicFile;
import dev.strahl.codec.PfmWriter;
import dev.strahl.codec.PngWriter;
import dev.strahl.render.Aov;
import dev.strahl.render.RenderBuffers;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * Writes images to files, choosing the format by the file name's extension (case-insensitive):
 * <ul>
 *   <li>{@code .png} — 8-bit sRGB: exposure and tone curve ({@link #withExposure},
 *       {@link #withToneMapping}; by default none and clamping to [0, 1]), then the sRGB transfer function;</li>
 *   <li>{@code .pfm} — linear 32-bit float RGB, the values exactly as rendered;</li>
 *   <li>{@code .exr} — OpenEXR, scanline, linear: channels {@code R}, {@code G}, {@code B} and,
 *       from {@link RenderBuffers}, the feature buffers in the same file as {@code albedo.R/G/B},
 *       {@code normal.X/Y/Z}, {@code depth.Z} and the sample counts as {@code spp.Y} (those two always
 *       32-bit float: depths exceed half's range, counts its exact integers); {@code half} samples (the default) or {@code float}, ZIP compression (the
 *       default) or none.</li>
 * </ul>
 * With PNG or PFM output, the feature buffers go to files beside it, named after it:
 * {@code out.albedo.pfm}, {@code out.normal.pfm}, {@code out.depth.pfm}, {@code out.spp.pfm} (linear
 * float; depth and the sample count in all three channels).
 *
 * <p>Writes are atomic ({@link AtomicFile}): the image goes to a temporary file in the same
 * directory, which is then renamed over the target. An interrupted or failed write leaves the
 * previous file (if any) untouched and no partial or temporary file behind.
 */
public final class ImageWriters {

    private enum Format { PNG, PFM, EXR }

    private static final ImageWriters DEFAULTS = new ImageWriters(ToneMapping.CLAMP, 0, false, true);

    private final ToneMapping toneMapping;
    private final double exposure;
    private final boolean exrFloat;
    private final boolean exrZip;

    private ImageWriters(ToneMapping toneMapping, double exposure, boolean exrFloat, boolean exrZip) {
        this.toneMapping = Objects.requireNonNull(toneMapping, "toneMapping");
        if (!Double.isFinite(exposure)) {
            throw new IllegalArgumentException("exposure must be a finite number of stops, got " + exposure);
        }
        this.exposure = exposure;
        this.exrFloat = exrFloat;
        this.exrZip = exrZip;
    }

    /**
     * A writer as {@link #write(Image, Path)} writes: PNGs clamped at exposure 0, as they always
     * were; EXRs with half samples and ZIP compression, as Mitsuba writes them. The {@code with...}
     * methods return changed copies. Linear outputs (PFM, EXR) hold the values as rendered whatever
     * the exposure and curve.
     *
     * @return the default writer
     */
    public static ImageWriters defaults() {
        return DEFAULTS;
    }

    /**
     * This writer with another tone curve for PNGs.
     *
     * @param curve the PNG's tone curve
     * @return a new writer
     */
    public ImageWriters withToneMapping(ToneMapping curve) {
        return new ImageWriters(curve, exposure, exrFloat, exrZip);
    }

    /**
     * This writer with another exposure for PNGs.
     *
     * @param stops each value is multiplied by 2^stops before the tone curve; finite
     * @return a new writer
     */
    public ImageWriters withExposure(double stops) {
        return new ImageWriters(toneMapping, stops, exrFloat, exrZip);
    }

    /**
     * This writer with other EXR samples.
     *
     * @param asFloat 32-bit float samples rather than 16-bit half (depth is float either way)
     * @return a new writer
     */
    public ImageWriters withExrFloat(boolean asFloat) {
        return new ImageWriters(toneMapping, exposure, asFloat, exrZip);
    }

    /**
     * This writer with or without EXR compression.
     *
     * @param zip ZIP-compress the EXR (else uncompressed)
     * @return a new writer
     */
    public ImageWriters withExrZip(boolean zip) {
        return new ImageWriters(toneMapping, exposure, exrFloat, zip);
    }

    /**
     * Writes an image to a file in the format given by its extension, replacing any existing file.
     *
     * @param img the linear image
     * @param out the file to write, ending in {@code .png} or {@code .pfm}
     * @throws IllegalArgumentException if the extension is not a supported format (nothing is written)
     * @throws IOException              if the directory of {@code out} does not exist or the file cannot
     *                                  be written; {@code out} is then unchanged
     */
    public static void write(Image img, Path out) throws IOException {
        Objects.requireNonNull(img, "img");
        DEFAULTS.write(RenderBuffers.of(img), out);
    }

    /**
     * Writes a render's image and its feature buffers and sample counts (those that are not null):
     * in one EXR file, or beside a PNG or PFM as {@code NAME.albedo.pfm}, {@code NAME.normal.pfm},
     * {@code NAME.depth.pfm}, {@code NAME.spp.pfm} (where {@code NAME} is {@code out} without its
     * extension). The variance is not written.
     *
     * The PNG's tone curve and exposure, the EXR's sample type and compression are this writer's.
     *
     * @param buffers the image and its feature buffers
     * @param out     the file to write, ending in {@code .png}, {@code .pfm} or {@code .exr}
     * @throws IllegalArgumentException if the extension is not a supported format (nothing is written)
     * @throws IOException              if a file cannot be written; each file is replaced atomically
     */
    public void write(RenderBuffers buffers, Path out) throws IOException {
        Objects.requireNonNull(buffers, "buffers");
        Format format = formatOf(out);
        Image img = buffers.color();
        if (format == Format.EXR) {
            writeExr(buffers, out);
            return;
        }
        AtomicFile.write(out, os -> {
            if (format == Format.PNG) {
                PngWriter.write(DisplayEncoding.toBufferedImage(img, exposure, toneMapping), os);
            } else {
                PfmWriter.write(img, os);
            }
        });
        for (Aov aov : Aov.values()) {
            Image feature = buffers.aov(aov);
            if (feature != null) {
                Path side = featureFile(out, aov);
                AtomicFile.write(side, os -> PfmWriter.write(feature, os));
            }
        }
    }

    /**
     * Where {@link #write(RenderBuffers, Path)} puts a feature buffer beside a PNG or PFM.
     *
     * @param out the image file
     * @param aov the feature buffer
     * @return {@code NAME.albedo.pfm} and so on, in the directory of {@code out}
     */
    public static Path featureFile(Path out, Aov aov) {
        String name = out.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String base = dot < 0 ? name : name.substring(0, dot);
        return out.resolveSibling(base + "." + aov.id() + ".pfm");
    }

    private void writeExr(RenderBuffers buffers, Path out) throws IOException {
        Image img = buffers.color();
        int w = img.width();
        int h = img.height();
        List<ExrWriter.Channel> channels = new ArrayList<>();
        addChannels(channels, img, new String[] {"R", "G", "B"}, null);
        if (buffers.albedo() != null) {
            addChannels(channels, buffers.albedo(), new String[] {"albedo.R", "albedo.G", "albedo.B"}, null);
        }
        if (buffers.normal() != null) {
            addChannels(channels, buffers.normal(), new String[] {"normal.X", "normal.Y", "normal.Z"}, null);
        }
        if (buffers.depth() != null) {
            addChannels(channels, buffers.depth(), new String[] {"depth.Z"}, ExrPixelType.FLOAT);
        }
        if (buffers.samples() != null) {
            addChannels(channels, buffers.samples(), new String[] {"spp.Y"}, ExrPixelType.FLOAT);
        }
        ExrWriter.write(out, w, h, channels, new ExrWriter.Options(exrFloat ? ExrPixelType.FLOAT : ExrPixelType.HALF,
                exrZip ? ExrCompression.ZIP : ExrCompression.NONE));
    }

    private static void addChannels(List<ExrWriter.Channel> dest, Image img, String[] names, ExrPixelType type) {
        int pixels = img.width() * img.height();
        float[] rgb = img.rgb();
        for (int c = 0; c < names.length; c++) {
            float[] v = new float[pixels];
            for (int p = 0; p < pixels; p++) {
                v[p] = rgb[3 * p + c];
            }
            dest.add(new ExrWriter.Channel(names[c], v, type));
        }
    }

    /**
     * Whether {@link #write(Image, Path)} can write a file of this name.
     *
     * @param path a file name or path
     * @return true if its extension is {@code .png}, {@code .pfm} or {@code .exr}, in any case
     */
    public static boolean isSupported(Path path) {
        String ext = extension(path);
        return ext.equals("png") || ext.equals("pfm") || ext.equals("exr");
    }

    private static Format formatOf(Path out) {
        String ext = extension(out);
        switch (ext) {
            case "png":
                return Format.PNG;
            case "pfm":
                return Format.PFM;
            case "exr":
                return Format.EXR;
            case "":
                throw new IllegalArgumentException("image file name " + out + " has no extension: use .png, .pfm or .exr");
            default:
                String given = out.getFileName().toString();
                throw new IllegalArgumentException("unknown image format '" + given.substring(given.lastIndexOf('.'))
                        + "' of " + out + ": use .png, .pfm or .exr");
        }
    }

    /** The lower-case extension of the file name without the dot, or "" if it has none. */
    private static String extension(Path path) {
        Path name = Objects.requireNonNull(path, "path").getFileName();
        if (name == null) {
            return "";
        }
        String s = name.toString();
        int dot = s.lastIndexOf('.');
        return dot < 0 ? "" : s.substring(dot + 1).toLowerCase(Locale.ROOT);
    }
}
