package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.render.RenderSettings;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.PhotonParameters;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.io.json.SceneSettings;
import dev.strahl.io.json.SceneSettings.Setting;
import java.nio.file.Path;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The photon mapper is one of the viewer's integrators and gets its parameters. */
class ViewerPhotonOptionsTest {
    static final Path SCENE = Path.of("s.json");

    @Test
    void photonParametersReachTheRenderSettings() throws Exception {
        ViewerOptions o = new ViewerOptions(null, RenderSettings.defaults().withSize(64, 64).withIntegrator(IntegratorKind.PHOTON).withPhotons(new PhotonParameters(5000, 0.03)),
                0, Theme.LIGHT, Set.of(), SceneOverrides.NONE);
        assertThat(o.renderSettings().transport().integrator()).isEqualTo(IntegratorKind.PHOTON);
        assertThat(o.renderSettings().transport().photons()).isEqualTo(new PhotonParameters(5000, 0.03));
        assertThat(ViewerOptions.defaults().renderSettings().transport().photons()).isEqualTo(PhotonParameters.defaults());
        // A scene file's settings keep the photon parameters of the options.
        assertThat(o.settingsFor(dev.strahl.io.json.SceneSettings.NONE).transport().photons())
                .isEqualTo(new PhotonParameters(5000, 0.03));
    }

    @Test
    void aSceneFilesPhotonKeysReplaceTheOptionsUnlessGiven() throws Exception {
        SceneSettings file = new SceneSettings(null, null, null, null, null, IntegratorKind.PHOTON, null, null, 20_000, 0.125);
        ViewerOptions none = new ViewerOptions(null, RenderSettings.defaults().withSize(64, 64).withPhotons(new PhotonParameters(5000, 0.03)),
                0, Theme.LIGHT, Set.of(), SceneOverrides.NONE);
        assertThat(none.settingsFor(file).transport().photons()).isEqualTo(new PhotonParameters(20_000, 0.125));
        assertThat(none.settingsFor(file).transport().integrator()).isEqualTo(IntegratorKind.PHOTON);
        ViewerOptions given = new ViewerOptions(null, RenderSettings.defaults().withSize(64, 64).withPhotons(new PhotonParameters(5000, 0.03)),
                0, Theme.LIGHT, Set.of(Setting.PHOTONS, Setting.PHOTON_RADIUS), SceneOverrides.NONE);
        assertThat(given.settingsFor(file).transport().photons()).as("--photons and --photon-radius given")
                .isEqualTo(new PhotonParameters(5000, 0.03));
    }

    @Test
    void badPhotonParametersAreRefused() {
        assertThatThrownBy(() -> new ViewerOptions(null, RenderSettings.defaults().withSize(64, 64).withIntegrator(IntegratorKind.PHOTON).withPhotons(new PhotonParameters(0, 0)),
                0, Theme.LIGHT, Set.of(), SceneOverrides.NONE))
                .hasMessageContaining("photons per iteration");
    }

    @Test
    void theIntegratorChoiceOffersPhoton() {
        assertThat(IntegratorKind.values()).contains(IntegratorKind.PHOTON);
        assertThat(IntegratorKind.PHOTON.id()).isEqualTo("photon");
    }
}
