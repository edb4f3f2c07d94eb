package dev.strahl.scene;

import dev.strahl.sampling.HemisphereSampling;

/**
 * How a scene file asks to be rendered: its {@code film} and {@code integrator} keys. Every field
 * is null where the file says nothing; {@code RenderSettings.withScene} applies the others, and a
 * command-line option overrides them. The integrator is kept by name, because the scene layer
 * sits below the integrators; an unknown name is refused when the settings are applied.
 *
 * @param width           film width in pixels, or null
 * @param height          film height in pixels, or null
 * @param samplesPerPixel samples per pixel, or null
 * @param maxDepth        path segments including the camera segment (-1 unbounded), or null
 * @param seed            the random seed, or null
 * @param integrator      the integrator's name ("path", "direct", "whitted", ...), or null
 * @param lightSamples    shadow rays per hit for the direct and Whitted integrators, or null
 * @param hemisphere      how diffuse bounces are sampled, or null
 */
public record SceneSettings(Integer width, Integer height, Integer samplesPerPixel, Integer maxDepth, Long seed,
                            String integrator, Integer lightSamples, HemisphereSampling hemisphere) {

    /** Settings that say nothing (a scene built in code, an OBJ, a PLY). */
    public static final SceneSettings NONE = new SceneSettings(null, null, null, null, null, null, null, null);

    /**
     * Whether no field is given.
     *
     * @return true if every field is null
     */
    public boolean isEmpty() {
        return equals(NONE);
    }
}
