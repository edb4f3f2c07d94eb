package dev.strahl.viewer;

import dev.strahl.integrator.IntegratorKind;
import dev.strahl.render.RenderSettings;
import dev.strahl.sampling.HemisphereSampling;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.SceneSettings;
import java.nio.file.Path;
import java.util.Objects;
import java.util.Set;

/**
 * How to start the viewer. A scene file's {@code film} and {@code integrator} keys replace the
 * values here, except those of the options named in {@code given}, which win as they do on the
 * command line ({@link #settingsFor}).
 *
 * @param scene      the scene file, or null for the default Cornell Box
 * @param width      film width in pixels at start-up (the film keeps this aspect when the window is resized)
 * @param height     film height in pixels at start-up
 * @param stopAt     samples per pixel after which rendering holds; 0 never stops
 * @param maxDepth   path segments including the camera segment; -1 unbounded
 * @param hemisphere diffuse direction sampling
 * @param threads    worker threads; 0 for all processors
 * @param seed       random seed
 * @param integrator   the light transport algorithm
 * @param lightSamples shadow rays per diffuse hit for the direct and Whitted integrators
 * @param theme      light, dark, or follow the system
 * @param given      the settings given explicitly (on the command line): a scene file does not override them
 */
public record ViewerOptions(Path scene, int width, int height, int stopAt, int maxDepth, HemisphereSampling hemisphere,
                            int threads, long seed, IntegratorKind integrator, int lightSamples, Theme theme, Set<Setting> given) {

    /** The options that a scene file's {@code film} and {@code integrator} keys also set. */
    public enum Setting { WIDTH, HEIGHT, MAX_DEPTH, HEMISPHERE, SEED, INTEGRATOR, LIGHT_SAMPLES }

    public ViewerOptions {
        if (stopAt < 0) {
            throw new IllegalArgumentException("stop-at samples per pixel must be >= 0 (0 = never stop), got " + stopAt);
        }
        Objects.requireNonNull(hemisphere, "hemisphere");
        Objects.requireNonNull(integrator, "integrator");
        Objects.requireNonNull(theme, "theme");
        given = Set.copyOf(Objects.requireNonNull(given, "given"));
        renderSettings(width, height, maxDepth, hemisphere, threads, seed, integrator, lightSamples);   // validates
    }

    /**
     * The Cornell Box at 512×512, stopping at 1024 spp, unbounded depth, cosine sampling, all
     * processors; nothing given explicitly, so a scene file's settings apply.
     */
    public static ViewerOptions defaults() {
        return new ViewerOptions(null, 512, 512, 1024, -1, HemisphereSampling.COSINE, 0, 0, IntegratorKind.PATH, 1, Theme.SYSTEM, Set.of());
    }

    /** The render settings these options describe, without a scene file (validated by {@link RenderSettings}). */
    RenderSettings renderSettings() {
        return renderSettings(width, height, maxDepth, hemisphere, threads, seed, integrator, lightSamples);
    }

    /**
     * The render settings for a scene loaded from {@code file}: its film size, integrator, max
     * depth, hemisphere sampling, light samples and seed replace these options' values, and the
     * options in {@link #given} override the file again, as {@code strahl render} combines them.
     * The file's {@code spp} is not used: the viewer renders until its own stop-at count.
     *
     * @throws SceneException naming {@code file} if the file asks for an unknown integrator
     */
    RenderSettings settingsFor(Path file, SceneSettings sceneSettings) throws SceneException {
        RenderSettings base = renderSettings();
        RenderSettings s;
        try {
            s = base.withScene(sceneSettings).withSamplesPerPixel(base.samplesPerPixel());
        } catch (IllegalArgumentException e) {
            throw new SceneException(file, e.getMessage(), e);
        }
        if (given.contains(Setting.WIDTH) || given.contains(Setting.HEIGHT)) {
            s = s.withSize(given.contains(Setting.WIDTH) ? width : s.width(), given.contains(Setting.HEIGHT) ? height : s.height());
        }
        if (given.contains(Setting.MAX_DEPTH)) {
            s = s.withMaxDepth(maxDepth);
        }
        if (given.contains(Setting.HEMISPHERE)) {
            s = s.withHemisphere(hemisphere);
        }
        if (given.contains(Setting.SEED)) {
            s = s.withSeed(seed);
        }
        if (given.contains(Setting.INTEGRATOR)) {
            s = s.withIntegrator(integrator);
        }
        if (given.contains(Setting.LIGHT_SAMPLES)) {
            s = s.withLightSamples(lightSamples);
        }
        return s;
    }

    private static RenderSettings renderSettings(int width, int height, int maxDepth, HemisphereSampling hemisphere, int threads, long seed,
                                                 IntegratorKind integrator, int lightSamples) {
        return RenderSettings.defaults().withSize(width, height).withMaxDepth(maxDepth).withHemisphere(hemisphere)
                .withThreads(threads).withSeed(seed).withIntegrator(integrator).withLightSamples(lightSamples).withSamplesPerPass(1);
    }
}
