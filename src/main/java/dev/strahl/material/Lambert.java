package dev.strahl.material;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import dev.strahl.sampling.Warp;
import dev.strahl.texture.TextureLookup;
import java.util.Objects;
import org.joml.Vector2dc;
import org.joml.Vector3dc;

/**
 * Lambertian diffuse reflection: f = albedo(uv) / π on the side of wo, zero for transmission.
 * Sampled cosine-weighted (pdf = cosθ/π, weight = albedo) or uniformly (pdf = 1/(2π),
 * weight = 2·albedo·cosθ). The albedo may be an image (Mitsuba's {@code diffuse} with a
 * {@code bitmap} reflectance).
 *
 * @param albedo   reflectance, each channel in [0, 1]
 * @param uniform  sample directions uniformly over the hemisphere rather than cosine-weighted
 */
public record Lambert(TextureLookup albedo, boolean uniform) implements Bsdf {
    private static final double INV_PI = 1 / Math.PI;

    /**
     * Checks that a constant albedo lies in [0, 1] (an image's texels are colours decoded from
     * [0, 1], or linear values that the texture's reader checked).
     *
     * @param albedo   reflectance, each channel in [0, 1]
     * @param uniform  sample directions uniformly rather than cosine-weighted
     */
    public Lambert {
        Objects.requireNonNull(albedo, "albedo");
        Rgb a = albedo.mean();
        if (albedo.isConstant() && (a.r() < 0 || a.g() < 0 || a.b() < 0 || a.max() > 1)) {
            throw new IllegalArgumentException("diffuse albedo must lie in [0, 1], got " + a);
        }
    }

    /**
     * A constant albedo, cosine-weighted sampling.
     *
     * @param albedo reflectance, each channel in [0, 1]
     */
    public Lambert(Rgb albedo) {
        this(TextureLookup.of(Objects.requireNonNull(albedo, "albedo")), false);
    }

    /**
     * A constant albedo.
     *
     * @param albedo  reflectance, each channel in [0, 1]
     * @param uniform sample directions uniformly rather than cosine-weighted
     */
    public Lambert(Rgb albedo, boolean uniform) {
        this(TextureLookup.of(Objects.requireNonNull(albedo, "albedo")), uniform);
    }

    @Override
    public void eval(Vector2dc uv, Vector3dc wo, Vector3dc wi, MutableRgb dest) {
        if (wo.z() <= 0 || wi.z() <= 0) {
            dest.setZero();
            return;
        }
        albedo.rgb(uv.x(), uv.y(), dest);
        dest.mul(INV_PI);
    }

    @Override
    public double pdf(Vector2dc uv, Vector3dc wo, Vector3dc wi) {
        if (wo.z() <= 0) {
            return 0;
        }
        return uniform ? Warp.uniformHemispherePdf(wi.z()) : Warp.cosineHemispherePdf(wi.z());
    }

    @Override
    public boolean sample(Vector2dc uv, Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        if (wo.z() <= 0) {
            return false;
        }
        out.delta = false;
        out.eta = 1;
        albedo.rgb(uv.x(), uv.y(), out.weight);
        if (!uniform) {
            Warp.cosineHemisphere(u1, u2, out.wi);
            out.pdf = Warp.cosineHemispherePdf(out.wi.z);
        } else {
            Warp.uniformHemisphere(u1, u2, out.wi);
            out.pdf = Warp.uniformHemispherePdf(out.wi.z);
            out.weight.mul(2 * out.wi.z);
        }
        return out.pdf > 0;
    }

    @Override
    public Bsdf withUniformHemisphere(boolean u) {
        return u == uniform ? this : new Lambert(albedo, u);
    }

    /** The albedo, on either side. */
    @Override
    public void albedo(Vector2dc uv, Vector3dc wo, MutableRgb dest) {
        albedo.rgb(uv.x(), uv.y(), dest);
    }
}
