package dev.strahl.material;

import dev.strahl.color.MutableRgb;
import dev.strahl.texture.TextureLookup;
import java.util.Objects;
import org.joml.Vector2dc;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Rough glass: GGX reflection and transmission at a rough dielectric interface (Walter et al.,
 * "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007), as Mitsuba 3's
 * {@code roughdielectric} with {@code distribution = ggx}; index η inside (the side z &lt; 0) and 1
 * outside, no absorption. Not two-sided, like {@link Dielectric}.
 *
 * <p>With η' = η if wo is outside and 1/η if inside (the relative index of the side of wi over that
 * of wo, for transmission), the generalised half vector is m = normalize(wo + η' wi) turned to +z
 * (m = normalize(wo + wi) for reflection), and a pair whose m lies behind wo or wi is 0. Then
 * (Walter et al. 2007, eqs. 20, 21; pbrt-v4 §9.7, {@code DielectricBxDF}):
 * <ul>
 *   <li>reflection: f = F(wo·m) D(m) G(wo, wi) / (4 |cosθo cosθi|);</li>
 *   <li>transmission: f = (1 − F(wo·m)) D(m) G(wo, wi) |wi·m| |wo·m| / (|cosθo cosθi| (wi·m + wo·m/η')²) / η'²,
 *       the last factor because strahl's paths carry radiance (see {@link Dielectric}).</li>
 * </ul>
 * F is the exact dielectric Fresnel term ({@link Fresnel#dielectric}), G the separable Smith term.
 *
 * <p><b>Sampling.</b> A visible normal m for wo ({@link Ggx#sampleVisible}); reflection about m with
 * probability F(wo·m) ({@code uc}), refraction through m otherwise. pdf: D_wo(m) F / (4 |wo·m|) for
 * reflection, D_wo(m) (1 − F) |wi·m| / (wi·m + wo·m/η')² for transmission (Walter et al. 2007,
 * eqs. 14, 17). A direction on the wrong side for its lobe is an absorbed sample.
 *
 * @param eta   index of refraction of the inside relative to the outside, positive
 * @param alpha GGX roughness α (a scalar texture), clamped below to {@link Ggx#MIN_ALPHA}
 */
public record RoughDielectric(double eta, TextureLookup alpha) implements Glass {

    /**
     * Checks the index and the roughness.
     *
     * @param eta   positive and finite
     * @param alpha GGX roughness
     */
    public RoughDielectric {
        if (!(eta > 0) || !Double.isFinite(eta)) {
            throw new IllegalArgumentException("index of refraction must be a positive finite number, got " + eta);
        }
        Objects.requireNonNull(alpha, "alpha");
        if (alpha.isConstant() && !(alpha.value(0, 0) >= 0 && Double.isFinite(alpha.value(0, 0)))) {
            throw new IllegalArgumentException("dielectric roughness alpha must be finite and >= 0, got " + alpha.value(0, 0));
        }
    }

    /** Smooth glass ({@link Dielectric}) if α is the constant 0, rough glass otherwise. */
    public static Bsdf of(double eta, TextureLookup alpha) {
        if (alpha.isConstant() && alpha.value(0, 0) == 0) {
            return new Dielectric(eta);
        }
        return new RoughDielectric(eta, alpha);
    }

    private double alphaAt(Vector2dc uv) {
        return Math.max(Ggx.MIN_ALPHA, alpha.value(uv.x(), uv.y()));
    }

    @Override
    public void eval(Vector2dc uv, Vector3dc wo, Vector3dc wi, MutableRgb dest) {
        double v = evalOrPdf(uv, wo, wi, false);
        dest.set(v, v, v);
    }

    @Override
    public double pdf(Vector2dc uv, Vector3dc wo, Vector3dc wi) {
        return evalOrPdf(uv, wo, wi, true);
    }

    /** f (or the pdf) of the pair: the set-up is shared. */
    private double evalOrPdf(Vector2dc uv, Vector3dc wo, Vector3dc wi, boolean wantPdf) {
        double cosO = wo.z(), cosI = wi.z();
        if (cosO == 0 || cosI == 0) {
            return 0;
        }
        boolean reflect = cosO * cosI > 0;
        double etaP = reflect ? 1 : cosO > 0 ? eta : 1 / eta;
        double mx = wo.x() + etaP * wi.x(), my = wo.y() + etaP * wi.y(), mz = wo.z() + etaP * wi.z();
        double len = Math.sqrt(mx * mx + my * my + mz * mz);
        if (!(len > 0)) {
            return 0;
        }
        double sign = mz < 0 ? -1 / len : 1 / len;
        mx *= sign;
        my *= sign;
        mz *= sign;
        double woDotM = wo.x() * mx + wo.y() * my + wo.z() * mz;
        double wiDotM = wi.x() * mx + wi.y() * my + wi.z() * mz;
        if (woDotM * cosO <= 0 || wiDotM * cosI <= 0) {
            return 0;                                  // m lies behind wo or wi
        }
        double a = alphaAt(uv);
        double fr = Fresnel.dielectric(woDotM, eta);
        if (wantPdf) {
            double visible = Ggx.visiblePdf(wo, mx, my, mz, a);
            if (reflect) {
                return visible * fr / (4 * Math.abs(woDotM));
            }
            double denom = wiDotM + woDotM / etaP;
            return visible * (1 - fr) * Math.abs(wiDotM) / (denom * denom);
        }
        double dg = Ggx.d(mz, a) * Ggx.g(wo, wi, a);
        if (reflect) {
            return fr * dg / (4 * Math.abs(cosO * cosI));
        }
        double denom = wiDotM + woDotM / etaP;
        return (1 - fr) * dg * Math.abs(wiDotM * woDotM / (cosO * cosI * denom * denom)) / (etaP * etaP);
    }

    @Override
    public boolean sample(Vector2dc uv, Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        if (wo.z() == 0) {
            return false;
        }
        double a = alphaAt(uv);
        Vector3d m = Ggx.sampleVisible(wo, a, u1, u2, out.wi);
        double mx = m.x, my = m.y, mz = m.z;
        double woDotM = wo.x() * mx + wo.y() * my + wo.z() * mz;
        double fr = Fresnel.dielectric(woDotM, eta);
        if (uc < fr) {
            out.wi.set(2 * woDotM * mx - wo.x(), 2 * woDotM * my - wo.y(), 2 * woDotM * mz - wo.z()).normalize();
            if (!(out.wi.z * wo.z() > 0)) {
                return false;
            }
            out.eta = 1;
        } else {
            if (Fresnel.refract(wo, mx, my, mz, eta, out.wi) == 0) {
                return false;                          // F = 1 there, so uc < F always held: cannot happen
            }
            out.wi.normalize();
            if (!(out.wi.z * wo.z() < 0)) {
                return false;
            }
            out.eta = Fresnel.relativeEta(wo.z(), eta);   // the roulette undoes the radiance's 1/η'² (BsdfSample.eta)
        }
        out.delta = false;
        return weighByPdf(uv, wo, out);
    }
}
