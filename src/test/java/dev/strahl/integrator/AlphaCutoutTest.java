package dev.strahl.integrator;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.Texture;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.testing.Renders;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.joml.Vector3d;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.api.Test;

/**
 * Alpha cut-outs: where alpha &lt; cutoff a surface is absent for camera rays, bounce rays and
 * shadow rays alike, and an emitter emits nothing there. A checker alpha (half its area cut
 * away, by symmetry) lets half the light through.
 */
class AlphaCutoutTest {
    @TempDir
    static Path dir;
    private static Texture checker;

    @BeforeEach
    void writeChecker() throws Exception {
        if (checker == null) {
            BufferedImage img = new BufferedImage(2, 2, BufferedImage.TYPE_INT_ARGB);
            img.setRGB(0, 0, 0xffffffff);
            img.setRGB(1, 1, 0xffffffff);
            img.setRGB(1, 0, 0x00ffffff);
            img.setRGB(0, 1, 0x00ffffff);
            Path f = dir.resolve("checker.png");
            ImageIO.write(img, "png", f.toFile());
            checker = Texture.image(f).alpha().withUvScale(8, 8);
        }
    }

    /** A square of half-size h at height z with uvs over [0, 1]², facing up or down. */
    static TriangleMesh square(double h, double z, boolean up) {
        float a = (float) h, zz = (float) z;
        float[] p = {-a, -a, zz, a, -a, zz, a, a, zz, -a, a, zz};
        int[] i = up ? new int[] {0, 1, 2, 0, 2, 3} : new int[] {0, 2, 1, 0, 3, 2};
        return new TriangleMesh(p, i, null, new float[] {0, 0, 1, 0, 1, 1, 0, 1});
    }

    static final Material FLOOR = Material.diffuse("floor", Rgb.gray(0.5));
    static final Material BLACK = Material.diffuse("black", Rgb.BLACK);
    static final Rgb LE = Rgb.gray(4);

    /** Floor at z = 0, an optional black screen at z = 1, a lamp at z = 2 facing down; seen from under the screen. */
    static Scene shadowScene(Material screen, Material lamp) {
        Scene.Builder b = Scene.builder().addMesh(square(3, 0, true), FLOOR).addMesh(square(0.6, 2, false), lamp);
        if (screen != null) {
            b.addMesh(square(2, 1, true), screen);
        }
        return b.camera(new Camera(new Vector3d(0, -2.5, 0.6), new Vector3d(0, 0, 0), new Vector3d(0, 0, 1), 55)).build();
    }

    static double meanLuminance(Image img) {
        double[] m = img.mean();
        return (m[0] + m[1] + m[2]) / 3;
    }

    static RenderSettings settings(IntegratorKind kind, int spp) {
        return RenderSettings.defaults().withSize(32, 32).withSamplesPerPixel(spp).withSeed(11).withIntegrator(kind).withMaxDepth(2);
    }

    @ParameterizedTest(name = "{0}")
    @EnumSource(value = IntegratorKind.class, names = {"PATH", "WHITTED"})
    void aCheckerCutoutScreenLetsHalfTheLightThrough(IntegratorKind kind) {
        Material lamp = Material.emissive("lamp", Rgb.BLACK, LE);
        double open = meanLuminance(Renders.render(shadowScene(null, lamp), settings(kind, 64)));
        double closed = meanLuminance(Renders.render(shadowScene(BLACK, lamp), settings(kind, 16)));
        double half = meanLuminance(Renders.render(shadowScene(BLACK.withAlphaCutout(checker, 0.5), lamp), settings(kind, 64)));
        assertThat(closed).as("an opaque screen casts a full shadow").isLessThan(0.01 * open);
        assertThat(half / open).as("light through a checker screen (%s)", kind).isCloseTo(0.5, within(0.04));
    }

    @Test
    void aCutoutEmitterEmitsFromHalfItsArea() {
        Material lamp = Material.emissive("lamp", Rgb.BLACK, LE);
        double full = meanLuminance(Renders.render(shadowScene(null, lamp), settings(IntegratorKind.PATH, 64)));
        double half = meanLuminance(Renders.render(shadowScene(null, lamp.withAlphaCutout(checker, 0.5)), settings(IntegratorKind.PATH, 64)));
        assertThat(half / full).isCloseTo(0.5, within(0.04));
        // Light sampling alone sees the same (a sample in the cut-out carries no radiance).
        double whitted = meanLuminance(Renders.render(shadowScene(null, lamp.withAlphaCutout(checker, 0.5)),
                settings(IntegratorKind.WHITTED, 64)));
        double whittedFull = meanLuminance(Renders.render(shadowScene(null, lamp), settings(IntegratorKind.WHITTED, 64)));
        assertThat(whitted / whittedFull).isCloseTo(0.5, within(0.04));
    }

    @Test
    void cameraRaysPassTheCutoutUnchanged() {
        // Looking up through the screen at the lamp: Le where the screen is cut away, black elsewhere.
        Material lamp = Material.emissive("lamp", Rgb.BLACK, LE);
        Camera up = new Camera(new Vector3d(0, 0, 0.2), new Vector3d(0, 0, 2), new Vector3d(0, 1, 0), 20);
        RenderSettings s = RenderSettings.defaults().withSize(32, 32).withSamplesPerPixel(16).withSeed(3).withMaxDepth(1);
        Image open = Renders.render(shadowScene(null, lamp).withCamera(up), s);
        Image half = Renders.render(shadowScene(BLACK.withAlphaCutout(checker, 0.5), lamp).withCamera(up), s);
        assertThat(meanLuminance(open)).isCloseTo(4, within(1e-9));
        assertThat(meanLuminance(half) / meanLuminance(open)).isCloseTo(0.5, within(0.04));
        float max = 0;
        for (float v : half.rgb()) {
            max = Math.max(max, v);
        }
        assertThat((double) max).as("a pixel seen wholly through a hole: Le, no throughput lost").isCloseTo(4, within(1e-6));
    }
}
