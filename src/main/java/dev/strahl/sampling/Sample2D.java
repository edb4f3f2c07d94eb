package dev.strahl.sampling;

/**
 * Two uniform numbers in [0, 1) from one {@link Sampler#get2D} or {@link Sampler#getPixel2D}
 * call, written into a holder the caller owns (JOML's {@code dest} style). Mutable; each worker
 * owns its holders and reuses them for every sample, so that drawing a pair allocates nothing.
 */
public final class Sample2D {
    /** The first number of the pair (x of the stratified point). */
    public double u1;
    /** The second number of the pair (y of the stratified point). */
    public double u2;

    /** A holder for a sampler to fill in. */
    public Sample2D() {}

    @Override
    public String toString() {
        return "(" + u1 + ", " + u2 + ")";
    }
}
