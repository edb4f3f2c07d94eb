package dev.strahl.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.io.SceneLoader;
import dev.strahl.io.obj.MtlMaterial;
import dev.strahl.io.obj.ObjModel;
import dev.strahl.io.obj.ObjReader;
import dev.strahl.image.Image;
import dev.strahl.render.RenderSettings;
import dev.strahl.testing.Renders;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3d;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Self-intersection: the Cornell Box scaled by 10³ and moved by 10⁴ on every axis renders the
 * image of the original (radiance does not depend on the scale). Ray origins are offset by an
 * amount that grows with the coordinates; one that did not would let rays re-hit the surface they
 * leave (shadow acne, darker walls) or, too large, leak light through the box's corners.
 * Checked: with the offset set to zero both comparisons fail (regions 15 % darker).
 */
class FarFromOriginTest {
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withSize(64, 64).withSamplesPerPixel(64).withSeed(3);
    private static final int REGION = 8;
    private static Image original;

    @BeforeAll
    static void renderTheOriginal() throws Exception {
        original = Renders.render(cornell(1, 0), SETTINGS);
    }

    /** The shipped Cornell Box with every position p replaced by scale·p + offset (on all axes), and its camera likewise. */
    static Scene cornell(double scale, double offset) throws SceneException {
        ObjModel model = ObjReader.read(Path.of("scenes", "cornell-box.obj"));
        float[] p = model.mesh().positions();
        for (int i = 0; i < p.length; i++) {
            p[i] = (float) (scale * p[i] + offset);
        }
        TriangleMesh moved = new TriangleMesh(p, model.mesh().indices(), model.mesh().normals());
        Scene.Builder b = Scene.builder();
        List<Material> palette = new ArrayList<>();
        for (MtlMaterial m : model.materials()) {
            palette.add(m.toMaterial(b::note));
        }
        b.addMesh(moved, model.triangleMaterial(), palette);
        Vector3d shift = new Vector3d(offset, offset, offset);
        b.camera(new Camera(new Vector3d(0, 1, 3.9).mul(scale).add(shift), new Vector3d(0, 1, 0).mul(scale).add(shift),
                new Vector3d(0, 1, 0), 40));
        return b.build();
    }

    @Test
    void scaledByAThousandAndMovedByTenThousandRendersTheSameImage() throws Exception {
        Image far = Renders.render(cornell(1e3, 1e4), SETTINGS);
        assertSameImage(far, original);
    }

    @Test
    void movedByAHundredThousandRendersTheSameImageToo() throws Exception {
        Image far = Renders.render(cornell(1e3, 1e5), SETTINGS);
        assertSameImage(far, original);
    }

    @Test
    void theComparisonNoticesAFivePercentDarkerRegion() {
        float[] rgb = original.rgb();
        for (int y = 24; y < 32; y++) {
            for (int x = 40; x < 48; x++) {
                for (int c = 0; c < 3; c++) {
                    rgb[3 * (y * 64 + x) + c] *= 0.95f;       // a region of the back wall
                }
            }
        }
        Image darker = new Image(64, 64, rgb);
        assertThatThrownBy(() -> assertSameImage(darker, original)).isInstanceOf(AssertionError.class)
                .hasMessageContaining("region (5, 3)");
    }

    /**
     * Per 8×8 region, the mean luminance of both images agrees within 4 standard errors of the
     * difference (estimated from the spread of the per-pixel differences), or 1 % where the
     * images agree so well that this is smaller.
     */
    static void assertSameImage(Image actual, Image expected) {
        assertThat(actual.width()).isEqualTo(expected.width());
        for (int ry = 0; ry < expected.height() / REGION; ry++) {
            for (int rx = 0; rx < expected.width() / REGION; rx++) {
                double sumA = 0, sumE = 0, sumD = 0, sumD2 = 0;
                int n = REGION * REGION;
                for (int y = ry * REGION; y < (ry + 1) * REGION; y++) {
                    for (int x = rx * REGION; x < (rx + 1) * REGION; x++) {
                        double a = luminance(actual, x, y), e = luminance(expected, x, y);
                        sumA += a;
                        sumE += e;
                        sumD += a - e;
                        sumD2 += (a - e) * (a - e);
                    }
                }
                double meanD = sumD / n;
                double se = Math.sqrt(Math.max(0, sumD2 / n - meanD * meanD) / (n - 1));
                double tolerance = Math.max(4 * se, 0.01 * sumE / n);
                assertThat(Math.abs(meanD)).as("region (%d, %d): mean %.4f vs %.4f", rx, ry, sumA / n, sumE / n)
                        .isLessThanOrEqualTo(tolerance);
            }
        }
    }

    private static double luminance(Image img, int x, int y) {
        return 0.2126 * img.get(x, y, 0) + 0.7152 * img.get(x, y, 1) + 0.0722 * img.get(x, y, 2);
    }

}
