package dev.strahl.film;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Locale;
import java.util.Objects;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Writes images to files, choosing the format by the file name's extension (case-insensitive):
 * <ul>
 *   <li>{@code .png} — 8-bit sRGB: clamped to [0, 1], sRGB transfer function, no exposure;</li>
 *   <li>{@code .pfm} — linear 32-bit float RGB, the values exactly as rendered.</li>
 * </ul>
 * Writes are atomic: the image goes to a temporary file in the same directory, which is then
 * renamed over the target. An interrupted or failed write leaves the previous file (if any)
 * untouched and no partial or temporary file behind.
 */
public final class ImageWriters {

    private enum Format { PNG, PFM }

    /** Writes an encoded image to a stream; used to test the atomic write with failing encoders. */
    @FunctionalInterface
    interface Encoder {
        void writeTo(OutputStream out) throws IOException;
    }

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
        writeAtomically(out, os -> {
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

    /**
     * Writes {@code out} through a temporary file in the same directory and a rename, so that
     * readers see either the old file or the complete new one. On any failure (including an
     * exception from the encoder) the temporary file is deleted and the exception rethrown.
     */
    static void writeAtomically(Path out, Encoder encoder) throws IOException {
        Path target = out.toAbsolutePath();
        Path dir = target.getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new IOException("output directory does not exist: " + dir);
        }
        if (Files.isDirectory(target)) {
            // a rename would silently replace an empty directory
            throw new IOException("cannot write image " + out + ": it is a directory");
        }
        Path tmp = null;
        try {
            OutputStream raw = null;
            for (int attempt = 0; raw == null; attempt++) {
                Path candidate = tempName(dir, target.getFileName().toString());
                try {
                    raw = Files.newOutputStream(candidate, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
                    tmp = candidate;
                } catch (FileAlreadyExistsException e) {
                    if (attempt == 99) {
                        throw e;
                    }
                }
            }
            try (OutputStream os = new BufferedOutputStream(raw, 1 << 16)) {
                encoder.writeTo(os);
            }
            move(tmp, target);
        } catch (Throwable t) {
            if (tmp != null) {
                try {
                    Files.deleteIfExists(tmp);
                } catch (IOException e) {
                    t.addSuppressed(e);
                }
            }
            throw t;
        }
    }

    /**
     * ".name&lt;random&gt;.tmp", hidden and recognisable, the naming of
     * {@code Files.createTempFile(dir, "." + name, ".tmp")}. Not createTempFile itself: it creates
     * the file with permissions rw------- on POSIX systems, which the rename would pass on to the
     * image; CREATE_NEW gives the usual permissions (0666 minus the umask).
     */
    private static Path tempName(Path dir, String name) {
        if (name.length() > 200) {
            name = name.substring(0, 200);   // room for the suffix within the usual 255-byte name limit
        }
        return dir.resolve("." + name + Long.toUnsignedString(ThreadLocalRandom.current().nextLong()) + ".tmp");
    }

    private static void move(Path tmp, Path target) throws IOException {
        try {
            Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
        }
    }
}
