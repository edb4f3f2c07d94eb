package dev.strahl.material;

import dev.strahl.math.Rgb;
import dev.strahl.sampling.HemisphereSampling;
import dev.strahl.sampling.Warp;
import java.util.Objects;
import org.joml.Vector3dc;

/**
 * Lambertian diffuse reflection: f = albedo / π on the side of wo, zero for transmission.
 * Sampled cosine-weighted (pdf = cosθ/π, weight = albedo) or uniformly (pdf = 1/(2π),
 * weight = 2·albedo·cosθ).
 *
 * @param albedo   reflectance, each channel in [0, 1]
 * @param sampling how directions are sampled
 */
public record Lambert(Rgb albedo, HemisphereSampling sampling) implements Bsdf {
    private static final double INV_PI = 1 / Math.PI;

    /**
     * Checks that the albedo lies in [0, 1].
     *
     * @param albedo   reflectance, each channel in [0, 1]
     * @param sampling how directions are sampled
     */
    public Lambert {
        Objects.requireNonNull(albedo, "albedo");
        Objects.requireNonNull(sampling, "sampling");
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
        this(albedo, HemisphereSampling.COSINE);
    }

    @Override
    public void eval(Vector3dc wo, Vector3dc wi, Rgb.Mutable dest) {
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
        return sampling == HemisphereSampling.COSINE ? Warp.cosineHemispherePdf(wi.z()) : Warp.uniformHemispherePdf(wi.z());
    }

    @Override
    public boolean sample(Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        if (wo.z() <= 0) {
            return false;
        }
        out.delta = false;
        if (sampling == HemisphereSampling.COSINE) {
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
    public Bsdf withHemisphereSampling(HemisphereSampling s) {
        return s == sampling ? this : new Lambert(albedo, s);
    }
}
