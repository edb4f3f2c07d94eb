package dev.strahl.geometry;

import java.math.BigDecimal;

/**
 * The ray–primitive tests of {@link Geometry}, on its flat arrays, for a run of primitives at a
 * time (a BVH leaf): one call per leaf, the per-ray set-up done once per call, and no object per
 * primitive.
 *
 * <p>Triangles use the watertight test of Woop, Benthin &amp; Wald ("Watertight Ray/Triangle
 * Intersection", JCGT 2(1), 2013): the vertices are moved into a frame in which the ray runs
 * along +z from the origin, and the three 2D edge functions decide the hit. An edge shared by
 * two triangles gives the same edge function up to its sign in both, computed from the same
 * transformed vertices, so no ray slips through between them. The arithmetic is double, from
 * the float vertices. Spheres use the stable quadratic of Haines et al. ("Precision
 * Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019, ch. 7).
 */
final class Intersections {
    private Intersections() {}

    /**
     * The closest hit among triangles [first, end) in (0, ray.tMax): fills {@code hit}, shortens
     * {@code ray.tMax}; with {@code cull}, back faces of triangles flagged {@link Geometry#CLOSED}
     * are skipped.
     */
    static boolean triangles(float[] pos, int[] tri, byte[] flags, int first, int end, Ray ray, Hit hit, boolean cull) {
        final double dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
        // The axis of the largest direction component becomes z; x and y follow cyclically,
        // swapped when that component is negative so that the winding (and front face) is kept.
        final double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        final int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        final double dkz = kz == 0 ? dx : kz == 1 ? dy : dz;
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        if (dkz < 0) {
            int tmp = kx;
            kx = ky;
            ky = tmp;
        }
        final double sz = 1 / dkz;
        final double sx = component(dx, dy, dz, kx) * sz, sy = component(dx, dy, dz, ky) * sz;
        final double okx = component(ray.o.x, ray.o.y, ray.o.z, kx);
        final double oky = component(ray.o.x, ray.o.y, ray.o.z, ky);
        final double okz = component(ray.o.x, ray.o.y, ray.o.z, kz);
        double tMax = ray.tMax;
        int found = -1;
        double foundU = 0, foundV = 0, foundW = 0, foundDet = 1;
        for (int prim = first; prim < end; prim++) {
            int a = 3 * tri[3 * prim], b = 3 * tri[3 * prim + 1], c = 3 * tri[3 * prim + 2];
            // Vertices relative to the origin, sheared so that the ray is the z axis.
            double az0 = pos[a + kz] - okz, bz0 = pos[b + kz] - okz, cz0 = pos[c + kz] - okz;
            double axs = pos[a + kx] - okx - sx * az0, ays = pos[a + ky] - oky - sy * az0;
            double bxs = pos[b + kx] - okx - sx * bz0, bys = pos[b + ky] - oky - sy * bz0;
            double cxs = pos[c + kx] - okx - sx * cz0, cys = pos[c + ky] - oky - sy * cz0;
            // Scaled barycentrics: u of vertex a, v of b, w of c.
            double u = cxs * bys - cys * bxs;
            double v = axs * cys - ays * cxs;
            double w = bxs * ays - bys * axs;
            if (u == 0 || v == 0 || w == 0) {
                u = exact(cxs, bys, cys, bxs);
                v = exact(axs, cys, ays, cxs);
                w = exact(bxs, ays, bys, axs);
            }
            if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) {
                continue;
            }
            double det = u + v + w;
            // det < 0: the ray meets the back face (its direction along the winding normal).
            if (det == 0 || (det < 0 && cull && (flags[prim] & Geometry.CLOSED) != 0)) {
                continue;
            }
            double t = (u * az0 + v * bz0 + w * cz0) * sz / det;
            if (t > 0 && t < tMax) {
                tMax = t;
                found = prim;
                foundU = u;
                foundV = v;
                foundW = w;
                foundDet = det;
            }
        }
        if (found < 0) {
            return false;
        }
        ray.tMax = tMax;
        hit.t = tMax;
        hit.prim = found;
        hit.b1 = foundV / foundDet;
        hit.b2 = foundW / foundDet;
        assert foundU * foundDet >= 0;
        return true;
    }

    /** Whether any triangle of [first, end) blocks the ray in (0, ray.tMax); the test of {@link #triangles}, never culling. */
    static boolean trianglesOcclude(float[] pos, int[] tri, int first, int end, Ray ray) {
        final double dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
        final double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        final int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        final double dkz = kz == 0 ? dx : kz == 1 ? dy : dz;
        int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
        if (dkz < 0) {
            int tmp = kx;
            kx = ky;
            ky = tmp;
        }
        final double sz = 1 / dkz;
        final double sx = component(dx, dy, dz, kx) * sz, sy = component(dx, dy, dz, ky) * sz;
        final double okx = component(ray.o.x, ray.o.y, ray.o.z, kx);
        final double oky = component(ray.o.x, ray.o.y, ray.o.z, ky);
        final double okz = component(ray.o.x, ray.o.y, ray.o.z, kz);
        final double tMax = ray.tMax;
        for (int prim = first; prim < end; prim++) {
            int a = 3 * tri[3 * prim], b = 3 * tri[3 * prim + 1], c = 3 * tri[3 * prim + 2];
            double az0 = pos[a + kz] - okz, bz0 = pos[b + kz] - okz, cz0 = pos[c + kz] - okz;
            double axs = pos[a + kx] - okx - sx * az0, ays = pos[a + ky] - oky - sy * az0;
            double bxs = pos[b + kx] - okx - sx * bz0, bys = pos[b + ky] - oky - sy * bz0;
            double cxs = pos[c + kx] - okx - sx * cz0, cys = pos[c + ky] - oky - sy * cz0;
            double u = cxs * bys - cys * bxs;
            double v = axs * cys - ays * cxs;
            double w = bxs * ays - bys * axs;
            if (u == 0 || v == 0 || w == 0) {
                u = exact(cxs, bys, cys, bxs);
                v = exact(axs, cys, ays, cxs);
                w = exact(bxs, ays, bys, axs);
            }
            if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) {
                continue;
            }
            double det = u + v + w;
            if (det == 0) {
                continue;
            }
            double t = (u * az0 + v * bz0 + w * cz0) * sz / det;
            if (t > 0 && t < tMax) {
                return true;
            }
        }
        return false;
    }

    /**
     * a·b − c·d where the double evaluation of one edge function gave zero: the double value if
     * it is not zero, else the sign of the exact value as ±{@link Double#MIN_VALUE} (or 0), the
     * paper's fallback to higher precision, so that a ray a hair beside an edge, whose products
     * underflow or cancel, is not taken as on it. Only rays exactly through an edge's line get here.
     */
    private static double exact(double a, double b, double c, double d) {
        double e = a * b - c * d;
        if (e != 0 || !Double.isFinite(a + b + c + d)) {
            return e;
        }
        int sign = new BigDecimal(a).multiply(new BigDecimal(b)).compareTo(new BigDecimal(c).multiply(new BigDecimal(d)));
        return sign * Double.MIN_VALUE;
    }

    private static double component(double x, double y, double z, int axis) {
        return axis == 0 ? x : axis == 1 ? y : z;
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
