package dev.strahl.integrator;

import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.material.Bsdf;
import dev.strahl.math.Frame;
import dev.strahl.image.Rgb;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * What every integrator needs at a hit: the surface point, its material's BSDF and emission, and
 * the local shading frame with wo in it. One per worker thread, reused at every hit.
 */
public final class Shading {
    public final SurfacePoint sp = new SurfacePoint();
    public final Frame frame = new Frame();
    public final Vector3d woLocal = new Vector3d();
    private final Vector3d wo = new Vector3d();
    public Bsdf bsdf;
    /** Emitted radiance towards the ray's origin: black unless the front of an emitter was hit. */
    public Rgb emitted;
    /** Cosine between the emitter's normal and the direction back to the ray origin. */
    double cosEmitter;

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
        world.geometry().surface(ray, hit, sp);
        bsdf = bsdfs[sp.material];
        wo.set(ray.d).negate();
        double cosGeometric = wo.dot(sp.ng);
        Rgb le = world.emission(sp.material);
        cosEmitter = cosGeometric;
        emitted = cosGeometric > 0 ? le : Rgb.BLACK;
        if (bsdf.isTwoSided() && cosGeometric < 0) {
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
}
