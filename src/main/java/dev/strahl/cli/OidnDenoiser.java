package dev.strahl.cli;

import dev.strahl.image.Image;
import dev.strahl.codec.PfmReader;
import dev.strahl.codec.PfmWriter;
import dev.strahl.render.RenderBuffers;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * {@code --denoiser oidn}: Intel Open Image Denoise's command-line tool {@code oidnDenoise}
 * (shipped by the {@code pyoidn} package, among others), found on the PATH, run on the render's
 * image, albedo and normal written as PFM files to a temporary directory:
 * {@code oidnDenoise -d cpu --hdr c.pfm --alb a.pfm --nrm n.pfm -o out.pfm}. Not a dependency:
 * strahl's own denoiser is the default and needs nothing installed.
 */
final class OidnDenoiser {
    static final String TOOL = "oidnDenoise";
    private final Path executable;

    private OidnDenoiser(Path executable) {
        this.executable = executable;
    }

    /**
     * The tool on the PATH.
     *
     * @return the denoiser
     * @throws IllegalArgumentException if there is none (a usage error: nothing is rendered)
     */
    static OidnDenoiser onPath() {
        String path = System.getenv("PATH");
        if (path != null) {
            for (String dir : path.split(java.io.File.pathSeparator)) {
                if (dir.isEmpty()) {
                    continue;
                }
                Path candidate = Path.of(dir, TOOL);
                if (Files.isRegularFile(candidate) && Files.isExecutable(candidate)) {
                    return new OidnDenoiser(candidate);
                }
            }
        }
        throw new IllegalArgumentException("--denoiser oidn: " + TOOL + " was not found on the PATH (pip install pyoidn provides it)");
    }

    /** Denoises the image with its albedo and normal (when kept); its messages become the exception's. */
    Image denoise(RenderBuffers buffers) throws IOException {
        Path dir = Files.createTempDirectory("strahl-oidn");
        try {
            List<String> cmd = new ArrayList<>(List.of(executable.toString(), "-d", "cpu", "--hdr", pfm(dir, "color", buffers.color())));
            if (buffers.albedo() != null) {
                cmd.addAll(List.of("--alb", pfm(dir, "albedo", buffers.albedo())));
                if (buffers.normal() != null) {                 // OIDN takes normals only with an albedo
                    cmd.addAll(List.of("--nrm", pfm(dir, "normal", buffers.normal())));
                }
            }
            Path out = dir.resolve("out.pfm");
            cmd.addAll(List.of("-o", out.toString()));
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            String log = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            int code;
            try {
                code = p.waitFor();
            } catch (InterruptedException e) {
                p.destroy();
                Thread.currentThread().interrupt();
                throw new IOException("interrupted");
            }
            if (code != 0 || !Files.isRegularFile(out)) {
                throw new IOException("exit code " + code + ": " + log.strip());
            }
            return PfmReader.read(out);
        } finally {
            try (Stream<Path> files = Files.walk(dir)) {
                for (Path f : files.sorted(Comparator.reverseOrder()).toList()) {
                    Files.deleteIfExists(f);
                }
            }
        }
    }

    private static String pfm(Path dir, String name, Image image) throws IOException {
        Path file = dir.resolve(name + ".pfm");
        try (OutputStream os = Files.newOutputStream(file)) {
            PfmWriter.write(image, os);
        }
        return file.toString();
    }
}
