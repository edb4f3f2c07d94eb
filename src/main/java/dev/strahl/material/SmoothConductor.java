package dev.strahl.material;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import org.joml.Vector2dc;
import org.joml.Vector3dc;

/**
 * A polished metal: a perfect mirror whose reflectance is the exact conductor Fresnel term
 * F(cosθo) per channel ({@link Fresnel#conductor}), Mitsuba 3's {@code conductor}. The limit
 * α → 0 of {@link Conductor}. Two-sided.
 *
 * @param eta the real part of the complex index of refraction per channel, positive
 * @param k   the absorption coefficient per channel, ≥ 0
 */
public record SmoothConductor(Rgb eta, Rgb k) implements DeltaBsdf {

    /**
     * Checks the indices.
     *
     * @param eta real part per channel, positive and finite
     * @param k   imaginary part per channel, ≥ 0 and finite
     */
    public SmoothConductor {
        Conductor.checkIndex(eta, k);
    }

    @Override
    public boolean sample(Vector2dc uv, Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        if (!out.reflectSpecularly(wo)) {
            return false;
        }
        double c = wo.z();
        out.weight.set(Fresnel.conductor(c, eta.r(), k.r()), Fresnel.conductor(c, eta.g(), k.g()), Fresnel.conductor(c, eta.b(), k.b()));
        return true;
    }

    /** The tint of what is seen in it: the Fresnel reflectance at wo's angle. */
    @Override
    public void albedo(Vector2dc uv, Vector3dc wo, MutableRgb dest) {
        double c = Math.min(1, Math.abs(wo.z()));
        dest.set(Fresnel.conductor(c, eta.r(), k.r()), Fresnel.conductor(c, eta.g(), k.g()), Fresnel.conductor(c, eta.b(), k.b()));
    }
}
