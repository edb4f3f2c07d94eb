package dev.strahl.viewer;

import dev.strahl.io.json.SceneSettings;
import dev.strahl.io.json.SceneSettings.Setting;
import dev.strahl.render.RenderSettings;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.Objects;
import java.util.Set;

/**
 * How to start the viewer, by concern: the scene, the render settings (as {@code strahl render}
 * takes them), when to hold, the look of the window, which settings the command line gave, and what
 * it changes in every scene opened. A scene file's {@code film} and {@code integrator} keys replace
 * the settings here, except those named in {@code given}, which win as they do on the command line,
 * and except {@code spp}: the viewer renders until its own stop-at count ({@link #settingsFor}).
 * Start from {@link #defaults()} and change parts with the {@code with...} methods.
 *
 * @param scene     the scene file, or null for the default Cornell Box
 * @param settings  the render settings; the film size is the window's at start-up (the film keeps its
 *                  aspect when the window is resized), the sample count is not used
 * @param stopAt    samples per pixel after which rendering holds; 0 never stops
 * @param theme     light, dark, or follow the system
 * @param given     the settings given explicitly (on the command line): a scene file does not override them
 * @param overrides the environment map and lens that replace every opened scene's own (command-line options)
 */
public record ViewerOptions(Path scene, RenderSettings settings, int stopAt, Theme theme, Set<Setting> given, SceneOverrides overrides) {

    /**
     * The scene-file settings the viewer never takes from a file: its stop-at count is an
     * interactive limit, not a sample budget, so a file's {@code spp} does not apply.
     */
    static final Set<Setting> NEVER_FROM_FILE = Set.of(Setting.SAMPLES_PER_PIXEL);

    public ViewerOptions {
        Objects.requireNonNull(settings, "settings");
        checkStopAt(stopAt);
        Objects.requireNonNull(theme, "theme");
        given = Set.copyOf(Objects.requireNonNull(given, "given"));
        Objects.requireNonNull(overrides, "overrides");
    }

    /**
     * The Cornell Box at 512×512, stopping at 1024 spp, with the render defaults (path tracing,
     * unbounded depth, all processors); nothing given explicitly, so a scene file's settings apply.
     */
    public static ViewerOptions defaults() {
        return new ViewerOptions(null, RenderSettings.defaults(), 1024, Theme.SYSTEM, Set.of(), SceneOverrides.NONE);
    }

    /** These options with another scene file (null: the Cornell Box). */
    public ViewerOptions withScene(Path file) {
        return new ViewerOptions(file, settings, stopAt, theme, given, overrides);
    }

    /** These options with other render settings. */
    public ViewerOptions withSettings(RenderSettings s) {
        return new ViewerOptions(scene, s, stopAt, theme, given, overrides);
    }

    /** These options with another stop-at count (0: never stop). */
    public ViewerOptions withStopAt(int n) {
        return new ViewerOptions(scene, settings, n, theme, given, overrides);
    }

    /** These options with another theme. */
    public ViewerOptions withTheme(Theme t) {
        return new ViewerOptions(scene, settings, stopAt, t, given, overrides);
    }

    /** These options with other settings given on the command line. */
    public ViewerOptions withGiven(Set<Setting> g) {
        return new ViewerOptions(scene, settings, stopAt, theme, g, overrides);
    }

    /** These options with other changes to every scene opened. */
    public ViewerOptions withOverrides(SceneOverrides o) {
        return new ViewerOptions(scene, settings, stopAt, theme, given, o);
    }

    /** Returns {@code n} if it is a stop-at count (0 = never stop, or a positive count of samples per pixel). */
    static int checkStopAt(int n) {
        if (n < 0) {
            throw new IllegalArgumentException("stop-at samples per pixel must be >= 0 (0 = never stop), got " + n);
        }
        return n;
    }

    /** The render settings the viewer starts jobs with, without a scene file: passes of one sample per pixel. */
    RenderSettings renderSettings() {
        return settings.withSamplesPerPass(1);
    }

    /**
     * The render settings for a scene loaded from {@code file}: its film size, integrator, max
     * depth, hemisphere sampling, light samples and seed replace these options' values, and the
     * options in {@link #given} override the file again, as {@code strahl render} combines them
     * ({@link SceneSettings#applyTo}, shared with it). The file's {@code spp} is not used
     * ({@link #NEVER_FROM_FILE}): the viewer renders until its own stop-at count.
     */
    RenderSettings settingsFor(SceneSettings sceneSettings) {
        Set<Setting> kept = EnumSet.copyOf(NEVER_FROM_FILE);
        kept.addAll(given);
        return sceneSettings.applyTo(renderSettings(), kept);
    }
}
