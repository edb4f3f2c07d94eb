package dev.strahl.cli;

import dev.strahl.io.json.SceneSettings.Setting;
import java.util.EnumSet;
import java.util.Map;
import java.util.Set;
import picocli.CommandLine;

/**
 * The options that name a scene file's settings, for {@code render} and {@code view} alike: an
 * option given on the command line, even at its default value, wins over the file's key
 * ({@code RenderSettings.withSceneFile} combines them).
 */
final class SceneFileOptions {
    /** Each option that a scene file's {@code film} or {@code integrator} key also sets. */
    static final Map<String, Setting> OPTIONS = Map.of(
            "--width", Setting.WIDTH,
            "--height", Setting.HEIGHT,
            "--spp", Setting.SAMPLES_PER_PIXEL,
            "--max-depth", Setting.MAX_DEPTH,
            "--seed", Setting.SEED,
            "--integrator", Setting.INTEGRATOR,
            "--light-samples", Setting.LIGHT_SAMPLES,
            "--hemisphere", Setting.HEMISPHERE,
            "--photons", Setting.PHOTONS,
            "--photon-radius", Setting.PHOTON_RADIUS);

    private SceneFileOptions() {
    }

    /** The settings whose option is on the command line of {@code parsed}. */
    static Set<Setting> given(CommandLine.ParseResult parsed) {
        Set<Setting> given = EnumSet.noneOf(Setting.class);
        OPTIONS.forEach((option, setting) -> {
            if (parsed.hasMatchedOption(option)) {
                given.add(setting);
            }
        });
        return given;
    }
}
