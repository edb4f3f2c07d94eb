package dev.strahl.material;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import dev.strahl.sampling.Warp;
import java.util.Objects;
import org.joml.Vector2dc;
import org.joml.Vector3dc;

/**
 * A diffuse base with a rough mirror on top (MTL {@code illum 2} with Ks &gt; 0, DESIGN.md §3):
 * f = Kd/π + Ks · D(h) G(wo, wi) / (4 cosθo cosθi), h = normalize(wo + wi), for wo and wi both
 * above the surface (zero otherwise; no transmission). The Fresnel factor of the microfacet
 * mirror is 1. Two-sided: the integrator turns the frame to the side of wo.
 *
 * <ul>
 *   <li><b>D</b> is Beckmann's distribution of microfacet normals,
 *       D(m) = exp(−tan²θm/α²) / (π α² cos⁴θm), normalised so that ∫ D(m) cosθm dωm = 1
 *       (Walter et al., "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007;
 *       pbrt-v3 §8.4.2).</li>
 *   <li><b>G</b> is Smith's separable masking–shadowing G = G1(wo) G1(wi) with Beckmann's exact
 *       G1(v) = 2 / (1 + erf(a) + exp(−a²)/(a√π)), a = 1/(α tanθv) (Walter et al. 2007;
 *       equivalently 1/(1 + Λ(v)), pbrt-v3 §8.4.3). The exact erf form, not Walter's rational
 *       approximation (which Mitsuba 3 uses, relative error &lt; 0.35 %), so that the BSDF is
 *       the textbook one to machine precision; {@link #erfc} has an absolute error below 1e-15.</li>
 *   <li><b>α from the Phong exponent</b> Ns: α = sqrt(2 / (Ns + 2)), the inverse of Walter et
 *       al.'s (2007) correspondence Ns = 2 α⁻² − 2 between a normalised Phong lobe and a
 *       Beckmann distribution of the same width; see {@link #fromPhongExponent}.</li>
 * </ul>
 *
 * <p><b>Sampling.</b> The diffuse lobe is chosen with probability mean(Kd) / (mean(Kd) +
 * mean(Ks)) (in proportion to the lobes' albedos, up to masking), the specular lobe otherwise,
 * using {@code uc}. The diffuse lobe samples the cosine-weighted (default) or the uniform
 * hemisphere. The specular lobe samples the distribution of normals, D(m) cosθm
 * (tan²θm = −α² ln(1 − u1), φm = 2π u2; Walter et al. 2007), and reflects wo about m:
 * wi = 2 (wo·m) m − wo, whose density is D(m) cosθm / (4 |wo·m|) (1/(4 |wo·m|) is the Jacobian
 * of the reflection; Walter et al. 2007, pbrt-v3 §14.1.1); a wi below the surface is an
 * absorbed sample. This is simpler than sampling the visible normals (Heitz &amp; d'Eon 2014, which for Beckmann
 * needs an inverse erf) at the price of more variance at grazing wo. {@link #pdf} is the mixture of both
 * lobes' densities and the sample weight is f·cosθi / pdf of that mixture.
 *
 * @param diffuse     Kd, the diffuse albedo, channels ≥ 0
 * @param specular    Ks, the reflectance of the microfacet mirror, channels ≥ 0; every channel of
 *                    Kd + Ks at most 1
 * @param alpha       Beckmann roughness α &gt; 0, the root-mean-square slope of the microfacets
 * @param uniform     the diffuse lobe samples directions uniformly rather than cosine-weighted
 */
public record Glossy(Rgb diffuse, Rgb specular, double alpha, boolean uniform) implements Bsdf {
    private static final double INV_PI = 1 / Math.PI;
    private static final double INV_SQRT_PI = 1 / Math.sqrt(Math.PI);
    /** Kd + Ks may exceed 1 by this much, the round-off of the normalisation in the factory. */
    private static final double ENERGY_TOLERANCE = 1e-9;

