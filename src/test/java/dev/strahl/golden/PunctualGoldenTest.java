package dev.strahl.golden;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.io.SceneLoader;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.testing.Golden;
import dev.strahl.testing.Renders;
import java.nio.file.Path;
import java.util.Locale;
import org.joml.Vector3d;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Point, spot and directional lights against a Mitsuba 3.9.1 reference (128×128, 4096 spp,
 * docs/anchors/punctual_refs.py; the scene is src/test/resources/golden/punctual.json): a grey
 * floor and a diffuse ball under a point light, a hard-edged spot (glTF inner = outer cone, which
 * Mitsuba's {@code spot} with beam width = cutoff angle also is: their smooth falloffs differ) and
 * a directional light, with interreflections (unbounded depth).
 *
 * <p>Tolerance: each 16×16 block's mean colour within {@value #BLOCK_TOLERANCE} of its
 * luminance (summed over r, g, b) plus {@value #FLOOR} of the image's mean block luminance (the
 * shadows and the black background are lit by interreflection only), and relMSE below
 * {@value #MAX_REL_MSE}. Measured at {@value #SPP} spp, seed 1: worst block 0.8 %, relMSE 7.5e-4
 * (the noise of the spot's hard edge, a ring in the difference image); image means within 0.1 %.
 * The mutation tests show that a point light 5 % too bright, a spot 2° too wide and a directional
 * light coming from a mirrored side all fail.
 */
class PunctualGoldenTest {
    static final int SPP = 256;
    static final int BLOCK = 16;
    static final double BLOCK_TOLERANCE = 0.02;
    static final double FLOOR = 0.05;
    static final double MAX_REL_MSE = 2e-3;
    static final String REFERENCE = "punctual_128.pfm";

    static final Camera CAMERA = new Camera(new Vector3d(0, 1.5, 4.5), new Vector3d(0, 0.3, 0), new Vector3d(0, 1, 0), 40);

    static Scene fromFile;
    static Image render;

    @BeforeAll
    static void renderScene() throws Exception {
        fromFile = SceneLoader.load(Path.of("src/test/resources/golden/punctual.json"));
        render = render(fromFile, SPP);
    }

    static Image render(Scene scene, int spp) {
        return Renders.render(scene, RenderSettings.defaults().withSize(128, 128).withSamplesPerPixel(spp).withSeed(1));
    }

    @Test
    void pointSpotAndDirectionalLightsMatchMitsuba() {
        Image ref = Golden.reference(REFERENCE);
        String failures = differences(render, ref);
        assertThat(failures).as("against Mitsuba 3 (relMSE %.3g)", render.relMse(ref)).isEmpty();
    }

    /** The scene of punctual.json built in code, with the three lights as given. */
    private static Scene scene(double pointScale, double spotDegrees, Vector3d sunTravel) {
        TriangleMesh floor = new TriangleMesh(new float[] {-2, 0, -2, -2, 0, 2, 2, 0, 2, 2, 0, -2}, new int[] {0, 1, 2, 0, 2, 3}, null);
        return Scene.builder()
                .addMesh(floor, Material.diffuse("floor", Rgb.gray(0.6)))
                .addSphere(new Vector3d(0, 0.5, 0), 0.5, Material.diffuse("ball", new Rgb(0.7, 0.3, 0.2)))
                .pointLight(new Vector3d(1, 1.5, 1), new Rgb(4 * pointScale, 4 * pointScale, 3 * pointScale))
                .spotLight(new Vector3d(-1.2, 1.6, 0.6), new Vector3d(0.5, -1.6, -0.3), new Rgb(6, 3, 1), Math.toRadians(spotDegrees),
                        Math.toRadians(spotDegrees))
                .directionalLight(sunTravel, new Rgb(0.5, 0.6, 0.8))
                .camera(CAMERA)
                .build();
    }

    @Test
    void theSceneBuiltInCodeIsTheSceneFilesBitForBit() {
        Image inCode = render(scene(1, 25, new Vector3d(-0.5, -1, -0.3)), 4);
        assertThat(inCode.rgb()).isEqualTo(render(fromFile, 4).rgb());
    }

    @Test
    void aPointLightFivePercentTooBrightFails() {
        assertThat(differences(render(scene(1.05, 25, new Vector3d(-0.5, -1, -0.3)), SPP), Golden.reference(REFERENCE))).isNotEmpty();
    }

    @Test
    void aSpotTwoDegreesTooWideFails() {
        assertThat(differences(render(scene(1, 27, new Vector3d(-0.5, -1, -0.3)), SPP), Golden.reference(REFERENCE))).isNotEmpty();
    }

    @Test
    void aDirectionalLightFromTheMirroredSideFails() {
        assertThat(differences(render(scene(1, 25, new Vector3d(0.5, -1, -0.3)), SPP), Golden.reference(REFERENCE))).isNotEmpty();
    }

    /** One line per block off by more than the tolerance, and for the relMSE; empty if the image matches. */
    static String differences(Image img, Image ref) {
        int n = img.width() / BLOCK;
        double[][] diff = new double[n][n], sum = new double[n][n];
        double total = 0;
        for (int by = 0; by < n; by++) {
            for (int bx = 0; bx < n; bx++) {
                for (int c = 0; c < 3; c++) {
                    double a = 0, b = 0;
                    for (int y = by * BLOCK; y < (by + 1) * BLOCK; y++) {
                        for (int x = bx * BLOCK; x < (bx + 1) * BLOCK; x++) {
                            a += img.get(x, y, c);
                            b += ref.get(x, y, c);
                        }
                    }
                    diff[by][bx] += Math.abs(a - b);
                    sum[by][bx] += b;
                }
                total += sum[by][bx];
            }
        }
        double floor = FLOOR * total / (n * n);
        StringBuilder out = new StringBuilder();
        for (int by = 0; by < n; by++) {
            for (int bx = 0; bx < n; bx++) {
                double e = diff[by][bx] / (sum[by][bx] + floor);
                if (!(e <= BLOCK_TOLERANCE)) {
                    out.append(String.format(Locale.ROOT, "%n  block (%d, %d): %.2f %%", bx, by, 100 * e));
                }
            }
        }
        double relMse = img.relMse(ref);
        if (!(relMse <= MAX_REL_MSE)) {
            out.append(String.format(Locale.ROOT, "%n  relMSE %.3g", relMse));
        }
        return out.toString();
    }
}
