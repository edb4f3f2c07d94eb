package dev.strahl.medium;

import dev.strahl.math.Frame;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * The Henyey–Greenstein phase function (Henyey &amp; Greenstein 1941), as Mitsuba 3's {@code hg}:
 * p(θ) = (1 − g²) / (4π (1 + g² − 2g cosθ)^(3/2)), with θ the scattering angle (cosθ = −wo·wi,
 * see the package documentation) and g ∈ (−1, 1) the mean cosine of θ: g &gt; 0 scatters forwards
 * (fog, clouds), g &lt; 0 backwards, g = 0 is isotropic (1/4π). It integrates to 1 over the
 * sphere, and sampling follows it exactly, so the pdf is its value and the weight of a sample is 1.
 *
 * <p>Sampling inverts the cumulative distribution of cosθ (pbrt-v4 §11.3.1, Mitsuba's
 * {@code hg.cpp}): cosθ = (1 + g² − s²)/(2g) with s = (1 − g²)/(1 − g + 2gu) (see {@link #cosTheta}
 * for g near 0).
 */
public final class HenyeyGreenstein {
    /** Below this |g| the closed-form inverse cancels badly; its expansion to first order in g is used instead. */
    static final double SMALL_G = 1e-4;
    private static final double INV_4PI = 1 / (4 * Math.PI);

    private HenyeyGreenstein() {}

    /** p as a function of the cosine of the scattering angle θ (1: straight on). */
    public static double eval(double g, double cosTheta) {
        double denom = 1 + g * g - 2 * g * cosTheta;
        return INV_4PI * (1 - g * g) / (denom * Math.sqrt(denom));
    }

    /**
     * The density of scattering light that arrived travelling along −wo into wi (per steradian);
     * the value of the phase function, which sampling follows exactly.
     */
    public static double pdf(double g, Vector3dc wo, Vector3dc wi) {
        return eval(g, -wo.dot(wi));
    }

    /**
     * cosθ of a sample from the uniform number u: the inverse of the cumulative distribution of
     * cosθ, increasing in u (u = 0 gives −1, u → 1 gives 1). The closed form (1 + g² − s²)/(2g)
     * divides a difference of nearly equal numbers by 2g, which loses about 10⁻¹⁶/g of accuracy; for
     * |g| &lt; {@value #SMALL_G} the inverse of the distribution's first-order expansion,
     * F(μ) ≈ (1 + μ)/2 + (3g/4)(μ² − 1), is used instead: μ ≈ μ₀ + (3g/2)(1 − μ₀²) with μ₀ = 2u − 1,
     * off by O(g²) &lt; 10⁻⁷.
     */
    static double cosTheta(double g, double u) {
        if (Math.abs(g) < SMALL_G) {
            double mu = 2 * u - 1;
            return Math.max(-1, Math.min(1, mu + 1.5 * g * (1 - mu * mu)));
        }
        double s = (1 - g * g) / (1 - g + 2 * g * u);
        return Math.max(-1, Math.min(1, (1 + g * g - s * s) / (2 * g)));
    }

    /**
     * Samples wi for light that arrived travelling along −wo from the uniform numbers (u1, u2):
     * u1 chooses the scattering angle, u2 the azimuth about −wo. Writes wi (a unit vector) and
     * returns its density, {@link #pdf}; the sample's weight p/pdf is 1.
     *
     * @param frame scratch: set to the frame around −wo
     */
    public static double sample(double g, Vector3dc wo, double u1, double u2, Frame frame, Vector3d wi) {
        double cos = cosTheta(g, u1);
        double sin = Math.sqrt(Math.max(0, 1 - cos * cos));
        double phi = 2 * Math.PI * u2;
        frame.set(-wo.x(), -wo.y(), -wo.z());
        frame.toWorld(wi.set(sin * Math.cos(phi), sin * Math.sin(phi), cos), wi);
        return eval(g, cos);
    }
}