    /**
     * Checks the colours (energy conservation) and the roughness.
     *
     * @param diffuse  Kd, the diffuse albedo, channels ≥ 0
     * @param specular Ks, the reflectance of the microfacet mirror, channels ≥ 0; every channel of Kd + Ks at most 1
     * @param alpha    Beckmann roughness α &gt; 0, the root-mean-square slope of the microfacets
     * @param uniform  the diffuse lobe samples uniformly rather than cosine-weighted
     */
    public Glossy {
        Objects.requireNonNull(diffuse, "diffuse");
        Objects.requireNonNull(specular, "specular");
        if (diffuse.r() < 0 || diffuse.g() < 0 || diffuse.b() < 0 || specular.r() < 0 || specular.g() < 0 || specular.b() < 0) {
            throw new IllegalArgumentException("Kd and Ks must not be negative, got Kd " + diffuse + ", Ks " + specular);
        }
        if (maxSum(diffuse, specular) > 1 + ENERGY_TOLERANCE) {
            throw new IllegalArgumentException("Kd + Ks must not exceed 1 in any channel (energy conservation), got Kd "
                    + diffuse + ", Ks " + specular + "; use Glossy.fromPhongExponent to normalise");
        }
        if (!(alpha > 0) || !Double.isFinite(alpha)) {
            throw new IllegalArgumentException("Beckmann roughness alpha must be positive and finite, got " + alpha);
        }
    }

    /**
     * The BSDF of an MTL material with diffuse Kd, specular Ks and Phong exponent Ns, as DESIGN.md
     * §3 maps it: α = sqrt(2 / (Ns + 2)) (Ns = 10 → α ≈ 0.408, 100 → 0.140, 1000 → 0.0447), and
     * if m = max over channels of (Kd + Ks) exceeds 1, both Kd and Ks are divided by m, so the
     * albedo never exceeds 1 while the ratio of the colours is kept. Cosine-weighted diffuse
     * sampling.
     *
     * @param kd diffuse Kd, channels ≥ 0
     * @param ks specular Ks, channels ≥ 0
     * @param ns Phong exponent, ≥ 0
     * @return the BSDF
     */
    public static Glossy fromPhongExponent(Rgb kd, Rgb ks, double ns) {
        if (!(ns >= 0) || !Double.isFinite(ns)) {
            throw new IllegalArgumentException("Phong exponent Ns must be a finite number >= 0, got " + ns);
        }
        double max = maxSum(kd, ks);
        if (max > 1) {
            kd = kd.scale(1 / max);
            ks = ks.scale(1 / max);
        }
        return new Glossy(kd, ks, alphaFromPhongExponent(ns), false);
    }

    /**
     * Beckmann α for a Phong exponent: α = sqrt(2 / (Ns + 2)) (Walter et al. 2007).
     *
     * @param ns Phong exponent, ≥ 0
     * @return α
     */
    public static double alphaFromPhongExponent(double ns) {
        return Math.sqrt(2 / (ns + 2));
    }

    @Override
    public void eval(Vector2dc uv, Vector3dc wo, Vector3dc wi, MutableRgb dest) {
        if (wo.z() <= 0 || wi.z() <= 0) {
            dest.setZero();
            return;
        }
        double spec = specularValue(wo, wi);
        dest.set(diffuse.r() * INV_PI + specular.r() * spec,
                diffuse.g() * INV_PI + specular.g() * spec,
                diffuse.b() * INV_PI + specular.b() * spec);
    }

    @Override
    public double pdf(Vector2dc uv, Vector3dc wo, Vector3dc wi) {
        if (wo.z() <= 0 || wi.z() <= 0 || isBlack()) {
            return 0;
        }
        double pSpecular = specularProbability();
        return (1 - pSpecular) * diffusePdf(wi.z()) + pSpecular * specularPdf(wo, wi);
    }

