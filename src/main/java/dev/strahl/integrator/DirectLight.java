package dev.strahl.integrator;

import dev.strahl.math.MutableRgb;
import dev.strahl.accel.Bvh;
import dev.strahl.accel.TraversalStack;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.light.LightSample;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.math.Frame;
import dev.strahl.math.MathUtil;
import dev.strahl.image.Rgb;
import dev.strahl.sampling.Rng;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Next-event estimation: light arriving directly from the area lights at a surface point,
 * estimated with shadow rays to points sampled on the lights. One per worker thread (it owns its
 * scratch objects); shared by the path tracer, direct lighting and Whitted.
 */
public final class DirectLight {
    private final Bvh bvh;
    private final LightSampler lights;
    private final TraversalStack stack;
    private final SurfacePoint lightPoint = new SurfacePoint();
    private final LightSample ls = new LightSample();
    private final Ray shadow = new Ray();
    private final Vector3d wiLocal = new Vector3d();
    private final Vector3d toSurface = new Vector3d();
    private final Vector3d target = new Vector3d();
    private final MutableRgb f = new MutableRgb();
    public long rays;

    DirectLight(Bvh bvh, LightSampler lights, TraversalStack stack) {
        this.bvh = bvh;
        this.lights = lights;
        this.stack = stack;
    }

    /**
     * Adds beta · (1/n) Σ f(wo, wi)·Le·|cosθi|·w / pdf over n light samples to {@code out}.
     *
     * @param bsdfWeight 0 for pure light sampling (w = 1); otherwise the number of BSDF samples
     *                   taken at this point, and w is the power heuristic with sample counts
     *                   (Veach 1997, eq. 9.13): (n·pl)² / ((n·pl)² + (nb·pb)²)
     */
    public void add(Bsdf bsdf, SurfacePoint sp, Frame frame, Vector3dc woLocal, Rng rng, int n, int bsdfWeight,
             MutableRgb beta, MutableRgb out) {
        double scale = 1.0 / n;
        for (int i = 0; i < n; i++) {
            // The point on the light first: a pair of dimensions of a stratified sampler.
            double u1 = rng.nextDouble(), u2 = rng.nextDouble(), uLight = rng.nextDouble();
            if (!lights.sample(sp.p, uLight, u1, u2, lightPoint, ls)) {
                continue;
            }
            frame.toLocal(ls.wi, wiLocal);
            if (ls.wi.dot(sp.ng) * wiLocal.z <= 0) {
                continue;                          // shading and geometric normal disagree: no leaks
            }
            bsdf.eval(woLocal, wiLocal, f);
            if (f.isBlack() || !visible(sp)) {
                continue;
            }
            double w = bsdfWeight == 0 ? 1 : MathUtil.powerHeuristic(n * ls.pdf, bsdfWeight * bsdf.pdf(woLocal, wiLocal));
            f.mul(ls.radiance);
            out.addProduct(beta, f, Math.abs(wiLocal.z) * w * scale / ls.pdf);
        }
    }

    /** Whether the sampled light point is visible from sp (both ends moved off their surfaces). */
    private boolean visible(SurfacePoint sp) {
        sp.spawnOrigin(ls.wi, shadow.o);
        toSurface.set(ls.wi).negate();
        SurfacePoint.offset(ls.p, ls.ng, toSurface, target);
        shadow.d.set(target).sub(shadow.o);
        double dist = shadow.d.length();
        if (!(dist > 0)) {
            return false;
        }
        shadow.d.div(dist);
        shadow.tMax = dist;
        rays++;
        return !bvh.occluded(shadow, stack);
    }
}
