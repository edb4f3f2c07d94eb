package dev.strahl.cli;

import dev.strahl.image.ToneMapping;
import dev.strahl.io.ImageWriters;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/** How {@code render} writes its files, besides the image's name ({@code -o}): the "Output files" section. */
final class OutputFileOptions {

    @Option(names = "--exr-type", defaultValue = "half", paramLabel = "half|float",
            description = "Sample type of .exr output (default: ${DEFAULT-VALUE}); depth is always float.")
    String exrType;

    @Option(names = "--exr-compression", defaultValue = "zip", paramLabel = "zip|none",
            description = "Compression of .exr output (default: ${DEFAULT-VALUE}).")
    String exrCompression;

    @Option(names = "--tonemap", defaultValue = "clamp", paramLabel = "clamp|aces|agx",
            description = "Tone curve of .png output (default: ${DEFAULT-VALUE}: values above 1 are white).")
    String tonemap;

    @Option(names = "--exposure", defaultValue = "0", paramLabel = "EV",
            description = "Exposure of .png output in stops: values are multiplied by 2^EV before the tone curve (default: ${DEFAULT-VALUE}).")
    double exposure;

    @Option(names = "--stats", paramLabel = "FILE.json",
            description = "Also write the render's figures (time, samples/s, rays/s, load and BVH build time, the settings) as JSON.")
    Path statsFile;

    /** The PNG's tone curve and exposure, the EXR's type and compression, from the options (checked). */
    ImageWriters writer() {
        ToneMapping curve;
        try {
            curve = ToneMapping.of(tonemap);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--tonemap: " + e.getMessage());
        }
        if (!Double.isFinite(exposure)) {
            throw new IllegalArgumentException("--exposure must be a finite number of stops, got " + exposure);
        }
        if (!exrType.equals("half") && !exrType.equals("float")) {
            throw new IllegalArgumentException("--exr-type must be half or float, got '" + exrType + "'");
        }
        if (!exrCompression.equals("zip") && !exrCompression.equals("none")) {
            throw new IllegalArgumentException("--exr-compression must be zip or none, got '" + exrCompression + "'");
        }
        return ImageWriters.defaults().withToneMapping(curve).withExposure(exposure).withExrFloat(exrType.equals("float"))
                .withExrZip(exrCompression.equals("zip"));
    }

    /** Refuses an image file that cannot be written before time is spent on the render. */
    static void checkImage(Path file, String what) {
        if (!ImageWriters.isSupported(file)) {
            throw new IllegalArgumentException("unknown image format of " + file + ": use .png, .pfm or .exr");
        }
        checkWritable(file, what);
    }

    /** The directory must exist and take a new file: tried for real, since permissions alone do not tell (root, read-only mounts). */
    static void checkWritable(Path file, String what) {
        Path dir = file.toAbsolutePath().getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new IllegalArgumentException(what + " directory does not exist: " + dir);
        }
        if (Files.isDirectory(file)) {
            throw new IllegalArgumentException(what + " " + file + " is a directory");
        }
        try {
            Files.delete(Files.createTempFile(dir, ".strahl-write-test", ".tmp"));
        } catch (IOException | SecurityException e) {
            throw new IllegalArgumentException(what + " directory is not writable: " + dir);
        }
    }
}
