package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The settings a coordinator sends its members: every one arrives, the teaching options too. */
class UnitRenderersTest {

    @Test
    void everySettingSurvivesTheWire() {
        RenderSettings s = RenderSettings.defaults().withSize(33, 17).withSamplesPerPixel(12).withMaxDepth(5).withSeed(-7).withThreads(3)
                .withHemisphere(HemisphereSampling.UNIFORM).withCullBackFaces(true).withSamplesPerPass(2).withIntegrator(IntegratorKind.WHITTED)
                .withLightSamples(4).withTimeLimit(Duration.ofSeconds(9)).withPhotons(new PhotonParameters(1234, 0.25))
                .withBruteForce(true).withStripes(true).withShadows(false).withAovs(Set.of(Aov.DEPTH, Aov.ALBEDO));
        for (RenderSettings sent : new RenderSettings[] {s, RenderSettings.defaults(), s.withShadows(true)}) {
            for (boolean stratified : new boolean[] {true, false}) {
                UnitRenderers.Decoded back = UnitRenderers.decode(UnitRenderers.encode(sent, stratified));
                assertThat(back.settings()).isEqualTo(sent);
                assertThat(back.stratified()).isEqualTo(stratified);
            }
        }
    }

    /** A member of another strahl version (a setting more or less) refuses the settings naming the setting, as before it named the format. */
    @Test
    void settingsOfAnotherStrahlAreRefusedNamingTheSetting() {
        String text = UnitRenderers.encode(RenderSettings.defaults(), true);
        assertThatThrownBy(() -> UnitRenderers.decode(text.replace("shadows=true;", ""))).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("setting 'shadows' missing");
        assertThatThrownBy(() -> UnitRenderers.decode(text + ";mediaSteps=4")).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("unknown setting 'mediaSteps'");
        assertThatThrownBy(() -> UnitRenderers.decode(text.replace("maxDepth=-1", "maxDepth=0"))).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("max depth must be -1 (unbounded) or >= 1, got 0");
    }
}
