package dev.strahl.geometry;

/**
 * The ray–primitive tests of {@link Geometry}, on its flat arrays, for a run of primitives at a
 * time: the loops over triangles that {@link Geometry}'s queries run (the reference a BVH is
 * checked against), and the sphere test. Triangles use {@link RayTriangle}, the one triangle test
 * the BVH uses too, so both give the same bits. Spheres use the stable quadratic of Haines et al.
 * ("Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019, ch. 7).
 */
final class Intersections {
    private Intersections() {}

    /**
     * The closest hit among triangles [first, end) in (0, ray.tMax): fills {@code hit}, shortens
     * {@code ray.tMax}; with {@code cull}, back faces of triangles flagged {@link Geometry#CLOSED}
     * are skipped. Sets up its own {@link RayTriangle}: not for the render's inner loops, which
     * keep one per thread.
     */
    static boolean triangles(float[] pos, int[] tri, byte[] flags, int first, int end, Ray ray, Hit hit, boolean cull) {
        RayTriangle s = new RayTriangle().prepare(ray);
        double tMax = ray.tMax;
        int found = -1;
        for (int prim = first; prim < end; prim++) {
            if (s.hit(pos, tri, flags, prim, tMax, cull)) {
                tMax = s.t;
                found = prim;
            }
        }
        if (found < 0) {
            return false;
        }
        ray.tMax = tMax;
        hit.t = tMax;
        hit.prim = found;
        hit.b1 = s.b1();            // s holds the last hit it reported: the closest
        hit.b2 = s.b2();
        return true;
    }

    /** Whether any triangle of [first, end) blocks the ray in (0, ray.tMax); the test of {@link #triangles}, never culling. */
    static boolean trianglesOcclude(float[] pos, int[] tri, int first, int end, Ray ray) {
        RayTriangle s = new RayTriangle().prepare(ray);
        for (int prim = first; prim < end; prim++) {
            if (s.hit(pos, tri, null, prim, ray.tMax, false)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Nearest sphere distance in (0, tMax), else -1, for the sphere with centre and radius at
     * {@code sph[4s .. 4s+3]}: the discriminant from the distance of the centre to the ray line.
     */
    static double sphere(double[] sph, int s, Ray ray) {
        int k = 4 * s;
        double r = sph[k + 3];
        double tMax = ray.tMax;
        double dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
        double fx = ray.o.x - sph[k], fy = ray.o.y - sph[k + 1], fz = ray.o.z - sph[k + 2];
        double b = -(fx * dx + fy * dy + fz * dz);                  // d is unit length
        double lx = fx + b * dx, ly = fy + b * dy, lz = fz + b * dz;
        double discr = r * r - (lx * lx + ly * ly + lz * lz);
        if (discr < 0) {
            return -1;
        }
        double c = fx * fx + fy * fy + fz * fz - r * r;
        double q = b + Math.copySign(Math.sqrt(discr), b);
        double t0, t1;
        if (q == 0) {
            t0 = t1 = 0;
        } else {
            t0 = c / q;
            t1 = q;
        }
        if (t0 > t1) {
            double tmp = t0;
            t0 = t1;
            t1 = tmp;
        }
        if (t0 > 0 && t0 < tMax) {
            return t0;
        }
        return t1 > 0 && t1 < tMax ? t1 : -1;
    }
}
