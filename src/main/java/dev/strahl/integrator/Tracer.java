package dev.strahl.integrator;

import dev.strahl.accel.Aggregate;
import dev.strahl.accel.RayBatch;
import dev.strahl.accel.TraversalStack;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.world.SurfaceMaps;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * The per-thread machinery every integrator uses: closest-hit tracing that sets up shading at the
 * hit, next-event estimation, and the ray count. Owns its scratch objects; never shared.
 *
 * <p><b>Alpha cut-outs.</b> Where a material's alpha is below its cutoff the surface is absent:
 * the ray goes on from just past the hit, unchanged in direction and throughput, until it meets
 * a surface that is there (or leaves the scene). This loop lives here, not in the BVH, and runs
 * only in a world that has cut-outs ({@link World#hasCutouts()}); shadow rays do the same in
 * {@link DirectLight}. A ray re-spawned more than {@value #MAX_PASSES} times takes the surface
 * it stands on as opaque (a bound, not a case real scenes reach).
 */
public final class Tracer {
    /** The most cut-away surfaces one ray passes. */
    static final int MAX_PASSES = 256;

    final World world;
    final LightSampler lights;
    public final DirectLight direct;
    private final Aggregate bvh;
    private final TraversalStack stack;
    private final Hit hit = new Hit();
    private final Bsdf[] bsdfs;
    private final boolean cullBackFaces;
    private final boolean cutouts;
    private final Vector3d origin = new Vector3d();
    private long rays;

    public Tracer(World world, Bsdf[] bsdfs, boolean cullBackFaces) {
        this.world = world;
        this.lights = world.lights();
        this.bvh = world.bvh();
        this.stack = new TraversalStack();
        this.direct = new DirectLight(world, stack);
        this.bsdfs = bsdfs;
        this.cullBackFaces = cullBackFaces;
        this.cutouts = world.hasCutouts();
    }

    /**
     * Traces the ray; on a hit, sets up {@code s} there and returns the distance from the ray's
     * origin, else -1. The ray's origin and direction are as they were afterwards.
     */
    public double trace(Ray ray, Shading s) {
        rays++;
        hit.reset();
        double tMax = ray.tMax;
        // the query itself, not through closestHit: one call level less keeps the SIMD kernel's vectors inlined (none allocated)
        if (!bvh.intersect(ray, hit, stack, cullBackFaces)) {
            return -1;
        }
        return settle(ray, tMax, hit, s);
    }

    /** The closest hits of rays [0, n) of {@code batch} at once (the aggregate's batch query), into its hit arrays. */
    void closestHits(RayBatch batch, int n) {
        rays += n;
        bvh.intersect(batch, 0, n, stack, cullBackFaces);
    }

    /**
     * Sets up {@code s} at the closest hit found for {@code ray} (by {@link #trace} or a batch query), whose tMax was
     * {@code tMax} before the query, and returns its distance; in a world with cut-outs, passes the
     * cut-away surfaces first (tracing on; -1 if nothing is left). The ray's origin and direction
     * are as they were afterwards.
     */
    double settle(Ray ray, double tMax, Hit hit, Shading s) {
        if (!cutouts) {
            s.at(ray, hit, world, bsdfs);
            return hit.t;
        }
        world.surface(ray, hit, s.sp);
        if (!cutAway(s)) {
            s.setUp(ray, world, bsdfs);
            return hit.t;
        }
        return passCutouts(ray, tMax, s, hit);
    }

    private boolean cutAway(Shading s) {
        SurfaceMaps maps = world.maps(s.sp.material);
        return maps != null && maps.cutAway(s.sp.uv);
    }

    /** Continues the ray past cut-away surfaces (s.sp holds the first) to the first surface that is there. */
    private double passCutouts(Ray ray, double tMax, Shading s, Hit hit) {
        origin.set(ray.o);
        for (int pass = 0; pass < MAX_PASSES; pass++) {
            s.sp.spawnOrigin(ray.d, ray.o);
            ray.tMax = tMax - origin.distance(ray.o);
            rays++;
            hit.reset();
            if (!(ray.tMax > 0) || !bvh.intersect(ray, hit, stack, cullBackFaces)) {
                ray.o.set(origin);
                return -1;
            }
            world.surface(ray, hit, s.sp);
            if (!cutAway(s)) {
                break;
            }
        }
        s.setUp(ray, world, bsdfs);
        ray.o.set(origin);
        return origin.distance(s.sp.p);
    }

    /** Rays traced so far, shadow rays included. */
    public long rayCount() {
        return rays + direct.rays;
    }
}
