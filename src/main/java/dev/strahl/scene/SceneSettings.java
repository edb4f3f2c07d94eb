package dev.strahl.scene;

import dev.strahl.sampling.HemisphereSampling;

/**
 * How a scene file asks to be rendered: its {@code film} and {@code integrator} keys. Every field
 * is null where the file says nothing; {@code RenderSettings.withScene} applies the others, and
 * {@code RenderSettings.withSceneFile} does so except for the {@link Setting}s given on a command
 * line, which win. The integrator is kept by name, because the scene layer sits below the
 * integrators; the scene file reader refuses an unknown name at its line, and settings made in
 * code with one are refused when they are applied.
 *
 * @param width           film width in pixels, or null
 * @param height          film height in pixels, or null
 * @param samplesPerPixel samples per pixel, or null
 * @param maxDepth        path segments including the camera segment (-1 unbounded), or null
 * @param seed            the random seed, or null
 * @param integrator      the integrator's name ("path", "direct", "whitted", ...), or null
 * @param lightSamples    shadow rays per hit for the direct and Whitted integrators, or null
 * @param hemisphere      how diffuse bounces are sampled, or null
 * @param photons         photons per iteration for the photon mapper, or null
 * @param photonRadius    the photon mapper's initial gather radius in scene units (0 = automatic), or null
 */
public record SceneSettings(Integer width, Integer height, Integer samplesPerPixel, Integer maxDepth, Long seed,
                            String integrator, Integer lightSamples, HemisphereSampling hemisphere,
                            Integer photons, Double photonRadius) {

    /**
     * The settings a scene file can give, one per field. A command line names the ones it gives
     * itself, so that the file's value of those is not used.
     */
    public enum Setting {
        /** {@code film.width} */
        WIDTH,
        /** {@code film.height} */
        HEIGHT,
        /** {@code integrator.spp} */
        SAMPLES_PER_PIXEL,
        /** {@code integrator.maxDepth} */
        MAX_DEPTH,
        /** {@code integrator.seed} */
        SEED,
        /** {@code integrator.type} */
        INTEGRATOR,
        /** {@code integrator.lightSamples} */
        LIGHT_SAMPLES,
        /** {@code integrator.hemisphere} */
        HEMISPHERE,
        /** {@code integrator.photons} */
        PHOTONS,
        /** {@code integrator.photonRadius} */
        PHOTON_RADIUS
    }

    /** Settings that say nothing (a scene built in code, an OBJ, a PLY). */
    public static final SceneSettings NONE = new SceneSettings(null, null, null, null, null, null, null, null, null, null);

    /**
     * Settings that say nothing about the photon mapper's parameters.
     *
     * @param width           film width in pixels, or null
     * @param height          film height in pixels, or null
     * @param samplesPerPixel samples per pixel, or null
     * @param maxDepth        path segments including the camera segment (-1 unbounded), or null
     * @param seed            the random seed, or null
     * @param integrator      the integrator's name, or null
     * @param lightSamples    shadow rays per hit for the direct and Whitted integrators, or null
     * @param hemisphere      how diffuse bounces are sampled, or null
     */
    public SceneSettings(Integer width, Integer height, Integer samplesPerPixel, Integer maxDepth, Long seed,
                         String integrator, Integer lightSamples, HemisphereSampling hemisphere) {
        this(width, height, samplesPerPixel, maxDepth, seed, integrator, lightSamples, hemisphere, null, null);
    }

    /**
     * Whether no field is given.
     *
     * @return true if every field is null
     */
    public boolean isEmpty() {
        return equals(NONE);
    }
}
