package dev.strahl.io.json;

import dev.strahl.image.Image;
import dev.strahl.codec.exr.ExrReader;
import dev.strahl.codec.HdrReader;
import dev.strahl.codec.ImageFormatException;
import dev.strahl.codec.ImageLimits;
import dev.strahl.codec.PfmReader;
import dev.strahl.scene.SceneException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads a linear image for an environment map: Radiance {@code .hdr}/{@code .pic}, OpenEXR
 * {@code .exr} (its R, G, B or Y channels) or {@code .pfm}. Every failure is a {@link
 * SceneException} whose message is one line that starts with the image file (what the image
 * readers say: truncated, corrupt, an EXR compression strahl does not read, too large for the heap).
 */
public final class EnvironmentMaps {
    /**
     * Bytes per texel that an environment needs besides the decoded image: the API image's copy
     * in and out (2 × 12), the scaled texels (12) and the sampling distribution's weights (2 × 4)
     * and cumulative sums (8).
     */
    static final int BYTES_PER_TEXEL = 52;

    private EnvironmentMaps() {
    }

    /** Whether strahl reads environment maps of this file's extension. */
    public static boolean isSupported(String name) {
        String n = name.toLowerCase(Locale.ROOT);
        return n.endsWith(".hdr") || n.endsWith(".pic") || n.endsWith(".exr") || n.endsWith(".pfm");
    }

    /**
     * Reads the image.
     *
     * @param file an .hdr, .pic, .exr or .pfm file
     * @return its colour, linear
     * @throws SceneException one line naming the file
     */
    public static Image read(Path file) throws SceneException {
        String name = file.getFileName() == null ? file.toString() : file.getFileName().toString();
        if (!isSupported(name)) {
            throw new SceneException(file, "not an environment map format strahl reads (expected .hdr, .pic, .exr or .pfm)");
        }
        try {
            if (Files.isDirectory(file)) {
                throw new SceneException(file, "is a directory, not an environment map");
            }
            String n = name.toLowerCase(Locale.ROOT);
            Image image;
            if (n.endsWith(".exr")) {
                image = ExrReader.readRgb(file).toImage();
            } else if (n.endsWith(".pfm")) {
                image = PfmReader.read(file);
            } else {
                image = HdrReader.read(file).toImage();
            }
            if (image.height() < 2) {
                throw new SceneException(file, "an environment map needs at least 2 rows, this one has " + image.height());
            }
            String shortfall = ImageLimits.heapShortfall((long) BYTES_PER_TEXEL * image.width() * image.height());
            if (shortfall != null) {
                throw new SceneException(file, "a " + image.width() + "x" + image.height() + " environment map (" + BYTES_PER_TEXEL
                        + " bytes a texel: its texels and sampling tables) " + shortfall);
            }
            return image;
        } catch (ImageFormatException e) {
            throw asSceneException(file, e);
        } catch (NoSuchFileException e) {
            throw new SceneException(file, "environment map not found");
        } catch (IOException e) {
            throw new SceneException(file, "cannot read the environment map: " + e.getMessage(), e);
        } catch (OutOfMemoryError e) {
            throw new SceneException(file, "the environment map does not fit in the Java heap (at most "
                    + ImageLimits.bytes(Runtime.getRuntime().maxMemory()) + "): give Java more memory (java -Xmx...)");
        }
    }

    /** The readers' messages start with the file (and a header line, "file:line: "); a SceneException adds them again. */
    private static SceneException asSceneException(Path file, ImageFormatException e) {
        String message = String.valueOf(e.getMessage());
        Matcher m = Pattern.compile(Pattern.quote(file.toString()) + ":(\\d+): (.*)", Pattern.DOTALL).matcher(message);
        if (m.matches()) {
            return new SceneException(file, Integer.parseInt(m.group(1)), m.group(2));
        }
        String prefix = file + ": ";
        return new SceneException(file, message.startsWith(prefix) ? message.substring(prefix.length()) : message, e);
    }
}
