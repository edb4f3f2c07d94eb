package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.codec.PfmReader;
import dev.strahl.image.Image;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** render --noise-threshold: the option, the scene file's key, the figures, the spp buffer and bad values. */
class NoiseThresholdCommandTest {
    private static final String SPHERE = Path.of("scenes", "cornell-sphere.json").toString();

    @TempDir
    Path dir;

    @Test
    void aLooseThresholdEndsTheRenderAndSaysWhereTheSamplesWent() throws Exception {
        Path png = dir.resolve("a.png");
        Path stats = dir.resolve("a.json");
        RenderCommandTest.Run r = RenderCommandTest.strahl("render", SPHERE, "-o", png.toString(), "--width", "32", "--height", "24",
                "--spp", "100000", "--noise-threshold", "0.5", "--aov", "spp", "--stats", stats.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.err()).contains("strahl: noise threshold 0.5: 100 % of the pixels converged, which ended the render; 32 to ")
                .contains("path, 32x24, up to ");
        String json = Files.readString(stats);
        assertThat(number(json, "converged_fraction")).isEqualTo(1);
        assertThat(number(json, "spp_min")).isEqualTo(32);
        assertThat(number(json, "spp_max")).isGreaterThan(32).isLessThan(100_000);
        assertThat(number(json, "spp_mean")).isBetween(32.0, number(json, "spp_max"));
        assertThat(number(json, "noiseThreshold")).isEqualTo(0.5);
        Image spp = PfmReader.read(dir.resolve("a.spp.pfm"));
        double sum = 0;
        for (int i = 0; i < spp.rgb().length; i += 3) {
            sum += spp.rgb()[i];
        }
        assertThat(sum / (32 * 24)).isEqualTo(number(json, "spp_mean"));
    }

    /** The number of a key in a stats file (each key once there). */
    private static double number(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\" : ([-0-9.eE]+)").matcher(json);
        assertThat(m.find()).as(key).isTrue();
        return Double.parseDouble(m.group(1));
    }

    @Test
    void theSceneFileKeyAppliesAndTheOptionWins() throws Exception {
        String scene = Files.readString(Path.of(SPHERE)).replaceFirst("\\{", "{ \"integrator\": { \"noiseThreshold\": 0.5, \"spp\": 100000 },")
                .replace("cornell-sphere.obj", Path.of("scenes", "cornell-sphere.obj").toAbsolutePath().toString().replace("\\", "/"));
        Path file = Files.writeString(dir.resolve("s.json"), scene);
        RenderCommandTest.Run r = RenderCommandTest.strahl("render", file.toString(), "-o", dir.resolve("s.png").toString(),
                "--width", "32", "--height", "24");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.err()).contains("noise threshold 0.5: 100 % of the pixels converged, which ended the render");
        RenderCommandTest.Run off = RenderCommandTest.strahl("render", file.toString(), "-o", dir.resolve("t.png").toString(),
                "--width", "8", "--height", "6", "--spp", "3", "--noise-threshold", "0");
        assertThat(off.code()).as(off.err()).isZero();
        assertThat(off.err()).doesNotContain("noise threshold").contains("3 spp");
    }

    @Test
    void aBadThresholdIsOneLineAndExitTwo() throws Exception {
        for (String bad : new String[] {"-0.1", "2", "NaN", "lots"}) {
            Path png = dir.resolve("b.png");
            RenderCommandTest.Run r = RenderCommandTest.strahl("render", SPHERE, "-o", png.toString(), "--width", "8", "--height", "8",
                    "--noise-threshold", bad);
            assertThat(r.code()).as(bad).isEqualTo(2);
            assertThat(r.errLines()).as(bad).singleElement().asString().startsWith("strahl: ").contains("--noise-threshold");
            assertThat(png).doesNotExist();
        }
    }
}
