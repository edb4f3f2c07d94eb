package dev.strahl.integrator;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.material.Bsdf;
import dev.strahl.math.Frame;
import dev.strahl.math.Rgb;
import dev.strahl.sampling.HemisphereSampling;
import dev.strahl.scene.Scene;
import org.joml.Vector3d;

/**
 * What every integrator needs at a hit: the surface point, its material's BSDF and emission, and
 * the local shading frame with wo in it. One per worker thread, reused at every hit.
 */
final class Shading {
    final SurfacePoint sp = new SurfacePoint();
    final Frame frame = new Frame();
    final Vector3d woLocal = new Vector3d();
    private final Vector3d wo = new Vector3d();
    Bsdf bsdf;
    /** Emitted radiance towards the ray's origin: black unless the front of an emitter was hit. */
    Rgb emitted;
    /** Cosine between the emitter's normal and the direction back to the ray origin. */
    double cosEmitter;

    /** Each material's BSDF, with diffuse lobes sampled as given. */
    static Bsdf[] bsdfs(Scene scene, HemisphereSampling hemisphere) {
        Bsdf[] out = new Bsdf[scene.materials().size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = scene.materials().get(i).bsdf().withHemisphereSampling(hemisphere);
        }
        return out;
    }

    /**
     * Sets up shading at the hit. Two-sided BSDFs see the side of wo as their front. Where the
     * interpolated shading normal puts wo on another side than the geometric normal does (at
     * silhouettes of smooth meshes), the geometric normal is used instead: no black facets and no
     * light through the surface.
     */
    void at(Ray ray, Hit hit, Geometry geometry, Bsdf[] bsdfs, Rgb[] emission) {
        geometry.surface(ray, hit, sp);
        bsdf = bsdfs[sp.material];
        wo.set(ray.d).negate();
        double cosGeometric = wo.dot(sp.ng);
        Rgb le = emission[sp.material];
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
