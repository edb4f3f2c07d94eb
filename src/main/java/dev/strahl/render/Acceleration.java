package dev.strahl.render;

/**
 * How rays find the primitives they hit. {@link #BVH} is what strahl uses; {@link #NONE} is a
 * teaching option: it tests every ray against every primitive, the brute-force loop a first ray
 * tracer starts from, so that what the hierarchy buys can be measured on a real scene
 * (docs/experiments.md). It finds the same hits, many times slower.
 */
public enum Acceleration {
    /** The four-wide bounding volume hierarchy: the default. */
    BVH,
    /** Teaching option: no acceleration structure, every ray against every primitive. */
    NONE
}
