package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.codec.PfmReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** {@code --integrator photon} with its options on the command line. */
class PhotonOptionsTest {
    @TempDir
    Path out;

    @Test
    void photonIntegratorRendersTheCornellBox() throws IOException {
        Path pfm = out.resolve("photon.pfm");
        RenderCommandTest.Run r = RenderCommandTest.render(RenderCommandTest.CORNELL, pfm,
                "--integrator", "photon", "--photons", "3000", "--photon-radius", "0.05", "--spp", "2");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.err()).contains("strahl: photon, 16x16, 2 spp");
        Image img = PfmReader.read(pfm);
        assertThat(img.mean()[0]).isGreaterThan(0.05);
    }

    @Test
    void photonOptionsChangeTheImage() throws IOException {
        Path a = out.resolve("a.pfm"), b = out.resolve("b.pfm"), c = out.resolve("c.pfm");
        RenderCommandTest.render(RenderCommandTest.CORNELL, a, "--integrator", "photon", "--photons", "2000", "--spp", "1");
        RenderCommandTest.render(RenderCommandTest.CORNELL, b, "--integrator", "photon", "--photons", "3000", "--spp", "1");
        RenderCommandTest.render(RenderCommandTest.CORNELL, c, "--integrator", "photon", "--photons", "2000", "--photon-radius", "0.1", "--spp", "1");
        assertThat(Files.readAllBytes(b)).isNotEqualTo(Files.readAllBytes(a));
        assertThat(Files.readAllBytes(c)).isNotEqualTo(Files.readAllBytes(a));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "--photons|0|photons per iteration must lie in 1 ..",
        "--photons|-5|photons per iteration must lie in 1 ..",
        "--photons|many|'many'",
        "--photon-radius|-0.1|photon radius must be a finite number >= 0",
        "--photon-radius|NaN|photon radius must be a finite number >= 0",
        "--photon-radius|Infinity|photon radius must be a finite number >= 0"})
    void badPhotonOptionIsOneLine(String option, String value, String fragment) {
        RenderCommandTest.Run r = RenderCommandTest.render(RenderCommandTest.CORNELL, out.resolve("x.png"),
                "--integrator", "photon", option, value);
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.err()).contains(fragment);
        assertThat(r.errLines()).hasSize(1);
        assertThat(r.err()).startsWith("strahl: ").doesNotContain("Exception");
        assertThat(out.resolve("x.png")).doesNotExist();
    }

    @Test
    void helpListsThePhotonOptions() {
        RenderCommandTest.Run r = RenderCommandTest.strahl("render", "--help");
        assertThat(r.out()).contains("path|direct|whitted|photon").contains("--photons").contains("--photon-radius");
        RenderCommandTest.Run v = RenderCommandTest.strahl("view", "--help");
        assertThat(v.out()).contains("--photons").contains("--photon-radius");
    }
}
