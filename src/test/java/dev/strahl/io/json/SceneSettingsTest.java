package dev.strahl.io.json;

import dev.strahl.io.json.SceneSettings.Setting;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import dev.strahl.render.Aov;
import dev.strahl.render.PhotonParameters;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.SceneException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import org.junit.jupiter.api.Test;

/**
 * {@link SceneSettings#applyTo}, the one place where a command line's options and a scene
 * file's settings are combined (for {@code render} and {@code view}): the file replaces what is not
 * given, what is given wins, each setting on its own, and the file is checked whatever is given.
 */
class SceneSettingsTest {
    /** A file that sets every key, each to a value unlike the command line's below. */
    static final SceneSettings EVERY_KEY = new SceneSettings(320, 160, 8, 3, 42L, IntegratorKind.DIRECT, 4, HemisphereSampling.UNIFORM, 2000, 0.1,
            Set.of(Aov.ALBEDO, Aov.DEPTH), null, 0.05);
    /** A command line with a value for every setting and for settings a file cannot give (threads, culling, pass size, time limit). */
    static final RenderSettings COMMAND_LINE = RenderSettings.defaults().withSize(200, 100).withSamplesPerPixel(256).withMaxDepth(5)
            .withSeed(9).withIntegrator(IntegratorKind.WHITTED).withLightSamples(2).withHemisphere(HemisphereSampling.COSINE)
            .withThreads(3).withCullBackFaces(true).withSamplesPerPass(2).withTimeLimit(Duration.ofSeconds(7))
            .withPhotons(new PhotonParameters(5000, 0.25)).withAovs(EnumSet.of(Aov.NORMAL)).withNoiseThreshold(0.01);

    /** Each setting's value in a RenderSettings. */
    static final Map<Setting, Function<RenderSettings, Object>> VALUE = new EnumMap<>(Map.ofEntries(
            Map.entry(Setting.AOVS, r -> r.output().aovs()),
            Map.entry(Setting.WIDTH, r -> r.output().width()),
            Map.entry(Setting.HEIGHT, r -> r.output().height()),
            Map.entry(Setting.SAMPLES_PER_PIXEL, r -> r.sampling().samplesPerPixel()),
            Map.entry(Setting.MAX_DEPTH, r -> r.transport().maxDepth()),
            Map.entry(Setting.SEED, r -> r.sampling().seed()),
            Map.entry(Setting.INTEGRATOR, r -> r.transport().integrator()),
            Map.entry(Setting.LIGHT_SAMPLES, r -> r.transport().lightSamples()),
            Map.entry(Setting.HEMISPHERE, r -> r.transport().hemisphere()),
            Map.entry(Setting.PHOTONS, r -> r.transport().photons().photonsPerIteration()),
            Map.entry(Setting.PHOTON_RADIUS, r -> r.transport().photons().initialRadius()),
            Map.entry(Setting.NOISE_THRESHOLD, r -> r.sampling().noiseThreshold())));

    @Test
    void withNothingGivenTheFileReplacesEverySettingItHas() throws Exception {
        RenderSettings s = EVERY_KEY.applyTo(COMMAND_LINE, Set.of());
        assertThat(s).isEqualTo(EVERY_KEY.applyTo(COMMAND_LINE));
        assertThat(s).isEqualTo(COMMAND_LINE.withSize(320, 160).withSamplesPerPixel(8).withMaxDepth(3).withSeed(42)
                .withIntegrator(IntegratorKind.DIRECT).withLightSamples(4).withHemisphere(HemisphereSampling.UNIFORM)
                .withPhotons(new PhotonParameters(2000, 0.1)).withAovs(EnumSet.of(Aov.ALBEDO, Aov.DEPTH)).withNoiseThreshold(0.05));
        assertThat(SceneSettings.NONE.applyTo(COMMAND_LINE, Set.of())).as("a file that says nothing").isEqualTo(COMMAND_LINE);
    }

    @Test
    void withEverythingGivenTheCommandLineWins() throws Exception {
        assertThat(EVERY_KEY.applyTo(COMMAND_LINE, EnumSet.allOf(Setting.class))).isEqualTo(COMMAND_LINE);
    }

