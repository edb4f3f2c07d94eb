package dev.strahl.codec;

import dev.strahl.color.DisplayEncoding;
import dev.strahl.image.Image;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import javax.imageio.ImageIO;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * Writes an 8-bit sRGB PNG: linear radiance clamped to [0, 1] and encoded with the sRGB transfer
 * function ({@link DisplayEncoding#toBufferedImage} at exposure 0), through the JDK's own PNG encoder.
 */
public final class PngWriter {

    private PngWriter() {
    }

    /** Writes {@code img} to {@code out}; does not close {@code out}. */
    public static void write(Image img, OutputStream out) throws IOException {
        write(DisplayEncoding.toBufferedImage(img, 0), out);
    }

    /** Writes an 8-bit image already tone-mapped and encoded to {@code out}; does not close {@code out}. */
    public static void write(BufferedImage bi, OutputStream out) throws IOException {
        // A memory cache rather than ImageIO's default file cache in java.io.tmpdir: the only file
        // a write creates is the caller's (ImageWriters' temporary file).
        try (ImageOutputStream ios = new MemoryCacheImageOutputStream(out)) {
            if (!ImageIO.write(bi, "png", ios)) {
                throw new IOException("this Java runtime has no PNG encoder");
            }
        }
    }
}
