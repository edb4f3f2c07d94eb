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

    @Test
    void settingsOfAnotherFormatAreRefusedNamingBoth() {
        byte[] bytes = UnitRenderers.encode(RenderSettings.defaults(), true);
        bytes[3] = 2;                                   // the format before the shadows setting
        assertThatThrownBy(() -> UnitRenderers.decode(bytes)).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("settings of format 2; this strahl reads 3");
    }
}
