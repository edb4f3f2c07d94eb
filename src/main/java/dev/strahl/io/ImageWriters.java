package dev.strahl.io;

import dev.strahl.film.Film;
import dev.strahl.image.Image;
import dev.strahl.io.image.AtomicFile;
import dev.strahl.io.image.PfmWriter;
import dev.strahl.io.image.PngWriter;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Objects;

/**
 * Writes images to files, choosing the format by the file name's extension (case-insensitive):
 * <ul>
 *   <li>{@code .png} — 8-bit sRGB: clamped to [0, 1], sRGB transfer function, no exposure;</li>
 *   <li>{@code .pfm} — linear 32-bit float RGB, the values exactly as rendered.</li>
 * </ul>
 * Writes are atomic ({@link AtomicFile}): the image goes to a temporary file in the same
 * directory, which is then renamed over the target. An interrupted or failed write leaves the
 * previous file (if any) untouched and no partial or temporary file behind.
 */
public final class ImageWriters {

    private enum Format { PNG, PFM }

    private ImageWriters() {
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
        Format format = formatOf(out);
        AtomicFile.write(out, os -> {
            if (format == Format.PNG) {
                PngWriter.write(img, os);
            } else {
                PfmWriter.write(img, os);
            }
        });
    }

    /**
     * Writes the current mean image of a film ({@link Film#toImage()}); otherwise as
     * {@link #write(Image, Path)}.
     *
     * @param film the film, possibly still being rendered into
     * @param out  the file to write, ending in {@code .png} or {@code .pfm}
     * @throws IllegalArgumentException if the extension is not a supported format (nothing is written)
     * @throws IOException              if the directory of {@code out} does not exist or the file cannot
     *                                  be written; {@code out} is then unchanged
     */
    public static void write(Film film, Path out) throws IOException {
        Objects.requireNonNull(film, "film");
        formatOf(out);                       // refuse a bad name before copying the film
        write(film.toImage(), out);
    }

    /**
     * Whether {@link #write(Image, Path)} can write a file of this name.
     *
     * @param path a file name or path
     * @return true if its extension is {@code .png} or {@code .pfm}, in any case
     */
    public static boolean isSupported(Path path) {
        String ext = extension(path);
        return ext.equals("png") || ext.equals("pfm");
    }

    private static Format formatOf(Path out) {
        String ext = extension(out);
        switch (ext) {
            case "png":
                return Format.PNG;
            case "pfm":
                return Format.PFM;
            case "":
                throw new IllegalArgumentException("image file name " + out + " has no extension: use .png or .pfm");
            default:
                String given = out.getFileName().toString();
                throw new IllegalArgumentException("unknown image format '" + given.substring(given.lastIndexOf('.'))
                        + "' of " + out + ": use .png or .pfm");
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
