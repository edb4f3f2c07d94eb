package dev.strahl.material;

import org.joml.Vector2dc;
import org.joml.Vector3dc;

/**
 * A smooth dielectric interface (MTL {@code illum 7}, glass): index of refraction {@code eta}
 * inside (the side z &lt; 0 of the local frame) and 1 outside, exact unpolarised Fresnel
 * reflectance ({@link Fresnel#dielectric}), no absorption. Both lobes are Dirac deltas, so
 * {@link #eval} and {@link #pdf} are zero and only {@link #sample} sees them.
 *
 * <p><b>Sides.</b> Not two-sided: the integrator keeps the frame of the shading normal, so
 * wo.z &gt; 0 means wo is outside and wo.z &lt; 0 that the path is inside the glass; there the
 * relative index is 1/η and rays beyond the critical angle are totally reflected.
 *
 * <p><b>Sampling</b> (pbrt-v4 §9.5, {@code DielectricBxDF::Sample_f}, specular case). With
 * F = F(cosθo, η), reflection wi = (−wo.x, −wo.y, wo.z) is chosen with probability F
 * ({@code uc < F}) and refraction by Snell's law ({@link Fresnel#refract}) with probability
 * 1 − F. The recorded pdf is that probability. Weights f·|cosθi|/pdf:
 * <ul>
 *   <li>reflection: F / F = 1;</li>
 *   <li>transmission: (1 − F) / (1 − F) / η'² = 1/η'², with η' = ηt/ηi of the crossing
 *       (η entering, 1/η leaving).</li>
 * </ul>
 * The 1/η'² factor is there because strahl's camera paths carry radiance, and radiance divided by
 * η² is what is conserved across a refracting interface (pbrt-v4 §9.5, TransportMode::Radiance;
 * Veach 1997, ch. 5). A path that enters and leaves the glass picks up η⁻² and η², so the factor
 * cancels for light that ends up outside; it matters for paths that end inside. Without it the
 * expected weight is F + (1 − F) = 1: the interface neither creates nor absorbs energy.
 *
 * @param eta index of refraction of the inside relative to the outside, positive
 */
public record Dielectric(double eta) implements DeltaBsdf, Glass {

    /**
     * Checks that eta is positive and finite.
     *
     * @param eta index of refraction of the inside relative to the outside, positive
     */
    public Dielectric {
        if (!(eta > 0) || !Double.isFinite(eta)) {
            throw new IllegalArgumentException("index of refraction must be a positive finite number, got " + eta);
        }
    }

    @Override
    public boolean sample(Vector2dc uv, Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        double reflectance = Fresnel.dielectric(wo.z(), eta);
        out.delta = true;
        if (uc < reflectance || !Fresnel.refract(wo, eta, out.wi)) {
            // uc < F always holds on total internal reflection (F = 1); refract fails only there.
            Fresnel.reflect(wo, out.wi);
            out.weight.set(1, 1, 1);
            out.pdf = reflectance;
            out.eta = 1;
            return true;
        }
        double etaRelative = Fresnel.relativeEta(wo.z(), eta);
        double scale = 1 / (etaRelative * etaRelative);
        out.weight.set(scale, scale, scale);
        out.pdf = 1 - reflectance;
        out.eta = etaRelative;
        return true;
    }
}
