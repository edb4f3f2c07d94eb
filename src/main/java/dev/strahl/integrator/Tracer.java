package dev.strahl.integrator;

import dev.strahl.accel.Bvh;
import dev.strahl.accel.TraversalStack;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.world.World;

/**
 * The per-thread machinery every integrator uses: closest-hit tracing that sets up shading at the
 * hit, next-event estimation, and the ray count. Owns its scratch objects; never shared.
 */
public final class Tracer {
    final World world;
    final LightSampler lights;
    public final DirectLight direct;
    private final Bvh bvh;
    private final TraversalStack stack;
    private final Hit hit = new Hit();
    private final Bsdf[] bsdfs;
    private final boolean cullBackFaces;
    private long rays;

    public Tracer(World world, Bsdf[] bsdfs, boolean cullBackFaces) {
        this.world = world;
        this.lights = world.lights();
        this.bvh = world.bvh();
        this.stack = Bvh.newStack();
        this.direct = new DirectLight(bvh, lights, stack);
        this.bsdfs = bsdfs;
        this.cullBackFaces = cullBackFaces;
    }

    /** Traces the ray; on a hit, sets up {@code s} there and returns the distance, else -1. */
    public double trace(Ray ray, Shading s) {
        rays++;
        hit.reset();
        if (!bvh.intersect(ray, hit, stack, cullBackFaces)) {
            return -1;
        }
        s.at(ray, hit, world, bsdfs);
        return hit.t;
    }

    /** Rays traced so far, shadow rays included. */
    public long rayCount() {
        return rays + direct.rays;
    }
}
