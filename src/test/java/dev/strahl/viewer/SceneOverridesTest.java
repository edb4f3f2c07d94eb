package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.render.PhotonParameters;
import dev.strahl.image.Image;
import dev.strahl.io.ImageWriters;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Camera;
import dev.strahl.scene.SceneException;
import dev.strahl.testing.Renders;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code strahl view --envmap --aperture --focus-distance}: applied to every scene the viewer opens. */
class SceneOverridesTest {
    @TempDir
    Path dir;

    static ViewerOptions with(SceneOverrides overrides) {
        return new ViewerOptions(null, RenderSettings.defaults().withSize(16, 16).withThreads(1).withPhotons(new PhotonParameters(5000, 0)).withShadows(true),
                4, Theme.LIGHT, Set.of(), overrides);
    }

    private Path scene() throws Exception {
        return Files.writeString(dir.resolve("s.json"), """
                { "camera": { "lookFrom": [0, 0, 5], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fov": 20, "aperture": 0.05, "focusDistance": 6 },
                  "materials": { "m": { "type": "diffuse" } },
                  "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 0.1, "material": "m" } ],
                  "environment": [0.1, 0.1, 0.1] }
                """);
    }

    @Test
    void theLensReplacesTheScenesOwnPartByPart() throws Exception {
        Camera own = SceneFiles.open(scene(), with(SceneOverrides.NONE), Viewer.FilmCheck.NONE).scene().camera();
        assertThat(own.aperture()).isEqualTo(0.05);
        assertThat(own.focusDistance()).isEqualTo(6);
        Camera both = SceneFiles.open(scene(), with(new SceneOverrides(null, 0.2, 3.0)), Viewer.FilmCheck.NONE).scene().camera();
        assertThat(both.aperture()).isEqualTo(0.2);
        assertThat(both.focusDistance()).isEqualTo(3);
        assertThat(both.lookFrom()).isEqualTo(own.lookFrom());
        Camera pinhole = SceneFiles.open(scene(), with(new SceneOverrides(null, 0.0, null)), Viewer.FilmCheck.NONE).scene().camera();
        assertThat(pinhole.aperture()).isZero();
        assertThat(pinhole.focusDistance()).as("the scene's focus distance stays").isEqualTo(6);
    }

    @Test
    void theEnvironmentMapReplacesTheScenesEnvironment() throws Exception {
        float[] sky = new float[3 * 8 * 4];
        for (int i = 0; i < sky.length; i += 3) {
            sky[i] = 0.25f;
            sky[i + 1] = 0.5f;
            sky[i + 2] = 1f;
        }
        Path map = dir.resolve("sky.pfm");
        ImageWriters.write(new Image(8, 4, sky), map);
        SceneFiles.Opened opened = SceneFiles.open(scene(), with(new SceneOverrides(map, null, null)), Viewer.FilmCheck.NONE);
        Image img = Renders.render(opened.scene(), RenderSettings.defaults().withSize(8, 8).withSamplesPerPixel(1).withThreads(1));
        assertThat(img.get(0, 0, 0)).as("a corner sees the map, not the scene's grey").isEqualTo(0.25f);
        assertThat(img.get(0, 0, 1)).isEqualTo(0.5f);
        assertThat(img.get(0, 0, 2)).isEqualTo(1f);
    }

    @Test
    void aMissingEnvironmentMapIsOneLineNamingIt() throws Exception {
        Path missing = dir.resolve("none.hdr");
        assertThatThrownBy(() -> SceneFiles.open(scene(), with(new SceneOverrides(missing, null, null)), Viewer.FilmCheck.NONE))
                .isInstanceOf(SceneException.class).hasMessageContaining(missing.toString()).hasMessageNotContaining("\n");
    }

    @Test
    void optionsWithoutOverridesChangeNothing() {
        assertThat(ViewerOptions.defaults().overrides()).isEqualTo(SceneOverrides.NONE);
        assertThat(Arrays.asList(SceneOverrides.NONE.envmap(), SceneOverrides.NONE.aperture(), SceneOverrides.NONE.focusDistance()))
                .containsOnlyNulls();
    }
}
