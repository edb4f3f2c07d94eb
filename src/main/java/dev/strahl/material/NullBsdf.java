package dev.strahl.material;

import dev.strahl.color.MutableRgb;
import org.joml.Vector2dc;
import org.joml.Vector3dc;

/**
 * An invisible surface (Mitsuba 3's {@code null}): light passes through it unchanged, neither
 * reflected nor refracted. It exists to mark where a participating medium begins and ends (a fog
 * box, the bounds of a smoke grid). Its one lobe is the delta in the direction −wo with weight 1;
 * the volumetric path tracer steps through such surfaces without counting them as bounces, and its
 * shadow rays pass them. Not two-sided, so that the integrator keeps the geometric normal's side,
 * which tells inside from outside.
 */
public record NullBsdf() implements DeltaBsdf {

    @Override
    public boolean sample(Vector2dc uv, Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        out.wi.set(wo).negate();
        out.weight.set(1, 1, 1);
        out.pdf = 1;
        out.delta = true;
        out.eta = 1;
        return true;
    }

    @Override
    public boolean isTwoSided() {
        return false;
    }

    /** 1: what is seen through it is seen untinted. */
    @Override
    public void albedo(Vector2dc uv, Vector3dc wo, MutableRgb dest) {
        dest.set(1, 1, 1);
    }
}
