package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A scene file's film and integrator keys are used by {@code strahl render}, and options given on the command line override them. */
class RenderSceneSettingsTest {
    @TempDir
    Path dir;

    private Path scene(String integrator) throws Exception {
        Files.copy(Path.of("scenes", "cornell-box.obj"), dir.resolve("cornell-box.obj"));
        Files.copy(Path.of("scenes", "cornell-box.mtl"), dir.resolve("cornell-box.mtl"));
        return Files.writeString(dir.resolve("s.json"), """
                { "film": { "width": 24, "height": 10 },
                  "integrator": %s,
                  "shapes": [ { "type": "mesh", "file": "cornell-box.obj" } ] }
                """.formatted(integrator));
    }

    @Test
    void theFilesSettingsAreUsedAndOptionsOverrideThem() throws Exception {
        Path s = scene("{ \"type\": \"direct\", \"spp\": 2, \"seed\": 5 }");
        var run = RenderCommandTest.strahl("render", s.toString(), "-o", dir.resolve("a.png").toString());
        assertThat(run.code()).as(run.err()).isZero();
        assertThat(run.err()).contains("direct, 24x10, 2 spp");
        BufferedImage a = ImageIO.read(dir.resolve("a.png").toFile());
        assertThat(a.getWidth()).isEqualTo(24);
        assertThat(a.getHeight()).isEqualTo(10);

        run = RenderCommandTest.strahl("render", s.toString(), "-o", dir.resolve("b.png").toString(), "--height", "6", "--spp", "1",
                "--integrator", "path");
        assertThat(run.code()).as(run.err()).isZero();
        assertThat(run.err()).contains("path, 24x6, 1 spp");
    }

    @Test
    void anUnknownIntegratorInTheFileIsOneLineNamingTheFile() throws Exception {
        Path s = scene("{ \"type\": \"bidir\" }");
        var run = RenderCommandTest.strahl("render", s.toString(), "-o", dir.resolve("a.png").toString());
        assertThat(run.code()).isEqualTo(2);
        assertThat(run.err().strip()).isEqualTo("strahl: " + s + ": unknown integrator 'bidir' (known: path, direct, whitted)");
    }
}
