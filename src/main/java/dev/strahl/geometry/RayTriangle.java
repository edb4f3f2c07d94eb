package dev.strahl.geometry;

import java.math.BigDecimal;

/**
 * The watertight ray–triangle test of Woop, Benthin &amp; Wald ("Watertight Ray/Triangle
 * Intersection", JCGT 2(1), 2013), the one definition every triangle query uses: the BVH's
 * closest-hit and any-hit leaves and the loops over all triangles of {@link Geometry}. The
 * vertices are moved into a frame in which the ray runs along +z from the origin, and the three 2D
 * edge functions decide the hit. An edge shared by two triangles gives the same edge function up
 * to its sign in both, computed from the same transformed vertices, so no ray slips through
 * between them. The arithmetic is double, from the float vertices.
 *
 * <p>An instance holds the per-ray set-up ({@link #prepare}: the axis permutation, the shear and
 * the permuted origin) and receives the distance and scaled barycentrics of the hits {@link #hit}
 * reports. One per thread (a BVH traversal keeps one in its stack); never share it.
 */
public final class RayTriangle {
    /** The axes that become x, y and z: z is the axis of the direction's largest component. */
    public int kx, ky, kz;
    /** The shear that makes the direction (0, 0, 1): x −= sx·z, y −= sy·z; sz = 1 / d[kz] scales z. */
    public double sx, sy, sz;
    /** The origin's coordinates on the axes kx, ky, kz. */
    public double okx, oky, okz;
    /**
     * Of the last hit {@link #hit} reported: its distance t, the scaled barycentrics v (of vertex
     * b) and w (of vertex c), and det = u + v + w; so b1 = v / det, b2 = w / det ({@link #b1()},
     * {@link #b2()}). Divided only for the closest hit, once.
     */
    public double t, v, w, det;

    private final double[] d = new double[3], o = new double[3];

    /** Creates a test to be {@link #prepare prepared} for each ray. */
    public RayTriangle() {}

    /**
     * Sets up the per-ray constants. The axis of the largest direction component becomes z; x
     * and y follow cyclically, swapped when that component is negative so that the winding (and
     * the front face) is kept. Without branches on the direction (random rays would mispredict
     * every one of them): selections go through small arrays and sign bits.
     */
    public RayTriangle prepare(Ray ray) {
        double dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        int gxy = signBit(ay - ax), gxz = signBit(az - ax), gyz = signBit(az - ay);    // 1 where the first is larger
        int z = gxy * (2 - 2 * gxz) + (1 - gxy) * (2 - gyz);
        d[0] = dx;
        d[1] = dy;
        d[2] = dz;
        o[0] = ray.o.x;
        o[1] = ray.o.y;
        o[2] = ray.o.z;
        double dkz = d[z];
        int x0 = z + 1 - 3 * (z >> 1), y0 = x0 + 1 - 3 * (x0 >> 1);
        int neg = signBit(dkz);
        kz = z;
        kx = x0 + neg * (y0 - x0);
        ky = y0 + neg * (x0 - y0);
        sz = 1 / dkz;
        sx = d[kx] * sz;
        sy = d[ky] * sz;
        okx = o[kx];
        oky = o[ky];
        okz = o[kz];
        return this;
    }

    /** The barycentric of vertex b of the last hit. */
    public double b1() {
        return v / det;
    }

    /** The barycentric of vertex c of the last hit. */
    public double b2() {
        return w / det;
    }

    /**
     * Triangle {@code prim} of the vertex positions {@code pos} (x, y, z per vertex) and indices
     * {@code tri} (three per triangle) against the ray set up by {@link #prepare}: whether it is
     * hit at a distance in (0, tMax); if so, the hit's t, v, w and det are in this object's
     * fields. With {@code cull}, the back face (the ray along the winding normal) of a triangle
     * flagged {@link Geometry#CLOSED} in {@code flags} is no hit ({@code flags} is not read
     * without {@code cull}).
     *
     * <p>The signs of the edge functions are compared on their sign bits
     * ({@link #differentSigns}); the rare zero edge functions go to {@link #onEdgeLine}, which
     * keeps the exact arithmetic out of the common path. The BVH's loops call this method (at
     * 363 bytecodes it is over the JIT's inlining limit for hot calls, 325); a static version
     * that the JIT inlined, with the set-up in the loops' locals, measured no faster
     * (docs/performance.md, round 4).
     */
    public boolean hit(float[] pos, int[] tri, byte[] flags, int prim, double tMax, boolean cull) {
        return hit(pos, 3 * tri[3 * prim], 3 * tri[3 * prim + 1], 3 * tri[3 * prim + 2], 1, flags, prim, tMax, cull);
    }