    @Override
    public boolean sample(Vector2dc uv, Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        if (wo.z() <= 0 || isBlack()) {
            return false;
        }
        double pSpecular = specularProbability();
        if (uc < pSpecular) {
            // Microfacet normal m from D(m) cosθm, then wi = 2 (wo·m) m − wo.
            double tan2Theta = -alpha * alpha * Math.log1p(-u1);
            double cosTheta = 1 / Math.sqrt(1 + tan2Theta);
            double sinTheta = Math.sqrt(tan2Theta) * cosTheta;
            double phi = 2 * Math.PI * u2;
            double mx = sinTheta * Math.cos(phi), my = sinTheta * Math.sin(phi), mz = cosTheta;
            double twoDot = 2 * (wo.x() * mx + wo.y() * my + wo.z() * mz);
            out.wi.set(twoDot * mx - wo.x(), twoDot * my - wo.y(), twoDot * mz - wo.z()).normalize();
            if (!(out.wi.z > 0)) {
                return false;
            }
        } else if (!uniform) {
            Warp.cosineHemisphere(u1, u2, out.wi);
        } else {
            Warp.uniformHemisphere(u1, u2, out.wi);
        }
        out.delta = false;
        out.eta = 1;
        out.pdf = pdf(uv, wo, out.wi);
        if (!(out.pdf > 0)) {
            return false;
        }
        eval(uv, wo, out.wi, out.weight);
        out.weight.mul(out.wi.z / out.pdf);
        return true;
    }

    @Override
    public Bsdf withUniformHemisphere(boolean u) {
        return u == uniform ? this : new Glossy(diffuse, specular, alpha, u);
    }

    // ------------------------------------------------------------------------------------------
    // The two lobes

    /** Kd = Ks = 0: every sample is absorbed. */
    private boolean isBlack() {
        return diffuse.isBlack() && specular.isBlack();
    }

    /** Probability of sampling the specular lobe: mean(Ks) / (mean(Kd) + mean(Ks)); callers rule out {@link #isBlack}. */
    private double specularProbability() {
        double s = specular.r() + specular.g() + specular.b();
        return s / (s + diffuse.r() + diffuse.g() + diffuse.b());
    }

    private double diffusePdf(double cosThetaI) {
        return uniform ? Warp.uniformHemispherePdf(cosThetaI) : Warp.cosineHemispherePdf(cosThetaI);
    }

    /** D(h) G1(wo) G1(wi) / (4 cosθo cosθi) for wo, wi above the surface (Walter et al. 2007 and pbrt-v3 §8.4.4, with F = 1). */
    private double specularValue(Vector3dc wo, Vector3dc wi) {
        double hx = wo.x() + wi.x(), hy = wo.y() + wi.y(), hz = wo.z() + wi.z();
        double d = beckmannD(hx, hy, hz, alpha);
        if (d == 0) {
            return 0;
        }
        return d * smithG1(wo, alpha) * smithG1(wi, alpha) / (4 * wo.z() * wi.z());
    }

    /** Density of wi under specular sampling: D(h) cosθh / (4 (wo·h)) (pbrt-v3 §14.1.1). */
    private double specularPdf(Vector3dc wo, Vector3dc wi) {
        double hx = wo.x() + wi.x(), hy = wo.y() + wi.y(), hz = wo.z() + wi.z();
        double length = Math.sqrt(hx * hx + hy * hy + hz * hz);
        if (!(length > 0)) {
            return 0;
        }
        double cosThetaH = hz / length;
        double woDotH = (wo.x() * hx + wo.y() * hy + wo.z() * hz) / length;
        if (!(woDotH > 0)) {
            return 0;
        }
        return beckmannD(hx, hy, hz, alpha) * cosThetaH / (4 * woDotH);
    }

    // ------------------------------------------------------------------------------------------
    // Beckmann microfacet functions (package-private for the tests)

    /**
     * Beckmann's D(m) = exp(−tan²θm/α²) / (π α² cos⁴θm) for the direction of (mx, my, mz), which
     * need not be normalised; zero for mz ≤ 0 (Walter et al. 2007; pbrt-v3 §8.4.2).
     */
    static double beckmannD(double mx, double my, double mz, double alpha) {
        if (!(mz > 0)) {
            return 0;
        }
        double z2 = mz * mz;
        double xy2 = mx * mx + my * my;
        double len2 = z2 + xy2;
        double tan2Theta = xy2 / z2;
        double cos4Theta = (z2 / len2) * (z2 / len2);
        double alpha2 = alpha * alpha;
        return Math.exp(-tan2Theta / alpha2) / (Math.PI * alpha2 * cos4Theta);
    }

