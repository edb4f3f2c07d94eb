package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import org.junit.jupiter.api.Test;

/** The photon mapper's fields of {@link RenderSettings}. */
class PhotonSettingsTest {

    @Test
    void defaultsAreTheAutomaticRadiusAndTheDefaultPhotonCount() {
        RenderSettings d = RenderSettings.defaults();
        assertThat(d.transport().photons().photonsPerIteration()).isEqualTo(PhotonParameters.DEFAULT_PHOTONS);
        assertThat(d.transport().photons().initialRadius()).isZero();
        assertThat(d.transport().integrator()).isEqualTo(IntegratorKind.PATH);
        assertThat(d.transport().photons()).isEqualTo(PhotonParameters.defaults());
    }

    @Test
    void withMethodsKeepThePhotonFieldsAndChangeOnlyTheirOwn() {
        RenderSettings s = RenderSettings.defaults().withPhotons(new PhotonParameters(5000, 0.02));
        assertThat(s.transport().photons()).isEqualTo(new PhotonParameters(5000, 0.02));
        RenderSettings t = s.withSize(7, 9).withSamplesPerPixel(3).withMaxDepth(4).withSeed(5).withThreads(2)
                .withHemisphere(HemisphereSampling.UNIFORM).withCullBackFaces(true).withSamplesPerPass(2)
                .withIntegrator(IntegratorKind.PHOTON).withLightSamples(3).withTimeLimit(Duration.ofSeconds(1));
        assertThat(t.transport().photons()).isEqualTo(new PhotonParameters(5000, 0.02));
        assertThat(t.withPhotons(new PhotonParameters(7, 0)).transport().photons()).isEqualTo(new PhotonParameters(7, 0));
    }

    @Test
    void badPhotonFieldsAreRefused() {
        assertThatThrownBy(() -> RenderSettings.defaults().withPhotons(new PhotonParameters(0, 0))).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("photons per iteration");
        assertThatThrownBy(() -> new PhotonParameters(10, -0.5)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("photon radius");
    }
}
