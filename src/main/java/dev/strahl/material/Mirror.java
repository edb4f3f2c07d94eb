package dev.strahl.material;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import java.util.Objects;
import org.joml.Vector2dc;
import org.joml.Vector3dc;

/**
 * Perfect specular reflection (MTL {@code illum 5}): wi = (−wo.x, −wo.y, wo.z) with reflectance
 * Ks and no Fresnel term (F ≡ 1, as DESIGN.md §3 prescribes). The lobe is a Dirac delta,
 * f = Ks · δ(wi − wr) / |cosθi|, so {@link #eval} and {@link #pdf} are zero for every wi and only
 * {@link #sample} sees it: weight f·|cosθi|/pdf = Ks, pdf = 1 (the probability of choosing the
 * only lobe, pbrt-v4's convention for delta lobes). Two-sided: the integrator turns the frame to
 * the side of wo.
 *
 * @param reflectance Ks, each channel in [0, 1]
 */
public record Mirror(Rgb reflectance) implements DeltaBsdf {

    /**
     * Checks that the reflectance lies in [0, 1].
     *
     * @param reflectance Ks, each channel in [0, 1]
     */
    public Mirror {
        Objects.requireNonNull(reflectance, "reflectance");
        if (reflectance.r() < 0 || reflectance.g() < 0 || reflectance.b() < 0 || reflectance.max() > 1) {
            throw new IllegalArgumentException("mirror reflectance must lie in [0, 1], got " + reflectance);
        }
    }

    @Override
    public boolean sample(Vector2dc uv, Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        if (!out.reflectSpecularly(wo)) {
            return false;
        }
        out.weight.set(reflectance);
        return true;
    }

    /** Ks: the tint of everything seen in the mirror. */
    @Override
    public void albedo(Vector2dc uv, Vector3dc wo, MutableRgb dest) {
        dest.set(reflectance);
    }
}
