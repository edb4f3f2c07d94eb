package dev.strahl.cli;

import dev.strahl.io.json.SceneSettings.Setting;
import dev.strahl.render.Aov;
import java.util.EnumSet;
import java.util.List;
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
    static final Map<String, Setting> OPTIONS = Map.ofEntries(
            Map.entry("--width", Setting.WIDTH),
            Map.entry("--height", Setting.HEIGHT),
            Map.entry("--spp", Setting.SAMPLES_PER_PIXEL),
            Map.entry("--max-depth", Setting.MAX_DEPTH),
            Map.entry("--seed", Setting.SEED),
            Map.entry("--integrator", Setting.INTEGRATOR),
            Map.entry("--light-samples", Setting.LIGHT_SAMPLES),
            Map.entry("--hemisphere", Setting.HEMISPHERE),
            Map.entry("--photons", Setting.PHOTONS),
            Map.entry("--photon-radius", Setting.PHOTON_RADIUS),
            Map.entry("--aov", Setting.AOVS),
            Map.entry("--noise-threshold", Setting.NOISE_THRESHOLD));

    private SceneFileOptions() {
    }

    /** The feature buffers named by {@code --aov} (null: not given, none); an unknown name is an error naming the option. */
    static Set<Aov> aovs(List<String> names) {
        Set<Aov> set = EnumSet.noneOf(Aov.class);
        if (names != null) {
            for (String name : names) {
                try {
                    set.add(Aov.of(name.trim()));
                } catch (IllegalArgumentException e) {
                    throw new IllegalArgumentException("--aov: " + e.getMessage());
                }
            }
        }
        return set;
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
