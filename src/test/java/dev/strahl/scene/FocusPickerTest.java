package dev.strahl.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import dev.strahl.io.SceneLoader;
import java.nio.file.Path;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** Ctrl+click's focus: the distance, along the viewing direction, of the surface under the cursor. */
class FocusPickerTest {

    @Test
    void theCentreFocusesOnTheSphereInFrontAndTheBackgroundOnNothing() throws Exception {
        Scene scene = SceneLoader.load(Path.of("src/test/resources/golden/thinlens.json"));
        Camera c = scene.camera();
        double toCentre = c.lookFrom().distance(new Vector3d(0, 0, -0.5));
        // the centre ray runs along the viewing direction through the green sphere's centre (radius 0.5)
        assertThat(scene.focusDistance(c, 0.5, 0.5, 1)).isCloseTo(toCentre - 0.5, within(1e-9));
        assertThat(scene.focusDistance(c, 0.02, 0.02, 1)).isNaN();
    }

    @Test
    void anOffCentreHitCountsAlongTheViewingDirectionNotAlongTheRay() throws Exception {
        Scene scene = SceneLoader.load(Path.of("src/test/resources/golden/thinlens.json"));
        Camera c = scene.camera();
        // the near red sphere, left of the centre: its distance along the view is less than along the ray
        double d = scene.focusDistance(c, 0.12, 0.62, 1);
        assertThat(d).isBetween(2.5, 3.6);
    }

    /** A cut-away surface is not there for the camera, so Ctrl+click focuses on what is seen behind it. */
    @Test
    void aCutAwaySurfaceIsPassedThroughAsTheCameraDoes() {
        Material grey = Material.diffuse("grey", new Rgb(0.5, 0.5, 0.5));
        Camera c = new Camera(new Vector3d(0, 0, 5), new Vector3d(0, 0, 0), new Vector3d(0, 1, 0), 30);
        Scene solid = Scene.builder().camera(c).environment(new Rgb(1, 1, 1)).addSphere(new Vector3d(0, 0, 0), 1, grey).build();
        Scene cut = Scene.builder().camera(c).environment(new Rgb(1, 1, 1))
                .addSphere(new Vector3d(0, 0, 0), 1, grey)
                .addSphere(new Vector3d(0, 0, 2.5), 0.5, grey.withAlphaCutout(Texture.constant(0), 0.5)).build();
        Scene kept = Scene.builder().camera(c).environment(new Rgb(1, 1, 1))
                .addSphere(new Vector3d(0, 0, 0), 1, grey)
                .addSphere(new Vector3d(0, 0, 2.5), 0.5, grey.withAlphaCutout(Texture.constant(1), 0.5)).build();
        assertThat(solid.focusDistance(c, 0.5, 0.5, 1)).isCloseTo(4, within(1e-9));
        assertThat(cut.focusDistance(c, 0.5, 0.5, 1)).as("the cut-away sphere in front").isCloseTo(4, within(1e-9));
        assertThat(kept.focusDistance(c, 0.5, 0.5, 1)).as("the same sphere kept").isCloseTo(2, within(1e-9));
    }
}