    /**
     * Smith's masking function for Beckmann microfacets, exact form (Walter et al. 2007; pbrt-v3 §8.4.3):
     * G1(v) = 2 / (1 + erf(a) + exp(−a²)/(a√π)), a = 1/(α tanθv) = cosθv / (α sinθv), with
     * 1 + erf(a) = 2 − erfc(a) to keep precision for large a. For a &gt; 6 the deficit 1 − G1 is
     * below 1e-17 and G1 = 1 is returned. Zero for v at or below the horizon. The
     * side condition χ⁺(v·m / v·n) holds for every v and h that {@link #specularValue} sees.
     */
    static double smithG1(Vector3dc v, double alpha) {
        double cosTheta = v.z();
        if (!(cosTheta > 0)) {
            return 0;
        }
        double sinTheta = Math.sqrt(v.x() * v.x() + v.y() * v.y());
        double a = cosTheta / (alpha * sinTheta);      // +∞ at normal incidence
        if (a > 6) {
            return 1;
        }
        return 2 / (2 - erfc(a) + Math.exp(-a * a) * INV_SQRT_PI / a);
    }

    /**
     * The complementary error function erfc(x) = 1 − erf(x), absolute error below 1e-15 and
     * relative error below 2e-13 (measured against 40-digit values on a grid over [−6, 6]; the
     * tests check known values). For 0 ≤ x &lt; 2 it is 1 − erf(x) with erf from the series of positive terms
     * erf(x) = (2/√π) e^{−x²} Σₙ 2ⁿ x^{2n+1} / (1·3·5···(2n+1)) (Abramowitz &amp; Stegun 7.1.6),
     * which has no cancellation; for x ≥ 2 the continued fraction
     * erfc(x) = (e^{−x²}/√π) / (x + (1/2)/(x + 1/(x + (3/2)/(x + 2/(x + …))))) (A&amp;S 7.1.14),
     * evaluated bottom-up with 60 terms (converged to round-off for x ≥ 2). erfc(−x) = 2 − erfc(x).
     * Both use e^{−x²} with x² split exactly ({@code expMinusSquare}).
     */
    static double erfc(double x) {
        if (x < 0) {
            return 2 - erfc(-x);
        }
        if (x < 2) {
            return 1 - erfSeries(x);
        }
        if (x > 27) {
            return 0;                                  // below the smallest double
        }
        double t = x;
        for (int k = 60; k >= 1; k--) {
            t = x + 0.5 * k / t;
        }
        return expMinusSquare(x) * INV_SQRT_PI / t;
    }

    /**
     * e^{−x²} without the rounding error of x² (which e^{−x²} would magnify by x²): x² = hi + lo
     * exactly (lo by a fused multiply-add), e^{−x²} = e^{−hi} (1 − lo).
     */
    private static double expMinusSquare(double x) {
        double hi = x * x;
        double lo = Math.fma(x, x, -hi);
        return Math.exp(-hi) * (1 - lo);
    }

    /** The error function; see {@link #erfc} for the method. */
    static double erf(double x) {
        if (x < 0) {
            return -erf(-x);
        }
        return x < 2 ? erfSeries(x) : 1 - erfc(x);
    }

    /** erf(x) for 0 ≤ x &lt; 2 by A&amp;S 7.1.6 (at most ~35 terms). */
    private static double erfSeries(double x) {
        double x2 = x * x;
        double term = x;
        double sum = x;
        for (int n = 1; term > 1e-17 * sum; n++) {
            term *= 2 * x2 / (2 * n + 1);
            sum += term;
        }
        return 2 * INV_SQRT_PI * expMinusSquare(x) * sum;
    }

    private static double maxSum(Rgb a, Rgb b) {
        return Math.max(a.r() + b.r(), Math.max(a.g() + b.g(), a.b() + b.b()));
    }

    /**
     * Kd + Ks: the diffuse lobe's directional albedo is exactly Kd; the microfacet mirror's is Ks
     * less what masking and the lobe's part below the horizon lose (a few percent but at grazing
     * angles), so Kd + Ks is the colour of the surface as its highlights show it.
     */
    @Override
    public void albedo(Vector2dc uv, Vector3dc wo, MutableRgb dest) {
        dest.set(diffuse.r() + specular.r(), diffuse.g() + specular.g(), diffuse.b() + specular.b());
    }
}
