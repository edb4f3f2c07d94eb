package dev.strahl.viewer;

import dev.strahl.render.Aov;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.PhotonParameters;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.scene.SceneException;
import dev.strahl.io.json.SceneSettings;
import dev.strahl.io.json.SceneSettings.Setting;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.Objects;
import java.util.Set;

/**
 * How to start the viewer. A scene file's {@code film} and {@code integrator} keys replace the
 * values here, except those of the options named in {@code given}, which win as they do on the
 * command line, and except {@code spp}: the viewer renders until its own stop-at count
 * ({@link #settingsFor}).
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
 * @param photons      photons per iteration for the photon mapper
 * @param photonRadius the photon mapper's initial gather radius; 0 = automatic
 * @param aovs         the feature buffers the render keeps ({@code --aov}, a scene file's {@code film.aovs})
 * @param overrides    the environment map and lens that replace every opened scene's own (command-line options)
 * @param shadows      whether shadow rays are traced (false: the teaching option {@code --shadows off})
 */
public record ViewerOptions(Path scene, int width, int height, int stopAt, int maxDepth, HemisphereSampling hemisphere,
                            int threads, long seed, IntegratorKind integrator, int lightSamples, Theme theme, Set<Setting> given,
                            int photons, double photonRadius, Set<Aov> aovs, SceneOverrides overrides, boolean shadows) {

    /**
     * The scene-file settings the viewer never takes from a file: its stop-at count is an
     * interactive limit, not a sample budget, so a file's {@code spp} does not apply.
     */
    static final Set<Setting> NEVER_FROM_FILE = Set.of(Setting.SAMPLES_PER_PIXEL);

    public ViewerOptions {
        checkStopAt(stopAt);
        Objects.requireNonNull(hemisphere, "hemisphere");
        Objects.requireNonNull(integrator, "integrator");
        Objects.requireNonNull(theme, "theme");
        given = Set.copyOf(Objects.requireNonNull(given, "given"));
        aovs = Set.copyOf(Objects.requireNonNull(aovs, "aovs"));
        Objects.requireNonNull(overrides, "overrides");
        renderSettings(width, height, maxDepth, hemisphere, threads, seed, integrator, lightSamples, photons, photonRadius);   // validates
    }

    /** Options with shadows, without feature buffers, that change nothing in the scenes opened. */
    public ViewerOptions(Path scene, int width, int height, int stopAt, int maxDepth, HemisphereSampling hemisphere, int threads,
                         long seed, IntegratorKind integrator, int lightSamples, Theme theme, Set<Setting> given, int photons,
                         double photonRadius) {
        this(scene, width, height, stopAt, maxDepth, hemisphere, threads, seed, integrator, lightSamples, theme, given, photons,
                photonRadius, Set.of(), SceneOverrides.NONE, true);
    }

    /** Options with the photon mapper's default parameters. */
    public ViewerOptions(Path scene, int width, int height, int stopAt, int maxDepth, HemisphereSampling hemisphere,
                         int threads, long seed, IntegratorKind integrator, int lightSamples, Theme theme, Set<Setting> given) {
        this(scene, width, height, stopAt, maxDepth, hemisphere, threads, seed, integrator, lightSamples, theme, given,
                PhotonParameters.DEFAULT_PHOTONS, 0);
    }

    /**
     * The Cornell Box at 512×512, stopping at 1024 spp, unbounded depth, cosine sampling, all
     * processors; nothing given explicitly, so a scene file's settings apply.
     */
    public static ViewerOptions defaults() {
        return new ViewerOptions(null, 512, 512, 1024, -1, HemisphereSampling.COSINE, 0, 0, IntegratorKind.PATH, 1, Theme.SYSTEM, Set.of());
    }

    /** Returns {@code n} if it is a stop-at count (0 = never stop, or a positive count of samples per pixel). */
    static int checkStopAt(int n) {
        if (n < 0) {
            throw new IllegalArgumentException("stop-at samples per pixel must be >= 0 (0 = never stop), got " + n);
        }
        return n;
    }

    /** The render settings these options describe, without a scene file (validated by {@link RenderSettings}). */
    RenderSettings renderSettings() {
        RenderSettings s = renderSettings(width, height, maxDepth, hemisphere, threads, seed, integrator, lightSamples, photons, photonRadius);
        return s.withAovs(aovs.isEmpty() ? EnumSet.noneOf(Aov.class) : EnumSet.copyOf(aovs)).withShadows(shadows);
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

    private static RenderSettings renderSettings(int width, int height, int maxDepth, HemisphereSampling hemisphere, int threads, long seed,
                                                 IntegratorKind integrator, int lightSamples, int photons, double photonRadius) {
        return RenderSettings.defaults().withSize(width, height).withMaxDepth(maxDepth).withHemisphere(hemisphere)
                .withThreads(threads).withSeed(seed).withIntegrator(integrator).withLightSamples(lightSamples).withSamplesPerPass(1)
                .withPhotons(new PhotonParameters(photons, photonRadius));
    }
}