    /**
     * {@link #hit(float[], int[], byte[], int, double, boolean)} with the vertices' places given:
     * coordinate k of vertex a is {@code v[a + stride·k]}, of b and c likewise. The BVH's scalar
     * kernel passes a lane of its leaf blocks (stride 4, the coordinates of four triangles side by
     * side); the same float values give the same bits. Its Vector API kernel runs these very
     * operations, in this order, on four lanes at once.
     */
    public boolean hit(float[] pos, int a, int b, int c, int stride, byte[] flags, int prim, double tMax, boolean cull) {
        int x = stride * kx, y = stride * ky, z = stride * kz;
        // Vertices relative to the origin, sheared so that the ray is the z axis.
        double az0 = pos[a + z] - okz, bz0 = pos[b + z] - okz, cz0 = pos[c + z] - okz;
        double axs = pos[a + x] - okx - sx * az0, ays = pos[a + y] - oky - sy * az0;
        double bxs = pos[b + x] - okx - sx * bz0, bys = pos[b + y] - oky - sy * bz0;
        double cxs = pos[c + x] - okx - sx * cz0, cys = pos[c + y] - oky - sy * cz0;
        // Scaled barycentrics: u of vertex a, v of b, w of c.
        double u = cxs * bys - cys * bxs;
        double v = axs * cys - ays * cxs;
        double w = bxs * ays - bys * axs;
        if (differentSigns(u, v, w)) {
            return false;
        }
        if (u == 0 || v == 0 || w == 0) {
            return onEdgeLine(axs, ays, bxs, bys, cxs, cys, az0, bz0, cz0, tMax, cull, flags, prim);
        }
        return record(u, v, w, az0, bz0, cz0, tMax, cull, flags, prim);
    }

    /**
     * {@link #hit} where an edge function is zero in double, so that the ray may run exactly
     * through an edge's line: the exact values decide ({@link #exact}; only the zeros can change).
     */
    private boolean onEdgeLine(double axs, double ays, double bxs, double bys, double cxs, double cys,
                               double az0, double bz0, double cz0, double tMax, boolean cull, byte[] flags, int prim) {
        double u = exact(cxs, bys, cys, bxs);
        double v = exact(axs, cys, ays, cxs);
        double w = exact(bxs, ays, bys, axs);
        if (differentSigns(u, v, w) || u + v + w == 0) {
            return false;
        }
        return record(u, v, w, az0, bz0, cz0, tMax, cull, flags, prim);
    }

    /** The end of {@link #hit} for edge functions of one sign (not all zero): culling, the distance, the record. */
    private boolean record(double u, double v, double w, double az0, double bz0, double cz0, double tMax,
                           boolean cull, byte[] flags, int prim) {
        double det = u + v + w;
        // det < 0: the ray meets the back face (its direction along the winding normal).
        if (det < 0 && cull && (flags[prim] & Geometry.CLOSED) != 0) {
            return false;
        }
        double t = (u * az0 + v * bz0 + w * cz0) * sz / det;
        if (!(t > 0 && t < tMax)) {
            return false;
        }
        this.t = t;
        this.v = v;
        this.w = w;
        this.det = det;
        return true;
    }

    /**
     * {@code (u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)} with one branch instead of
     * up to six, each of which a random ray mispredicts: the sign bit of {@code x + 0} is set
     * exactly when x &lt; 0 (the addition turns −0 into +0), that of {@code 0 − x} exactly when
     * x &gt; 0. A NaN may count either way; it gives no hit either way (its t is NaN).
     */
    private static boolean differentSigns(double u, double v, double w) {
        long below = Double.doubleToRawLongBits(u + 0.0) | Double.doubleToRawLongBits(v + 0.0) | Double.doubleToRawLongBits(w + 0.0);
        long above = Double.doubleToRawLongBits(0.0 - u) | Double.doubleToRawLongBits(0.0 - v) | Double.doubleToRawLongBits(0.0 - w);
        return (below & above) < 0;
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

    private static int signBit(double x) {
        return (int) (Double.doubleToRawLongBits(x) >>> 63);
    }
}
