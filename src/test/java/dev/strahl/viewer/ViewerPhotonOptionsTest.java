package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.integrator.IntegratorKind;
import dev.strahl.integrator.PhotonParameters;
import dev.strahl.sampling.HemisphereSampling;
import dev.strahl.scene.SceneSettings;
import dev.strahl.scene.SceneSettings.Setting;
import java.nio.file.Path;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The photon mapper is one of the viewer's integrators and gets its parameters. */
class ViewerPhotonOptionsTest {
    static final Path SCENE = Path.of("s.json");

    @Test
    void photonParametersReachTheRenderSettings() throws Exception {
        ViewerOptions o = new ViewerOptions(null, 64, 64, 0, -1, HemisphereSampling.COSINE, 0, 0, IntegratorKind.PHOTON, 1, Theme.LIGHT, Set.of(), 5000, 0.03);
        assertThat(o.renderSettings().integrator()).isEqualTo(IntegratorKind.PHOTON);
        assertThat(o.renderSettings().photonParameters()).isEqualTo(new PhotonParameters(5000, 0.03));
        assertThat(ViewerOptions.defaults().renderSettings().photonParameters()).isEqualTo(PhotonParameters.defaults());
        // A scene file's settings keep the photon parameters of the options.
        assertThat(o.settingsFor(java.nio.file.Path.of("s.json"), dev.strahl.scene.SceneSettings.NONE).photonParameters())
                .isEqualTo(new PhotonParameters(5000, 0.03));
    }

    @Test
    void aSceneFilesPhotonKeysReplaceTheOptionsUnlessGiven() throws Exception {
        SceneSettings file = new SceneSettings(null, null, null, null, null, "photon", null, null, 20_000, 0.125);
        ViewerOptions none = new ViewerOptions(null, 64, 64, 0, -1, HemisphereSampling.COSINE, 0, 0, IntegratorKind.PATH, 1, Theme.LIGHT,
                Set.of(), 5000, 0.03);
        assertThat(none.settingsFor(SCENE, file).photonParameters()).isEqualTo(new PhotonParameters(20_000, 0.125));
        assertThat(none.settingsFor(SCENE, file).integrator()).isEqualTo(IntegratorKind.PHOTON);
        ViewerOptions given = new ViewerOptions(null, 64, 64, 0, -1, HemisphereSampling.COSINE, 0, 0, IntegratorKind.PATH, 1, Theme.LIGHT,
                Set.of(Setting.PHOTONS, Setting.PHOTON_RADIUS), 5000, 0.03);
        assertThat(given.settingsFor(SCENE, file).photonParameters()).as("--photons and --photon-radius given")
                .isEqualTo(new PhotonParameters(5000, 0.03));
    }

    @Test
    void badPhotonParametersAreRefused() {
        assertThatThrownBy(() -> new ViewerOptions(null, 64, 64, 0, -1, HemisphereSampling.COSINE, 0, 0, IntegratorKind.PHOTON, 1, Theme.LIGHT, Set.of(), 0, 0))
                .hasMessageContaining("photons per iteration");
    }

    @Test
    void theIntegratorChoiceOffersPhoton() {
        assertThat(IntegratorKind.values()).contains(IntegratorKind.PHOTON);
        assertThat(IntegratorKind.PHOTON.id()).isEqualTo("photon");
    }
}
