package dev.strahl.sampling;

import org.joml.Vector3d;

/**
 * Warps from the unit square to other domains, each next to its density so the two cannot drift
 * apart. Directions are in a local frame with z up. Every pair is checked by a chi-square test.
 */
public final class Warp {
    private static final double INV_PI = 1.0 / Math.PI;
    private static final double INV_TWO_PI = 0.5 / Math.PI;
    private static final double PI_OVER_4 = Math.PI / 4;
    private static final double PI_OVER_2 = Math.PI / 2;

    private Warp() {}

    /**
     * Concentric mapping of the square onto the unit disk (Shirley &amp; Chiu, "A Low Distortion
     * Map Between Disk and Square", 1997). Writes (x, y) into {@code dest.x, dest.y}, z = 0.
     */
    public static Vector3d concentricDisk(double u1, double u2, Vector3d dest) {
        double ox = 2 * u1 - 1;
        double oy = 2 * u2 - 1;
        if (ox == 0 && oy == 0) {
            return dest.set(0, 0, 0);
        }
        double r;
        double theta;
        if (Math.abs(ox) > Math.abs(oy)) {
            r = ox;
            theta = PI_OVER_4 * (oy / ox);
        } else {
            r = oy;
            theta = PI_OVER_2 - PI_OVER_4 * (ox / oy);
        }
        return dest.set(r * Math.cos(theta), r * Math.sin(theta), 0);
    }

    /** Cosine-weighted hemisphere by Malley's method: the concentric disk lifted to z. pdf = cosθ/π. */
    public static Vector3d cosineHemisphere(double u1, double u2, Vector3d dest) {
        concentricDisk(u1, u2, dest);
        double z = Math.sqrt(Math.max(0, 1 - dest.x * dest.x - dest.y * dest.y));
        return dest.set(dest.x, dest.y, z);
    }

    public static double cosineHemispherePdf(double cosTheta) {
        return cosTheta > 0 ? cosTheta * INV_PI : 0;
    }

    /** Uniform hemisphere around z. pdf = 1/(2π). */
    public static Vector3d uniformHemisphere(double u1, double u2, Vector3d dest) {
        double z = u1;
        double r = Math.sqrt(Math.max(0, 1 - z * z));
        double phi = 2 * Math.PI * u2;
        return dest.set(r * Math.cos(phi), r * Math.sin(phi), z);
    }

    public static double uniformHemispherePdf(double cosTheta) {
        return cosTheta > 0 ? INV_TWO_PI : 0;
    }

    /** Uniform direction on the unit sphere. pdf = 1/(4π). */
    public static Vector3d uniformSphere(double u1, double u2, Vector3d dest) {
        double z = 1 - 2 * u1;
        double r = Math.sqrt(Math.max(0, 1 - z * z));
        double phi = 2 * Math.PI * u2;
        return dest.set(r * Math.cos(phi), r * Math.sin(phi), z);
    }

    public static double uniformSpherePdf() {
        return 0.25 * INV_PI;
    }

    /**
     * Uniform direction in the cone of half-angle θmax around z, cosθ uniform in [cosθmax, 1]
     * (pbrt-v4 §A.5.4, {@code SampleUniformCone}). pdf = 1/(2π(1 − cosθmax)).
     */
    public static Vector3d uniformCone(double u1, double u2, double cosThetaMax, Vector3d dest) {
        double z = 1 - u1 * (1 - cosThetaMax);
        double r = Math.sqrt(Math.max(0, 1 - z * z));
        double phi = 2 * Math.PI * u2;
        return dest.set(r * Math.cos(phi), r * Math.sin(phi), z);
    }

    /** Density of {@link #uniformCone} at a direction whose cosine with z is {@code cosTheta}: 0 outside the cone. */
    public static double uniformConePdf(double cosTheta, double cosThetaMax) {
        return cosTheta >= cosThetaMax && cosThetaMax < 1 ? INV_TWO_PI / (1 - cosThetaMax) : 0;
    }

    /**
     * Uniform barycentric coordinates (b0, b1) on a triangle, into {@code dest.x, dest.y}; the
     * point is b0·p0 + b1·p1 + (1 − b0 − b1)·p2. Uses the square-root parametrisation
     * (Osada et al. 2002; pbrt-v4 §6.5.4). pdf = 1/area.
     */
    public static Vector3d uniformTriangle(double u1, double u2, Vector3d dest) {
        double su = Math.sqrt(u1);
        double b0 = 1 - su;
        double b1 = u2 * su;
        return dest.set(b0, b1, 0);
    }
}
