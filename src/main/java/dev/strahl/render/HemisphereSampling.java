package dev.strahl.render;

/**
 * How diffuse lobes pick directions. Both converge to the same image; cosine sampling follows the
 * cosine factor of the rendering equation and so is less noisy, uniform sampling is kept to
 * show that difference.
 */
public enum HemisphereSampling {
    /** pdf = cosθ/π (Malley's method): the default. */
    COSINE,
    /** pdf = 1/(2π): noisier, for comparison. */
    UNIFORM
}
