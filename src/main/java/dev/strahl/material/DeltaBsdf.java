package dev.strahl.material;

import dev.strahl.color.MutableRgb;
import org.joml.Vector2dc;
import org.joml.Vector3dc;

/**
 * A BSDF whose lobes are all Dirac deltas (perfect mirrors, smooth glass): for any two directions
 * a caller can name, f and the pdf are zero, so {@link #eval} and {@link #pdf} are zero here once
 * for all of them, and only {@link #sample} sees the lobes (its pdf is the probability of the lobe
 * it chose, pbrt-v4's convention for delta lobes).
 */
public sealed interface DeltaBsdf extends Bsdf permits Mirror, Dielectric, SmoothConductor, NullBsdf {

    /** Zero: a delta lobe has no value at directions chosen by someone else. */
    @Override
    default void eval(Vector2dc uv, Vector3dc wo, Vector3dc wi, MutableRgb dest) {
        dest.setZero();
    }

    /** Zero: a delta lobe has no density with respect to solid angle. */
    @Override
    default double pdf(Vector2dc uv, Vector3dc wo, Vector3dc wi) {
        return 0;
    }

    @Override
    default boolean isDelta() {
        return true;
    }
}