    @Test
    void eachGivenSettingAloneWinsAndEveryOtherComesFromTheFile() throws Exception {
        assertThat(VALUE.keySet()).as("every setting is checked").isEqualTo(EnumSet.allOf(Setting.class));
        RenderSettings fromFile = EVERY_KEY.applyTo(COMMAND_LINE);
        for (Setting given : Setting.values()) {
            RenderSettings s = EVERY_KEY.applyTo(COMMAND_LINE, Set.of(given));
            for (Setting other : Setting.values()) {
                Object expected = VALUE.get(other).apply(other == given ? COMMAND_LINE : fromFile);
                assertThat(VALUE.get(other).apply(s)).as("%s given: %s", given, other).isEqualTo(expected);
            }
            assertThat(VALUE.get(given).apply(fromFile)).as("the file's %s differs from the command line's", given)
                    .isNotEqualTo(VALUE.get(given).apply(COMMAND_LINE));
        }
        RenderSettings widthOnly = EVERY_KEY.applyTo(COMMAND_LINE, Set.of(Setting.WIDTH));
        assertThat(new int[] {widthOnly.output().width(), widthOnly.output().height()}).as("the given width with the file's height").containsExactly(200, 160);
    }

    @Test
    void settingsAFileCannotGiveAreKept() throws Exception {
        for (Set<Setting> given : java.util.List.of(Set.<Setting>of(), EnumSet.allOf(Setting.class))) {
            RenderSettings s = EVERY_KEY.applyTo(COMMAND_LINE, given);
            assertThat(s.execution().threads()).isEqualTo(3);
            assertThat(s.transport().cullBackFaces()).isTrue();
            assertThat(s.execution().samplesPerPass()).isEqualTo(2);
            assertThat(s.execution().timeLimit()).isEqualTo(Duration.ofSeconds(7));
        }
    }

    @Test
    void thePhotonKeysApplyLikeTheOthers() throws Exception {
        SceneSettings photonOnly = new SceneSettings(null, null, null, null, null, IntegratorKind.PHOTON, null, null, 30_000, null);
        RenderSettings s = photonOnly.applyTo(COMMAND_LINE, Set.of());
        assertThat(s.transport().integrator()).isEqualTo(IntegratorKind.PHOTON);
        assertThat(s.transport().photons().photonsPerIteration()).isEqualTo(30_000);
        assertThat(s.transport().photons().initialRadius()).as("the file says nothing: the command line's").isEqualTo(0.25);
        assertThat(photonOnly.applyTo(COMMAND_LINE, Set.of(Setting.PHOTONS)).transport().photons().photonsPerIteration()).as("--photons given").isEqualTo(5000);
    }

    /**
     * A glTF camera's aspect ratio: the file's 512×320 film, and with only one side given the
     * other follows the aspect (a render of a 1.6 camera at --width 320 is 320×200, not 320×320);
     * both given, or none, as always.
     */
    @Test
    void aCamerasAspectRatioGivesTheSideNotGiven() throws Exception {
        SceneSettings gltf = SceneFile.load(Path.of("scenes/gltf-showcase.glb")).settings();
        assertThat(gltf.aspectRatio()).isEqualTo(1.6);
        RenderSettings base = RenderSettings.defaults();
        RenderSettings none = gltf.applyTo(base, Set.of());
        assertThat(new int[] {none.output().width(), none.output().height()}).containsExactly(512, 320);
        RenderSettings width = gltf.applyTo(base.withSize(320, base.output().height()), Set.of(Setting.WIDTH));
        assertThat(new int[] {width.output().width(), width.output().height()}).containsExactly(320, 200);
        RenderSettings height = gltf.applyTo(base.withSize(base.output().width(), 100), Set.of(Setting.HEIGHT));
        assertThat(new int[] {height.output().width(), height.output().height()}).containsExactly(160, 100);
        RenderSettings both = gltf.applyTo(base.withSize(300, 300), Set.of(Setting.WIDTH, Setting.HEIGHT));
        assertThat(new int[] {both.output().width(), both.output().height()}).containsExactly(300, 300);
        RenderSettings json = EVERY_KEY.applyTo(base.withSize(100, base.output().height()), Set.of(Setting.WIDTH));
        assertThat(json.output().height()).as("a scene file's film: each side on its own").isEqualTo(160);
    }
}
