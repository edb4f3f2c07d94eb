package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Scene;
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
        assertThat(FocusPicker.focusDistance(scene, c, 0.5, 0.5, 1)).isCloseTo(toCentre - 0.5, within(1e-9));
        assertThat(FocusPicker.focusDistance(scene, c, 0.02, 0.02, 1)).isNaN();
    }

    @Test
    void anOffCentreHitCountsAlongTheViewingDirectionNotAlongTheRay() throws Exception {
        Scene scene = SceneLoader.load(Path.of("src/test/resources/golden/thinlens.json"));
        Camera c = scene.camera();
        // the near red sphere, left of the centre: its distance along the view is less than along the ray
        double d = FocusPicker.focusDistance(scene, c, 0.12, 0.62, 1);
        assertThat(d).isBetween(2.5, 3.6);
    }
}
