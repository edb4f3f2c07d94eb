package dev.strahl.light;

import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.SurfacePoint;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/** A point sampled on a light, seen from a reference point; mutable, reused per thread. */
public final class LightSample {
    /** The point on the light and its geometric normal (unused for the environment). */
    public final Vector3d p = new Vector3d();
    public final Vector3d ng = new Vector3d();
    /** Unit direction from the reference point towards {@link #p}. */
    public final Vector3d wi = new Vector3d();
    /** Distance to {@link #p}; infinite for the environment. */
    public double distance;
    /** Whether the sample is of the environment: then only {@link #wi}, the pdf and the radiance mean anything. */
    public boolean infinite;
    /**
     * Whether the sample is of a punctual (delta) light: then {@link #radiance} is the irradiance
     * it gives a surface facing it, {@link #pdf} the probability of choosing it, and no BSDF
     * sample can find it (no MIS weight).
     */
    public boolean delta;
    /** Solid-angle density of wi at the reference point, light selection included. */
    public double pdf;
    /** Emitted radiance towards the reference point. */
    public final MutableRgb radiance = new MutableRgb();
    /** Scratch for the environment's (u, v). */
    final double[] uv = new double[2];

    /**
     * Aims this sample from {@code ref} at the point (px, py, pz) of a light: {@link #wi} the unit
     * direction towards it, {@link #distance} the distance d. Returns d², or 0 (leaving both as
     * they were) where the two points coincide (or a coordinate is NaN) and there is no direction.
     * The one place where area and punctual lights turn a light point into (wi, d).
     */
    double aim(Vector3dc ref, double px, double py, double pz) {
        double dx = px - ref.x(), dy = py - ref.y(), dz = pz - ref.z();
        double dist2 = dx * dx + dy * dy + dz * dz;
        double dist = Math.sqrt(dist2);
        if (!(dist > 0)) {
            return 0;
        }
        double inv = 1 / dist;
        wi.set(dx * inv, dy * inv, dz * inv);
        distance = dist;
        return dist2;
    }

    /**
     * Takes the point uniform by area on the emissive primitive {@code prim} for (u1, u2) into
     * {@code scratch} and this sample (not infinite, not delta) and aims at it from {@code ref}.
     * Returns cos θ at the light (between its geometric normal and the way back to ref), or 0
     * where the point faces away from ref or coincides with it: then there is no sample.
     */
    double aimAtAreaLight(Geometry geometry, int prim, Vector3dc ref, double u1, double u2, SurfacePoint scratch) {
        infinite = false;
        delta = false;
        geometry.samplePoint(prim, u1, u2, scratch);
        p.set(scratch.p);
        ng.set(scratch.ng);
        if (aim(ref, p.x, p.y, p.z) == 0) {
            return 0;
        }
        return Math.max(0, -ng.dot(wi));
    }
}
