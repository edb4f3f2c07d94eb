package dev.strahl.integrator;

import dev.strahl.sampling.HemisphereSampling;
import dev.strahl.scene.Scene;
import java.util.Locale;

/** The integrators a user can choose by name, from the talk's progression. */
public enum IntegratorKind {
    /** Unbiased path tracing (NEE + MIS + Russian roulette): the converged global illumination. */
    PATH,
    /** Direct lighting only, MIS between light and BSDF sampling: equals PATH at max depth 2. */
    DIRECT,
    /** Recursive (Whitted) ray tracing: specular reflection and refraction, direct light with soft shadows, no indirect diffuse light. */
    WHITTED;

    /**
     * The name used on the command line and in scene files.
     *
     * @return the lower-case name, e.g. "path"
     */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * Creates the integrator.
     *
     * @param scene         the scene it renders
     * @param maxDepth      path segments including the camera segment; -1 for unbounded
     * @param hemisphere    how diffuse bounces are sampled
     * @param cullBackFaces whether camera and continuation rays skip back faces of closed meshes
     * @param lightSamples shadow rays per diffuse or glossy hit (DIRECT and WHITTED; PATH takes one)
     * @return the integrator (internal)
     */
    public Integrator create(Scene scene, int maxDepth, HemisphereSampling hemisphere, boolean cullBackFaces, int lightSamples) {
        return switch (this) {
            case PATH -> new PathTracer(scene, maxDepth, hemisphere, cullBackFaces, PathTracer.Strategy.MIS);
            case DIRECT -> new DirectLighting(scene, hemisphere, cullBackFaces, lightSamples);
            case WHITTED -> new Whitted(scene, maxDepth, cullBackFaces, lightSamples);
        };
    }
}
