package dev.strahl.integrator;

import dev.strahl.color.MutableRgb;
import dev.strahl.accel.Aggregate;
import dev.strahl.accel.RayBatch;
import dev.strahl.accel.TraversalStack;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.light.LightSample;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.math.MathUtil;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.Sampler;
import dev.strahl.world.SurfaceMaps;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * Next-event estimation: light arriving directly from the area lights, the punctual lights and
 * the environment at a surface point, estimated with shadow rays to points sampled on the lights
 * (or towards directions sampled on the environment). A punctual light is a delta light: no BSDF
 * sample can hit it, so its samples always have weight 1, also under {@link Use#MIS}. One per worker thread (it owns its
 * scratch objects); shared by the path tracer, direct lighting, Whitted and the photon mapper.
 *
 * <p>Each light sample draws its numbers first, whatever follows: a pair for the point on the
 * light, then one number for the choice of light. So a caller that calls {@link #add} at every
 * vertex keeps the dimensions after it in place even where nothing can be estimated (a delta
 * BSDF, no lights, or {@link Use#DRAW_ONLY}); it never has to count what it did not draw.
 */
public final class DirectLight {
    /** What {@link #add} does with its light samples. */
    public enum Use {
        /** Draws their numbers and adds nothing: a strategy without light sampling (the path tracer's BSDF-only one). */
        DRAW_ONLY,
        /** Light sampling alone: weight w = 1. */
        LIGHT_ONLY,
        /** Weighted against one BSDF sample at the same point by the power heuristic. */
        MIS,
        /**
         * Light sampling alone (w = 1) with every shadow ray taken as unblocked and never traced:
         * the teaching option without shadows, the talk's picture of Lambert × light. Each light
         * in front of the point lights it as if nothing stood between them.
         */
        UNOCCLUDED
    }

    private final World world;
    private final Aggregate bvh;
    private final LightSampler lights;
    private final TraversalStack stack;
    private final boolean cutouts;
    private final Hit hit = new Hit();
    private final SurfacePoint blocker = new SurfacePoint();
    private final Vector3d origin = new Vector3d();
    private final SurfacePoint lightPoint = new SurfacePoint();
    private final LightSample ls = new LightSample();
    private final ShadowQuery query = new ShadowQuery();
    private final Ray shadow = new Ray();
    private final Vector3d wiLocal = new Vector3d();
    private final Vector3d toSurface = new Vector3d();
    private final Vector3d target = new Vector3d();
    private final MutableRgb f = new MutableRgb();
    private final Sample2D uPoint = new Sample2D();
    public long rays;

    DirectLight(World world, TraversalStack stack) {
        this.world = world;
        this.bvh = world.bvh();
        this.lights = world.lights();
        this.stack = stack;
        this.cutouts = world.hasCutouts();
    }

    /**
     * Draws n light samples and, where the BSDF at {@code s} is not a pure delta, there are lights
     * and {@code use} is not {@link Use#DRAW_ONLY}, adds beta · (1/n) Σ f(wo, wi)·Le·|cosθi|·w / pdf
     * over them to {@code out}: w = 1 for {@link Use#LIGHT_ONLY} and {@link Use#UNOCCLUDED}; for
     * {@link Use#MIS} the power heuristic with sample counts against one BSDF sample (Veach 1997,
     * eq. 9.13), (n·pl)² / ((n·pl)² + pb²). Only {@link Use#UNOCCLUDED} skips the shadow rays.
     * Each sample is {@link #prepare} then {@link #resolve}: the path tracer's wavefront does the
     * two apart, with every shadow ray of a batch traced in between.
     */
    public void add(Shading s, Sampler sampler, int n, Use use, MutableRgb beta, MutableRgb out) {
        boolean estimate = estimates(s, use);
        double scale = 1.0 / n;
        for (int i = 0; i < n; i++) {
            sampler.get2D(uPoint);                 // the point on the light: one stratified pair
            double uLight = sampler.get1D();
            if (estimate && prepare(s, uPoint.u1, uPoint.u2, uLight, use, n, scale, beta, query)) {
                resolve(query, out);
            }
        }
    }

    /** Whether light samples at {@code s} estimate anything: not at a pure delta BSDF, nor without lights, nor for {@link Use#DRAW_ONLY}. */
    public boolean estimates(Shading s, Use use) {
        return use != Use.DRAW_ONLY && !s.bsdf.isDelta() && !lights.isEmpty();
    }

    /**
     * Makes the shadow query of one light sample at {@code s} (where {@link #estimates} holds),
     * from its numbers: a pair (u1, u2) for the point on the light and uLight for the choice of
     * light. Returns false if the sample adds nothing whatever stands in its way; otherwise
     * {@code q} holds the contribution beta·f·Le·|cosθi|·w·scale/pdf and the shadow ray that
     * decides it (none for {@link Use#UNOCCLUDED}), for {@link #resolve}.
     */
    public boolean prepare(Shading s, double u1, double u2, double uLight, Use use, int n, double scale, MutableRgb beta, ShadowQuery q) {
        boolean lightAlone = use != Use.MIS;
        if (!lights.sample(s.sp.p, s.sp.n, uLight, u1, u2, lightAlone, lightPoint, ls)) {
            return false;
        }
        s.frame.toLocal(ls.wi, wiLocal);
        if (ls.wi.dot(s.sp.ng) * wiLocal.z <= 0) {
            return false;                          // shading and geometric normal disagree: no leaks
        }
        Bsdf bsdf = s.bsdf;
        bsdf.eval(s.sp.uv, s.woLocal, wiLocal, f);
        if (f.isBlack()) {
            return false;
        }
        q.traced = use != Use.UNOCCLUDED;
        if (q.traced && !shadowRay(s.sp, q.ray)) {
            return false;
        }
        double w = lightAlone || ls.delta ? 1 : MathUtil.powerHeuristic(n * ls.pdf, bsdf.pdf(s.sp.uv, s.woLocal, wiLocal));
        f.mul(ls.radiance);
        double k = Math.abs(wiLocal.z) * w * scale / ls.pdf;
        q.contribution.set(beta.r * f.r * k, beta.g * f.g * k, beta.b * f.b * k);   // addProduct's order: the same bits
        return true;
    }

    /** Adds a prepared query's contribution to {@code out} unless its shadow ray is blocked (tracing it; it may move the ray's origin). */
    public void resolve(ShadowQuery q, MutableRgb out) {
        if (!q.traced || !occluded(q.ray)) {
            out.r += q.contribution.r;
            out.g += q.contribution.g;
            out.b += q.contribution.b;
        }
    }

    /**
     * The shadow ray from sp to the sampled light point (or, for the environment, the way out along
     * wi), both ends moved off their surfaces, into {@code shadow}; false where the two coincide
     * (nothing to trace: the sample counts as blocked).
     */
    private boolean shadowRay(SurfacePoint sp, Ray shadow) {
        sp.spawnOrigin(ls.wi, shadow.o);
        if (ls.infinite) {
            shadow.d.set(ls.wi);
            shadow.tMax = Double.POSITIVE_INFINITY;
            return true;
        }
        if (ls.delta) {
            target.set(ls.p);                      // a point light is no surface: nothing to move off
        } else {
            toSurface.set(ls.wi).negate();
            SurfacePoint.offset(ls.p, ls.ng, toSurface, target);
        }
        shadow.d.set(target).sub(shadow.o);
        double dist = shadow.d.length();
        if (!(dist > 0)) {
            return false;
        }
        shadow.d.div(dist);
        shadow.tMax = dist;
        return true;
    }

    /**
     * Whether something blocks the shadow ray. Alpha cut-outs let it pass: in a world with
     * cut-outs, a blocked ray is traced again hit by hit (closest hits), past every cut-away
     * surface, and counts as blocked only by a surface that is there. May move the ray's origin.
     */
    boolean occluded(Ray ray) {
        rays++;
        return bvh.occluded(ray, stack) && (!cutouts || blockedPastCutouts(ray));
    }

    /**
     * Whether each of shadow rays [0, n) of {@code batch} is blocked, into {@code batch.occluded}:
     * {@link #occluded(Ray)} of each, the first any-hit query of all of them at once (the
     * aggregate's batch query), then the cut-outs ray by ray.
     */
    void occluded(RayBatch batch, int n) {
        rays += n;
        bvh.occluded(batch, 0, n, stack);
        if (!cutouts) {
            return;
        }
        Ray ray = shadow;
        for (int i = 0; i < n; i++) {
            if (batch.occluded[i]) {
                ray.o.set(batch.ox[i], batch.oy[i], batch.oz[i]);
                ray.d.set(batch.dx[i], batch.dy[i], batch.dz[i]);
                ray.tMax = batch.tMax[i];
                batch.occluded[i] = blockedPastCutouts(ray);
            }
        }
    }

    /** For a shadow ray found blocked: whether it still is when cut-away surfaces let it pass (tracing on hit by hit; may move its origin). */
    private boolean blockedPastCutouts(Ray ray) {
        double tMax = ray.tMax;
        origin.set(ray.o);
        for (int pass = 0; pass < Tracer.MAX_PASSES; pass++) {
            rays++;
            hit.reset();
            if (!bvh.intersect(ray, hit, stack, false)) {
                return false;
            }
            world.surface(ray, hit, blocker);
            SurfaceMaps maps = world.maps(blocker.material);
            if (maps == null || !maps.cutAway(blocker.uv)) {
                return true;
            }
            blocker.spawnOrigin(ray.d, ray.o);
            ray.tMax = tMax - origin.distance(ray.o);
            if (!(ray.tMax > 0)) {
                return false;
            }
        }
        return true;
    }
}
