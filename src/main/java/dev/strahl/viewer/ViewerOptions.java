package dev.strahl.viewer;

import dev.strahl.integrator.IntegratorKind;
import dev.strahl.integrator.PhotonParameters;
import dev.strahl.render.RenderSettings;
import dev.strahl.sampling.HemisphereSampling;
import java.nio.file.Path;
import java.util.Objects;

/**
 * How to start the viewer.
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
 * @param photons      photons per iteration for the photon mapper
 * @param photonRadius the photon mapper's initial gather radius; 0 = automatic
 */
public record ViewerOptions(Path scene, int width, int height, int stopAt, int maxDepth, HemisphereSampling hemisphere,
                            int threads, long seed, IntegratorKind integrator, int lightSamples, Theme theme,
                            int photons, double photonRadius) {

    public ViewerOptions {
        if (stopAt < 0) {
            throw new IllegalArgumentException("stop-at samples per pixel must be >= 0 (0 = never stop), got " + stopAt);
        }
        Objects.requireNonNull(hemisphere, "hemisphere");
        Objects.requireNonNull(integrator, "integrator");
        Objects.requireNonNull(theme, "theme");
        renderSettings(width, height, maxDepth, hemisphere, threads, seed, integrator, lightSamples, photons, photonRadius);   // validates
    }

    /** Options with the photon mapper's default parameters. */
    public ViewerOptions(Path scene, int width, int height, int stopAt, int maxDepth, HemisphereSampling hemisphere,
                         int threads, long seed, IntegratorKind integrator, int lightSamples, Theme theme) {
        this(scene, width, height, stopAt, maxDepth, hemisphere, threads, seed, integrator, lightSamples, theme,
                PhotonParameters.DEFAULT_PHOTONS, 0);
    }

    /** The Cornell Box at 512×512, stopping at 1024 spp, unbounded depth, cosine sampling, all processors. */
    public static ViewerOptions defaults() {
        return new ViewerOptions(null, 512, 512, 1024, -1, HemisphereSampling.COSINE, 0, 0, IntegratorKind.PATH, 1, Theme.SYSTEM);
    }

    /** The render settings these options describe (validated by {@link RenderSettings}). */
    RenderSettings renderSettings() {
        return renderSettings(width, height, maxDepth, hemisphere, threads, seed, integrator, lightSamples, photons, photonRadius);
    }

    private static RenderSettings renderSettings(int width, int height, int maxDepth, HemisphereSampling hemisphere, int threads, long seed,
                                                 IntegratorKind integrator, int lightSamples, int photons, double photonRadius) {
        return RenderSettings.defaults().withSize(width, height).withMaxDepth(maxDepth).withHemisphere(hemisphere)
                .withThreads(threads).withSeed(seed).withIntegrator(integrator).withLightSamples(lightSamples).withSamplesPerPass(1)
                .withPhotons(photons).withPhotonRadius(photonRadius);
    }
}
