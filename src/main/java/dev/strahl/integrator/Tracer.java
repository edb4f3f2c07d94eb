package dev.strahl.integrator;

import dev.strahl.accel.Bvh;
import dev.strahl.accel.TraversalStack;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.math.Rgb;
import dev.strahl.scene.Scene;

/**
 * The per-thread machinery every integrator uses: closest-hit tracing that sets up shading at the
 * hit, next-event estimation, and the ray count. Owns its scratch objects; never shared.
 */
final class Tracer {
    final Scene scene;
    final LightSampler lights;
    final DirectLight direct;
    private final Bvh bvh;
    private final Geometry geometry;
    private final TraversalStack stack;
    private final Hit hit = new Hit();
    private final Bsdf[] bsdfs;
    private final Rgb[] emission;
    private final boolean cullBackFaces;
    private long rays;

    Tracer(Scene scene, Bsdf[] bsdfs, boolean cullBackFaces) {
        this.scene = scene;
        this.lights = scene.lights();
        this.bvh = scene.bvh();
        this.geometry = scene.geometry();
        this.stack = Bvh.newStack();
        this.direct = new DirectLight(bvh, lights, stack);
        this.bsdfs = bsdfs;
        this.emission = new Rgb[bsdfs.length];
        for (int i = 0; i < emission.length; i++) {
            emission[i] = scene.materials().get(i).emission();
        }
        this.cullBackFaces = cullBackFaces;
    }

    /** Traces the ray; on a hit, sets up {@code s} there and returns the distance, else -1. */
    double trace(Ray ray, Shading s) {
        rays++;
        hit.reset();
        if (!bvh.intersect(ray, hit, stack, cullBackFaces)) {
            return -1;
        }
        s.at(ray, hit, geometry, bsdfs, emission);
        return hit.t;
    }

    /** Rays traced so far, shadow rays included. */
    long rayCount() {
        return rays + direct.rays;
    }
}
