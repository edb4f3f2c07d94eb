package dev.strahl.material;

import dev.strahl.math.MutableRgb;
import dev.strahl.image.Rgb;
import dev.strahl.sampling.Warp;
import java.util.Objects;
import org.joml.Vector3dc;

/**
 * Lambertian diffuse reflection: f = albedo / π on the side of wo, zero for transmission.
 * Sampled cosine-weighted (pdf = cosθ/π, weight = albedo) or uniformly (pdf = 1/(2π),
 * weight = 2·albedo·cosθ).
 *
 * @param albedo   reflectance, each channel in [0, 1]
 * @param uniform  sample directions uniformly over the hemisphere rather than cosine-weighted
 */
public record Lambert(Rgb albedo, boolean uniform) implements Bsdf {
    private static final double INV_PI = 1 / Math.PI;

    /**
     * Checks that the albedo lies in [0, 1].
     *
     * @param albedo   reflectance, each channel in [0, 1]
     * @param uniform  sample directions uniformly rather than cosine-weighted
     */
    public Lambert {
        Objects.requireNonNull(albedo, "albedo");
        if (albedo.r() < 0 || albedo.g() < 0 || albedo.b() < 0 || albedo.max() > 1) {
            throw new IllegalArgumentException("diffuse albedo must lie in [0, 1], got " + albedo);
        }
    }

    /**
     * Cosine-weighted sampling.
     *
     * @param albedo reflectance, each channel in [0, 1]
     */
    public Lambert(Rgb albedo) {
        this(albedo, false);
    }

    @Override
    public void eval(Vector3dc wo, Vector3dc wi, MutableRgb dest) {
        if (wo.z() <= 0 || wi.z() <= 0) {
            dest.setZero();
            return;
        }
        dest.set(albedo).mul(INV_PI);
    }

    @Override
    public double pdf(Vector3dc wo, Vector3dc wi) {
        if (wo.z() <= 0) {
            return 0;
        }
        return uniform ? Warp.uniformHemispherePdf(wi.z()) : Warp.cosineHemispherePdf(wi.z());
    }

    @Override
    public boolean sample(Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        if (wo.z() <= 0) {
            return false;
        }
        out.delta = false;
        out.eta = 1;
        if (!uniform) {
            Warp.cosineHemisphere(u1, u2, out.wi);
            out.pdf = Warp.cosineHemispherePdf(out.wi.z);
            out.weight.set(albedo);
        } else {
            Warp.uniformHemisphere(u1, u2, out.wi);
            out.pdf = Warp.uniformHemispherePdf(out.wi.z);
            out.weight.set(albedo).mul(2 * out.wi.z);
        }
        return out.pdf > 0;
    }

    @Override
    public Bsdf withUniformHemisphere(boolean u) {
        return u == uniform ? this : new Lambert(albedo, u);
    }

    /** The albedo, on either side. */
    @Override
    public void albedo(Vector3dc wo, MutableRgb dest) {
        dest.set(albedo);
    }
}
