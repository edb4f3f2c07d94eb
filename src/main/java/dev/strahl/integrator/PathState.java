package dev.strahl.integrator;

import dev.strahl.color.MutableRgb;
import org.joml.Vector3d;

/** What a path carries from one vertex to the next: its throughput and what its last BSDF sample was. */
final class PathState {
    /** The throughput: the product of the BSDF weights (and roulette's 1/q) so far. */
    final MutableRgb beta = new MutableRgb();
    /** The pdf of the last BSDF sample (for the MIS weight of what it reaches). */
    double prevPdf;
    /** Whether the last bounce was specular, or there was none yet: emission it reaches counts fully. */
    boolean prevDelta;
    /** Where the last BSDF sample left from, and the shading normal there: the light sampler's choice at that point (for the MIS weight). */
    final Vector3d prevP = new Vector3d(), prevN = new Vector3d();
    /** The product of η'² over the refractions so far (for the roulette). */
    double etaScale;
    /** The vertex the path reaches next, from 1 (the camera ray's hit). */
    int depth;

    /** A camera path, before its first hit. */
    void start() {
        beta.set(1, 1, 1);
        prevPdf = 0;
        prevDelta = true;
        etaScale = 1;
        depth = 1;
    }
}
