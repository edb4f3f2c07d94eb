package dev.strahl.render;

import java.util.Arrays;
import java.util.Locale;

/** The integrators a user can choose by name, from the talk's progression. */
public enum IntegratorKind {
    /** Unbiased path tracing (NEE + MIS + Russian roulette): the converged global illumination. */
    PATH,
    /** Direct lighting only, MIS between light and BSDF sampling: equals PATH at max depth 2. */
    DIRECT,
    /** Recursive (Whitted) ray tracing: specular reflection and refraction, direct light with soft shadows, no indirect diffuse light. */
    WHITTED,
    /** Progressive photon mapping (PPPM): clean caustics early; consistent, converges to PATH as iterations grow. */
    PHOTON;

    /**
     * The name used on the command line and in scene files.
     *
     * @return the lower-case name, e.g. "path"
     */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * The integrator of a name as used on the command line and in scene files.
     *
     * @param name "path", "direct", "whitted" or "photon"
     * @return the integrator kind
     * @throws IllegalArgumentException for an unknown name; the message lists the known ones
     */
    public static IntegratorKind named(String name) {
        for (IntegratorKind k : values()) {
            if (k.id().equals(name)) {
                return k;
            }
        }
        throw new IllegalArgumentException("unknown integrator '" + name + "' (known: "
                + String.join(", ", Arrays.stream(values()).map(IntegratorKind::id).toList()) + ")");
    }
}
