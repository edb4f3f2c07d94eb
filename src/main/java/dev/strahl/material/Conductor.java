package dev.strahl.material;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import dev.strahl.texture.TextureLookup;
import java.util.Map;
import java.util.Objects;
import org.joml.Vector2dc;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A rough metal: GGX microfacets ({@link Ggx}) with the exact conductor Fresnel term per RGB channel
 * ({@link Fresnel#conductor}), as Mitsuba 3's {@code roughconductor} with {@code distribution = ggx}
 * and sampling of visible normals:
 * f(wo, wi) = F(wo·h) D(h) G1(wo) G1(wi) / (4 cosθo cosθi), h = normalize(wo + wi), for wo and wi
 * above the surface (Walter et al. 2007, eq. 20); no transmission. Two-sided.
 *
 * <p><b>Sampling</b> draws a visible normal m for wo (Heitz 2018) and reflects wo about it:
 * pdf(wi) = D_wo(h) / (4 wo·h) (the Jacobian of the reflection, Walter et al. 2007 eq. 14), so the
 * weight f cosθi / pdf reduces to F(wo·m) G1(wi). A wi below the surface is an absorbed sample.
 *
 * <p><b>Presets</b> ({@link #PRESETS}): η and k of gold, silver, copper and aluminium as RGB, the
 * values Mitsuba 3 (3.x, {@code scalar_rgb} variant) uses for its {@code material} presets Au, Ag,
 * Cu and Al, which it derives from its tabulated spectral refractive indices; printed by
 * docs/anchors/conductor_presets.py.
 *
 * @param eta   the real part of the complex index of refraction per channel, positive
 * @param k     the absorption coefficient per channel, ≥ 0
 * @param alpha GGX roughness α (a scalar texture), clamped below to {@link Ggx#MIN_ALPHA}
 */
public record Conductor(Rgb eta, Rgb k, TextureLookup alpha) implements Bsdf {

    /** η and k of the named metals, as Mitsuba 3's scalar_rgb variant has them (see the class documentation). */
    public static final Map<String, Rgb[]> PRESETS = Map.of(
            "gold", new Rgb[] {new Rgb(0.143036, 0.375307, 1.44205), new Rgb(3.983, 2.38556, 1.60336)},
            "silver", new Rgb[] {new Rgb(0.155276, 0.116728, 0.138388), new Rgb(4.82835, 3.12222, 2.1469)},
            "copper", new Rgb[] {new Rgb(0.201005, 0.92375, 1.10222), new Rgb(3.91326, 2.45305, 2.14209)},
            "aluminium", new Rgb[] {new Rgb(1.6575, 0.880405, 0.521244), new Rgb(9.22381, 6.2695, 4.837)});

    /**
     * Checks the indices.
     *
     * @param eta   real part per channel, positive and finite
     * @param k     imaginary part per channel, ≥ 0 and finite
     * @param alpha GGX roughness
     */
    public Conductor {
        checkIndex(eta, k);
        Objects.requireNonNull(alpha, "alpha");
        if (alpha.isConstant() && !(alpha.value(0, 0) >= 0 && Double.isFinite(alpha.value(0, 0)))) {
            throw new IllegalArgumentException("conductor roughness alpha must be finite and >= 0, got " + alpha.value(0, 0));
        }
    }

    static void checkIndex(Rgb eta, Rgb k) {
        Objects.requireNonNull(eta, "eta");
        Objects.requireNonNull(k, "k");
        if (!(eta.r() > 0 && eta.g() > 0 && eta.b() > 0) || !Double.isFinite(eta.max())) {
            throw new IllegalArgumentException("conductor eta must be positive and finite in every channel, got " + eta);
        }
        if (!(k.r() >= 0 && k.g() >= 0 && k.b() >= 0) || !Double.isFinite(k.max())) {
            throw new IllegalArgumentException("conductor k must be >= 0 and finite in every channel, got " + k);
        }
    }

    /**
     * A conductor: smooth (a {@link SmoothConductor}, delta reflection) if α is the constant 0,
     * rough otherwise.
     */
    public static Bsdf of(Rgb eta, Rgb k, TextureLookup alpha) {
        if (alpha.isConstant() && alpha.value(0, 0) == 0) {
            return new SmoothConductor(eta, k);
        }
        return new Conductor(eta, k, alpha);
    }

    private double alphaAt(Vector2dc uv) {
        return Math.max(Ggx.MIN_ALPHA, alpha.value(uv.x(), uv.y()));
    }

    @Override
    public void eval(Vector2dc uv, Vector3dc wo, Vector3dc wi, MutableRgb dest) {
        if (!(wo.z() > 0) || !(wi.z() > 0)) {
            dest.setZero();
            return;
        }
        double hx = wo.x() + wi.x(), hy = wo.y() + wi.y(), hz = wo.z() + wi.z();
        double len = Math.sqrt(hx * hx + hy * hy + hz * hz);
        hx /= len;
        hy /= len;
        hz /= len;
        double a = alphaAt(uv);
        double value = Ggx.d(hz, a) * Ggx.g(wo, wi, a) / (4 * wo.z() * wi.z());
        fresnel(wo.x() * hx + wo.y() * hy + wo.z() * hz, dest).mul(value);
    }

    @Override
    public double pdf(Vector2dc uv, Vector3dc wo, Vector3dc wi) {
        if (!(wo.z() > 0) || !(wi.z() > 0)) {
            return 0;
        }
        double hx = wo.x() + wi.x(), hy = wo.y() + wi.y(), hz = wo.z() + wi.z();
        double len = Math.sqrt(hx * hx + hy * hy + hz * hz);
        hx /= len;
        hy /= len;
        hz /= len;
        double woDotH = wo.x() * hx + wo.y() * hy + wo.z() * hz;
        if (!(woDotH > 0)) {
            return 0;
        }
        return Ggx.visiblePdf(wo, hx, hy, hz, alphaAt(uv)) / (4 * woDotH);
    }

    @Override
    public boolean sample(Vector2dc uv, Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        if (!(wo.z() > 0)) {
            return false;
        }
        double a = alphaAt(uv);
        Vector3d m = Ggx.sampleVisible(wo, a, u1, u2, out.wi);
        double mx = m.x, my = m.y, mz = m.z;
        double woDotM = wo.x() * mx + wo.y() * my + wo.z() * mz;
        if (!(woDotM > 0)) {
            return false;
        }
        out.wi.set(2 * woDotM * mx - wo.x(), 2 * woDotM * my - wo.y(), 2 * woDotM * mz - wo.z()).normalize();
        if (!(out.wi.z > 0)) {
            return false;
        }
        out.delta = false;
        out.eta = 1;
        out.pdf = Ggx.visiblePdf(wo, mx, my, mz, a) / (4 * woDotM);
        if (!(out.pdf > 0) || !Double.isFinite(out.pdf)) {
            return false;
        }
        fresnel(woDotM, out.weight).mul(Ggx.g1(out.wi, a));
        return true;
    }

    /** F(cosθ) per channel into {@code dest}. */
    private MutableRgb fresnel(double cosTheta, MutableRgb dest) {
        return dest.set(Fresnel.conductor(cosTheta, eta.r(), k.r()), Fresnel.conductor(cosTheta, eta.g(), k.g()),
                Fresnel.conductor(cosTheta, eta.b(), k.b()));
    }

    /** The Fresnel reflectance at wo's angle (what a smooth conductor reflects; roughness loses a little more). */
    @Override
    public void albedo(Vector2dc uv, Vector3dc wo, MutableRgb dest) {
        fresnel(Math.min(1, Math.abs(wo.z())), dest);
    }
}
