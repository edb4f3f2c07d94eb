package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.integrator.IntegratorKind;
import dev.strahl.integrator.PhotonParameters;
import dev.strahl.sampling.HemisphereSampling;
import java.time.Duration;
import org.junit.jupiter.api.Test;

/** The photon mapper's fields of {@link RenderSettings}. */
class PhotonSettingsTest {

    @Test
    void defaultsAreTheAutomaticRadiusAndTheDefaultPhotonCount() {
        RenderSettings d = RenderSettings.defaults();
        assertThat(d.photons()).isEqualTo(PhotonParameters.DEFAULT_PHOTONS);
        assertThat(d.photonRadius()).isZero();
        assertThat(d.integrator()).isEqualTo(IntegratorKind.PATH);
        assertThat(d.photonParameters()).isEqualTo(PhotonParameters.defaults());
        // The constructor without photon fields gives the same defaults.
        RenderSettings old = new RenderSettings(512, 512, 64, -1, 0, 0, HemisphereSampling.COSINE, false, 0, IntegratorKind.PATH, 1, Duration.ZERO);
        assertThat(old).isEqualTo(d);
    }

    @Test
    void withMethodsKeepThePhotonFieldsAndChangeOnlyTheirOwn() {
        RenderSettings s = RenderSettings.defaults().withPhotons(5000).withPhotonRadius(0.02);
        assertThat(s.photons()).isEqualTo(5000);
        assertThat(s.photonRadius()).isEqualTo(0.02);
        RenderSettings t = s.withSize(7, 9).withSamplesPerPixel(3).withMaxDepth(4).withSeed(5).withThreads(2)
                .withHemisphere(HemisphereSampling.UNIFORM).withCullBackFaces(true).withSamplesPerPass(2)
                .withIntegrator(IntegratorKind.PHOTON).withLightSamples(3).withTimeLimit(Duration.ofSeconds(1));
        assertThat(t.photonParameters()).isEqualTo(new PhotonParameters(5000, 0.02));
        assertThat(t.withPhotons(7).photonRadius()).isEqualTo(0.02);
        assertThat(t.withPhotonRadius(0).photons()).isEqualTo(5000);
    }

    @Test
    void badPhotonFieldsAreRefused() {
        assertThatThrownBy(() -> RenderSettings.defaults().withPhotons(0)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("photons per iteration");
        assertThatThrownBy(() -> RenderSettings.defaults().withPhotonRadius(-0.5)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("photon radius");
    }
}
