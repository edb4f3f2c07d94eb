package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The settings by name: one name per setting, the names checkpoints of version 2 were written with, and the way back. */
class SettingsCodecTest {

    @Test
    void everySettingHasItsOwnNameInTheOrderOfTheParts() {
        assertThat(RenderSettings.defaults().entries().keySet()).containsExactly("width", "height", "aovs", "samplesPerPixel", "seed",
                "noiseThreshold", "integrator", "maxDepth", "lightSamples", "hemisphere", "cullBackFaces", "shadows", "lightTree", "photons.photonsPerIteration",
                "photons.initialRadius", "threads", "samplesPerPass", "timeLimit", "bruteForce", "stripes");
    }

    /** A checkpoint names the settings as it did before they were grouped, so that its files still resume. */
    @Test
    void theFingerprintKeepsTheNamesOfTheFlatSettings() {
        assertThat(SettingsCodec.parse(Checkpoint.settingsKey(RenderSettings.defaults())).keySet()).containsExactlyInAnyOrder("width",
                "height", "maxDepth", "seed", "hemisphere", "cullBackFaces", "integrator", "lightSamples", "photons.photonsPerIteration",
                "photons.initialRadius", "bruteForce", "stripes", "shadows", "lightTree", "noiseThreshold", "sampler", "features");
        // as version 2 wrote it before the parts: the same settings in the order of the flat record
        String flat = "width=512;height=512;maxDepth=-1;seed=0;hemisphere=COSINE;cullBackFaces=false;integrator=PATH;lightSamples=1;"
                + "photons.photonsPerIteration=100000;photons.initialRadius=0.0;bruteForce=false;stripes=false;shadows=true";
        assertThat(SettingsCodec.parse(Checkpoint.settingsKey(RenderSettings.defaults())))
                .containsAllEntriesOf(SettingsCodec.parse(flat));
    }

    @Test
    void theTextFormReadsBackToTheSameSettings() {
        RenderSettings s = RenderSettings.defaults().withSize(3, 5).withAovs(Set.of(Aov.NORMAL, Aov.ALBEDO)).withTimeLimit(Duration.ofMillis(1500))
                .withPhotons(new PhotonParameters(77, 0.1 + 0.2)).withSeed(Long.MIN_VALUE).withIntegrator(IntegratorKind.PHOTON);
        for (RenderSettings each : new RenderSettings[] {s, RenderSettings.defaults(), s.withAovs(Set.of())}) {
            assertThat(SettingsCodec.settings(SettingsCodec.parse(SettingsCodec.text(each.entries())))).isEqualTo(each);
        }
    }
}
