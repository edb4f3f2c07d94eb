package dev.strahl.material;

import dev.strahl.color.MutableRgb;
import dev.strahl.image.Rgb;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/** The result of sampling a BSDF; mutable, reused per thread. */
public final class BsdfSample {
    /** Creates a sample for a BSDF to fill in. */
    public BsdfSample() {}

    /** Sampled direction in the local frame. */
    public final Vector3d wi = new Vector3d();
    /** f(wo, wi)·|cosθi| / pdf. */
    public final MutableRgb weight = new MutableRgb();
    /** Solid-angle density of wi; for a delta lobe the probability of choosing that lobe. */
    public double pdf;
    /** Whether wi comes from a delta (perfectly specular) lobe, for which eval and pdf are zero. */
    public boolean delta;
    /**
     * Relative index of refraction η' = ηt/ηi of the interface crossing when wi is a refraction, 1
     * otherwise. The weight of a refraction carries the radiance scaling 1/η'²; a path tracer
     * multiplies η'² back for its Russian roulette test (pbrt-v4's etaScale), so that paths inside
     * a dense medium are not killed for a factor that leaving it undoes.
     */
    public double eta = 1;

    /**
     * The perfect mirror direction of {@code wo} (a delta lobe chosen for sure: pdf 1, η' 1), for
     * a BSDF that sets the weight; false below the surface, where a mirror reflects nothing.
     *
     * @param wo the outgoing direction in the local frame
     * @return whether there is a reflection
     */
    public boolean reflectSpecularly(Vector3dc wo) {
        if (wo.z() <= 0) {
            return false;
        }
        Fresnel.reflect(wo, wi);
        pdf = 1;
        delta = true;
        eta = 1;
        return true;
    }
}
