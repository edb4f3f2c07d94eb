package dev.strahl.accel;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.RayTriangle;

/**
 * Teaching option ({@code --accel none}): no tree, every query tests every primitive in a loop,
 * as a first ray tracer does (docs/experiments.md measures what the tree buys). Triangles go
 * through {@link RayTriangle}, the test every kernel uses, with the thread's set-up (nothing
 * allocated per ray), so it finds the hits the tree finds; only the order in which primitives are
 * tried differs, which can name the other triangle of an exact tie.
 */
public final class BruteForce implements Aggregate {
    private final Geometry geometry;

    /** Every query over all of {@code geometry}'s primitives. */
    public BruteForce(Geometry geometry) {
        this.geometry = geometry;
    }

    @Override
    public Geometry geometry() {
        return geometry;
    }

    @Override
    public boolean intersect(Ray ray, Hit hit, TraversalStack stack, boolean cullBackFaces) {
        RayTriangle tr = stack.triangle.prepare(ray);
        float[] pos = geometry.positionArray();
        int[] tri = geometry.indexArray();
        byte[] flags = geometry.flagArray();
        int triangles = geometry.triangleCount();
        double tHit = ray.tMax;
        int found = -1;
        for (int prim = 0; prim < triangles; prim++) {
            if (tr.hit(pos, tri, flags, prim, tHit, cullBackFaces)) {
                tHit = tr.t;
                found = prim;
            }
        }
        int spheres = geometry.sphereCount();
        if (spheres > 0) {
            ray.tMax = tHit;
            if (geometry.intersect(triangles, spheres, ray, hit, cullBackFaces)) {
                tHit = hit.t;
                found = hit.prim;
            }
        }
        if (found < 0) {
            return false;
        }
        ray.tMax = tHit;
        hit.t = tHit;
        hit.prim = found;
        if (found < triangles) {
            hit.b1 = tr.b1();
            hit.b2 = tr.b2();
        }
        return true;
    }

    @Override
    public boolean occluded(Ray ray, TraversalStack stack) {
        RayTriangle tr = stack.triangle.prepare(ray);
        float[] pos = geometry.positionArray();
        int[] tri = geometry.indexArray();
        int triangles = geometry.triangleCount();
        for (int prim = 0; prim < triangles; prim++) {
            if (tr.hit(pos, tri, null, prim, ray.tMax, false)) {
                return true;
            }
        }
        int spheres = geometry.sphereCount();
        return spheres > 0 && geometry.occludes(triangles, spheres, ray);
    }

    @Override
    public Aggregate bruteForce() {
        return this;
    }

    @Override
    public long byteSize() {
        return 0;
    }

    @Override
    public String kernel() {
        return "brute force";
    }
}
