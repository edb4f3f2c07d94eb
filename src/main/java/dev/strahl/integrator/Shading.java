package dev.strahl.integrator;

import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.material.Bsdf;
import dev.strahl.material.BsdfSample;
import dev.strahl.math.Frame;
import dev.strahl.light.Emission;
import dev.strahl.color.MutableRgb;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.Sampler;
import dev.strahl.world.SurfaceMaps;
import dev.strahl.world.World;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * What every integrator needs at a hit: the surface point, its material's BSDF and emission, the
 * local shading frame with wo in it, and the BSDF sample taken there. One per worker thread,
 * reused at every hit.
 */
public final class Shading {
    public final SurfacePoint sp = new SurfacePoint();
    public final Frame frame = new Frame();
    public final Vector3d woLocal = new Vector3d();
    /** The last {@link #sampleBsdf} result; {@code bs.wi} is in the local frame. */
    public final BsdfSample bs = new BsdfSample();
    /** The last {@link #sampleBsdf} direction in world space. */
    public final Vector3d wi = new Vector3d();
    private final Vector3d wo = new Vector3d();
    private final Sample2D uDirection = new Sample2D();
    private final MutableRgb texel = new MutableRgb();
    private final Vector3d tangent = new Vector3d();
    public Bsdf bsdf;
    /** Emitted radiance towards the ray's origin (Le at the hit's (u, v)): black unless the front of an emitter was hit. */
    public final MutableRgb emitted = new MutableRgb();
    /** Cosine between the emitter's normal and the direction back to the ray origin. */
    double cosEmitter;
    /** Whether {@link #setUp} turned ng (and n) around to face wo: then the surface's own geometric normal is −sp.ng. */
    boolean flipped;

    /** Each material's BSDF, with diffuse lobes sampled uniformly or cosine-weighted. */
    public static Bsdf[] bsdfs(World world, boolean uniformHemisphere) {
        Bsdf[] out = new Bsdf[world.materialCount()];
        for (int i = 0; i < out.length; i++) {
            out[i] = world.bsdf(i).withUniformHemisphere(uniformHemisphere);
        }
        return out;
    }

    /**
     * Sets up shading at the hit. Two-sided BSDFs see the side of wo as their front. Where the
     * interpolated shading normal puts wo on another side than the geometric normal does (at
     * silhouettes of smooth meshes), the geometric normal is used instead: no black facets and no
     * light through the surface.
     */
    void at(Ray ray, Hit hit, World world, Bsdf[] bsdfs) {
        world.surface(ray, hit, sp);
        setUp(ray, world, bsdfs);
    }

    /**
     * {@link #at} for a surface point already filled in: the material's normal map tilts the
     * shading normal first (every BSDF sees the tilted frame), then the sides are settled.
     */
    void setUp(Ray ray, World world, Bsdf[] bsdfs) {
        bsdf = bsdfs[sp.material];
        SurfaceMaps maps = world.maps(sp.material);
        if (maps != null && maps.normal() != null) {
            maps.tiltNormal(sp, texel, tangent);
        }
        wo.set(ray.d).negate();
        double cosGeometric = wo.dot(sp.ng);
        Emission le = world.emission(sp.material);
        cosEmitter = cosGeometric;
        if (cosGeometric > 0 && !le.isBlack()) {
            le.eval(sp.uv, emitted);
        } else {
            emitted.setZero();
        }
        flipped = bsdf.isTwoSided() && cosGeometric < 0;
        if (flipped) {
            sp.ng.negate();
            sp.n.negate();
            cosGeometric = -cosGeometric;
        }
        if (wo.dot(sp.n) * cosGeometric <= 0) {
            sp.n.set(sp.ng);
        }
        frame.set(sp.n);
        frame.toLocal(wo, woLocal);
    }

    /**
     * Samples the BSDF here with one number for the lobe choice and a pair for the direction (drawn
     * in that order, always both), into {@link #bs} and {@link #wi}. Returns false if the path is
     * absorbed, or if wi lies on the other side of the geometric normal than the shading frame
     * says (shading and geometric normal disagree: following it would leak light).
     */
    public boolean sampleBsdf(Sampler sampler) {
        double uc = sampler.get1D();
        sampler.get2D(uDirection);
        return sampleBsdf(uc, uDirection.u1, uDirection.u2);
    }

    /** {@link #sampleBsdf(Sampler)} with its numbers given: uc for the lobe, (u1, u2) for the direction. */
    boolean sampleBsdf(double uc, double u1, double u2) {
        if (!bsdf.sample(sp.uv, woLocal, uc, u1, u2, bs)) {
            return false;
        }
        frame.toWorld(bs.wi, wi);
        return !(wi.dot(sp.ng) * bs.wi.z <= 0);
    }

    /** Turns {@code ray} into the ray leaving this point in direction {@code dir} (its origin moved off the surface). */
    public void spawn(Ray ray, Vector3dc dir) {
        sp.spawnOrigin(dir, ray.o);
        ray.d.set(dir);
        ray.tMax = Double.POSITIVE_INFINITY;
    }
}
