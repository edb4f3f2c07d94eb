package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A scene file's film and integrator keys are used by {@code strahl render}, and options given on the command line override them. */
class RenderSceneSettingsTest {
    @TempDir
    Path dir;

    private Path scene(String integrator) throws Exception {
        return scene("s.json", integrator);
    }

    private Path scene(String name, String integrator) throws Exception {
        if (!Files.exists(dir.resolve("cornell-box.obj"))) {
            Files.copy(Path.of("scenes", "cornell-box.obj"), dir.resolve("cornell-box.obj"));
            Files.copy(Path.of("scenes", "cornell-box.mtl"), dir.resolve("cornell-box.mtl"));
        }
        return Files.writeString(dir.resolve(name), """
                { "film": { "width": 24, "height": 10 },
                  "integrator": %s,
                  "shapes": [ { "type": "mesh", "file": "cornell-box.obj" } ] }
                """.formatted(integrator));
    }

    /** The PFM that {@code strahl render} writes for {@code file} with {@code options}. */
    private byte[] render(Path file, String name, String... options) throws Exception {
        Path out = dir.resolve(name + ".pfm");
        List<String> args = new ArrayList<>(List.of("render", file.toString(), "-o", out.toString(), "--threads", "2"));
        args.addAll(List.of(options));
        var run = RenderCommandTest.strahl(args.toArray(String[]::new));
        assertThat(run.code()).as(run.err()).isZero();
        return Files.readAllBytes(out);
    }

    @Test
    void thePhotonKeysOfTheFileAreUsedAndTheOptionsOverrideThem() throws Exception {
        Path keys = scene("keys.json", "{ \"type\": \"photon\", \"spp\": 1, \"photons\": 2000, \"photonRadius\": 0.1 }");
        Path plain = scene("plain.json", "{ \"type\": \"photon\", \"spp\": 1 }");
        byte[] fromFile = render(keys, "a");
        assertThat(fromFile).as("the file's keys are the options' values")
                .isEqualTo(render(plain, "b", "--photons", "2000", "--photon-radius", "0.1"));
        byte[] morePhotons = render(keys, "c", "--photons", "3000");
        assertThat(morePhotons).as("--photons wins, the file's radius stays")
                .isEqualTo(render(plain, "d", "--photons", "3000", "--photon-radius", "0.1")).isNotEqualTo(fromFile);
        byte[] widerRadius = render(keys, "e", "--photon-radius", "0.2");
        assertThat(widerRadius).as("--photon-radius wins, the file's photons stay")
                .isEqualTo(render(plain, "f", "--photons", "2000", "--photon-radius", "0.2")).isNotEqualTo(fromFile);
    }

    /** film.aovs writes the feature buffers beside the image, as --aov does; --aov on the command line replaces the file's list. */
    @Test
    void theFilesAovsAreWrittenAndTheOptionReplacesThem() throws Exception {
        scene("plain.json", "{ \"spp\": 1 }");
        Path file = Files.writeString(dir.resolve("aovs.json"), Files.readString(dir.resolve("plain.json"))
                .replace("\"height\": 10 }", "\"height\": 10, \"aovs\": [\"depth\", \"albedo\"] }"));
        render(file, "a");
        assertThat(dir.resolve("a.depth.pfm")).exists();
        assertThat(dir.resolve("a.albedo.pfm")).exists();
        assertThat(dir.resolve("a.normal.pfm")).doesNotExist();
        render(file, "b", "--aov", "normal");
        assertThat(dir.resolve("b.normal.pfm")).exists();
        assertThat(dir.resolve("b.depth.pfm")).as("the option wins over the file's list").doesNotExist();
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
    void anUnknownIntegratorInTheFileIsOneLineNamingTheFileAndLine() throws Exception {
        Path s = scene("{ \"type\": \"bidir\" }");
        var run = RenderCommandTest.strahl("render", s.toString(), "-o", dir.resolve("a.png").toString());
        assertThat(run.code()).isEqualTo(2);
        assertThat(run.err().strip()).isEqualTo("strahl: " + s + ":2: 'integrator.type': unknown integrator 'bidir' (known: path, direct, whitted, photon)");
    }
}
