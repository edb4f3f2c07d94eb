package dev.strahl.golden;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.io.SceneLoader;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import dev.strahl.testing.Golden;
import dev.strahl.testing.Renders;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Participating media against Mitsuba 3.9.1's {@code volpath} (128×128, 8192 spp,
 * docs/anchors/media_refs.py, which writes the scene files of src/test/resources/golden/media
 * from the same numbers): fog in a Cornell-like room behind a {@code null} box, a glass sphere
 * filled with an absorbing medium, the same sphere filled with a scattering one (subsurface
 * scattering inside a dielectric shell) and a {@code .vol} density grid in a {@code null} box under
 * a sky and a sun. Each scene is read through the scene file, as a user's would be.
 *
 * <p><b>Tolerance.</b> The image is cut into square blocks (32×32 pixels; 64×64 for the fog, whose
 * noise is the rare fog point next to the light, and the subsurface sphere, whose noise is light
 * found only through the glass); every block's colour, summed over r, g and b, must be within
 * {@code tolerance} of the reference's, relative to the reference's plus {@value #FLOOR} of the
 * mean block's (dark blocks are judged on the scale of the image). Each tolerance is about twice
 * the worst block of strahl's renders at the test's spp with seeds 1–3 (docs/media.md gives the
 * figures), and each scene has a mutant it must catch, rendered
 * at the same spp: the fog's g of the wrong sign, the glass's extinction ×1.1, the subsurface
 * medium's g of the wrong sign, and the grid shifted by half a voxel along every axis (the voxel
 * centres at i/X instead of (i + ½)/X).
 */
class MediaGoldenTest {
    static final double FLOOR = 0.05;
    static final Path DIR = Path.of("src/test/resources/golden/media");

    /** A golden scene: its spp, block size and tolerance, and its mutant as a text edit of its scene file. */
    record Case(String name, int spp, int block, double tolerance, String mutant, String from, String to) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<Arguments> cases() {
        return Stream.of(
                Arguments.of(new Case("fog", 16, 64, 0.05, "g of the wrong sign", "\"g\": 0.5", "\"g\": -0.5")),
                Arguments.of(new Case("tint", 64, 32, 0.02, "sigmaT x 1.1", "\"scale\": 2.4", "\"scale\": 2.64")),
                Arguments.of(new Case("subsurface", 32, 64, 0.012, "g of the wrong sign", "\"g\": 0.3", "\"g\": -0.3")),
                Arguments.of(new Case("smoke", 16, 32, 0.01, "the grid half a voxel off",
                        "\"bounds\": [[-0.6, 0.02, -0.4], [0.6, 1.02, 0.4]]", "\"bounds\": [[-0.65, -0.03, -0.45], [0.55, 0.97, 0.35]]")));
    }

    @TempDir
    Path dir;

    static Image render(Path sceneFile, int spp) throws Exception {
        Scene scene = SceneLoader.load(sceneFile);
        return Renders.render(scene, RenderSettings.defaults().withSize(128, 128).withSamplesPerPixel(spp).withSeed(1));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void matchesMitsubaAndItsMutantDoesNot(Case c) throws Exception {
        Image ref = Golden.reference("media/" + c.name() + "_128.pfm");
        Image img = render(DIR.resolve(c.name() + ".json"), c.spp());
        String failures = differences(img, ref, c.block(), c.tolerance());
        assertThat(failures).as("%s against Mitsuba 3 (worst block %.2f %%, relMSE %.3g)", c.name(), 100 * worst(img, ref, c.block()),
                img.relMse(ref)).isEmpty();

        String text = Files.readString(DIR.resolve(c.name() + ".json"));
        assertThat(text).contains(c.from());
        Files.copy(DIR.resolve("smoke.vol"), dir.resolve("smoke.vol"));
        Path mutant = Files.writeString(dir.resolve(c.name() + ".json"), text.replace(c.from(), c.to()));
        Image wrong = render(mutant, c.spp());
        assertThat(differences(wrong, ref, c.block(), c.tolerance())).as("%s with %s (worst block %.2f %%)", c.name(), c.mutant(),
                100 * worst(wrong, ref, c.block())).isNotEmpty();
    }

    /** The blocks' relative differences: Σ over r, g, b of |block sum − reference's| / (reference's Σ + the floor). */
    static double[] blockErrors(Image img, Image ref, int block) {
        int n = img.width() / block;
        double[][] a = new double[n * n][3], r = new double[n * n][3];
        for (int y = 0; y < img.height(); y++) {
            for (int x = 0; x < img.width(); x++) {
                int b = (y / block) * n + x / block;
                for (int c = 0; c < 3; c++) {
                    a[b][c] += img.get(x, y, c);
                    r[b][c] += ref.get(x, y, c);
                }
            }
        }
        double total = 0;
        for (double[] rb : r) {
            total += rb[0] + rb[1] + rb[2];
        }
        double floor = FLOOR * total / (n * n);
        double[] e = new double[n * n];
        for (int b = 0; b < e.length; b++) {
            double diff = Math.abs(a[b][0] - r[b][0]) + Math.abs(a[b][1] - r[b][1]) + Math.abs(a[b][2] - r[b][2]);
            e[b] = diff / (r[b][0] + r[b][1] + r[b][2] + floor);
        }
        return e;
    }

    static double worst(Image img, Image ref, int block) {
        return java.util.Arrays.stream(blockErrors(img, ref, block)).max().orElse(0);
    }

    /** One line per block off by more than the tolerance; empty if the image matches. */
    static String differences(Image img, Image ref, int block, double tolerance) {
        double[] e = blockErrors(img, ref, block);
        int n = img.width() / block;
        StringBuilder out = new StringBuilder();
        for (int b = 0; b < e.length; b++) {
            if (!(e[b] <= tolerance)) {
                out.append(String.format(Locale.ROOT, "%n  block (%d, %d): %.2f %%", b % n, b / n, 100 * e[b]));
            }
        }
        return out.toString();
    }
}
