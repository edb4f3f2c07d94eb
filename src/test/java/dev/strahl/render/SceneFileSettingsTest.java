package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import dev.strahl.integrator.IntegratorKind;
import dev.strahl.sampling.HemisphereSampling;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.SceneSettings;
import dev.strahl.scene.SceneSettings.Setting;
import java.nio.file.Path;
import java.time.Duration;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import org.junit.jupiter.api.Test;

/**
 * {@link RenderSettings#withSceneFile}, the one place where a command line's options and a scene
 * file's settings are combined (for {@code render} and {@code view}): the file replaces what is not
 * given, what is given wins, each setting on its own, and the file is checked whatever is given.
 */
class SceneFileSettingsTest {
    static final Path FILE = Path.of("s.json");
    /** A file that sets every key, each to a value unlike the command line's below. */
    static final SceneSettings EVERY_KEY = new SceneSettings(320, 160, 8, 3, 42L, "direct", 4, HemisphereSampling.UNIFORM, 2000, 0.1);
    /** A command line with a value for every setting and for settings a file cannot give (threads, culling, pass size, time limit). */
    static final RenderSettings COMMAND_LINE = RenderSettings.defaults().withSize(200, 100).withSamplesPerPixel(256).withMaxDepth(5)
            .withSeed(9).withIntegrator(IntegratorKind.WHITTED).withLightSamples(2).withHemisphere(HemisphereSampling.COSINE)
            .withThreads(3).withCullBackFaces(true).withSamplesPerPass(2).withTimeLimit(Duration.ofSeconds(7))
            .withPhotons(5000).withPhotonRadius(0.25);

    /** Each setting's value in a RenderSettings. */
    static final Map<Setting, Function<RenderSettings, Object>> VALUE = new EnumMap<>(Map.of(
            Setting.WIDTH, RenderSettings::width,
            Setting.HEIGHT, RenderSettings::height,
            Setting.SAMPLES_PER_PIXEL, RenderSettings::samplesPerPixel,
            Setting.MAX_DEPTH, RenderSettings::maxDepth,
            Setting.SEED, RenderSettings::seed,
            Setting.INTEGRATOR, RenderSettings::integrator,
            Setting.LIGHT_SAMPLES, RenderSettings::lightSamples,
            Setting.HEMISPHERE, RenderSettings::hemisphere,
            Setting.PHOTONS, RenderSettings::photons,
            Setting.PHOTON_RADIUS, RenderSettings::photonRadius));

    @Test
    void withNothingGivenTheFileReplacesEverySettingItHas() throws Exception {
        RenderSettings s = COMMAND_LINE.withSceneFile(FILE, EVERY_KEY, Set.of());
        assertThat(s).isEqualTo(COMMAND_LINE.withScene(EVERY_KEY));
        assertThat(s).isEqualTo(COMMAND_LINE.withSize(320, 160).withSamplesPerPixel(8).withMaxDepth(3).withSeed(42)
                .withIntegrator(IntegratorKind.DIRECT).withLightSamples(4).withHemisphere(HemisphereSampling.UNIFORM)
                .withPhotons(2000).withPhotonRadius(0.1));
        assertThat(COMMAND_LINE.withSceneFile(FILE, SceneSettings.NONE, Set.of())).as("a file that says nothing").isEqualTo(COMMAND_LINE);
    }

    @Test
    void withEverythingGivenTheCommandLineWins() throws Exception {
        assertThat(COMMAND_LINE.withSceneFile(FILE, EVERY_KEY, EnumSet.allOf(Setting.class))).isEqualTo(COMMAND_LINE);
    }

    @Test
    void eachGivenSettingAloneWinsAndEveryOtherComesFromTheFile() throws Exception {
        assertThat(VALUE.keySet()).as("every setting is checked").isEqualTo(EnumSet.allOf(Setting.class));
        RenderSettings fromFile = COMMAND_LINE.withScene(EVERY_KEY);
        for (Setting given : Setting.values()) {
            RenderSettings s = COMMAND_LINE.withSceneFile(FILE, EVERY_KEY, Set.of(given));
            for (Setting other : Setting.values()) {
                Object expected = VALUE.get(other).apply(other == given ? COMMAND_LINE : fromFile);
                assertThat(VALUE.get(other).apply(s)).as("%s given: %s", given, other).isEqualTo(expected);
            }
            assertThat(VALUE.get(given).apply(fromFile)).as("the file's %s differs from the command line's", given)
                    .isNotEqualTo(VALUE.get(given).apply(COMMAND_LINE));
        }
        RenderSettings widthOnly = COMMAND_LINE.withSceneFile(FILE, EVERY_KEY, Set.of(Setting.WIDTH));
        assertThat(new int[] {widthOnly.width(), widthOnly.height()}).as("the given width with the file's height").containsExactly(200, 160);
    }

    @Test
    void settingsAFileCannotGiveAreKept() throws Exception {
        for (Set<Setting> given : java.util.List.of(Set.<Setting>of(), EnumSet.allOf(Setting.class))) {
            RenderSettings s = COMMAND_LINE.withSceneFile(FILE, EVERY_KEY, given);
            assertThat(s.threads()).isEqualTo(3);
            assertThat(s.cullBackFaces()).isTrue();
            assertThat(s.samplesPerPass()).isEqualTo(2);
            assertThat(s.timeLimit()).isEqualTo(Duration.ofSeconds(7));
        }
    }

    @Test
    void thePhotonKeysApplyLikeTheOthers() throws Exception {
        SceneSettings photonOnly = new SceneSettings(null, null, null, null, null, "photon", null, null, 30_000, null);
        RenderSettings s = COMMAND_LINE.withSceneFile(FILE, photonOnly, Set.of());
        assertThat(s.integrator()).isEqualTo(IntegratorKind.PHOTON);
        assertThat(s.photons()).isEqualTo(30_000);
        assertThat(s.photonRadius()).as("the file says nothing: the command line's").isEqualTo(0.25);
        assertThat(COMMAND_LINE.withSceneFile(FILE, photonOnly, Set.of(Setting.PHOTONS)).photons()).as("--photons given").isEqualTo(5000);
    }

    @Test
    void anUnknownIntegratorIsASceneErrorNamingTheFileEvenWhenTheIntegratorIsGiven() {
        SceneSettings bad = new SceneSettings(null, null, null, null, null, "bidir", null, null);
        for (Set<Setting> given : java.util.List.of(Set.<Setting>of(), Set.of(Setting.INTEGRATOR))) {
            SceneException e = catchThrowableOfType(SceneException.class, () -> COMMAND_LINE.withSceneFile(FILE, bad, given));
            assertThat(e).as("given %s", given).isNotNull();
            assertThat(e.getMessage()).isEqualTo("s.json: unknown integrator 'bidir' (known: path, direct, whitted, photon)");
            assertThat(e.file()).isEqualTo(FILE);
        }
    }
}
