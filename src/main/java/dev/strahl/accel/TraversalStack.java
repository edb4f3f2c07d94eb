package dev.strahl.accel;

import dev.strahl.geometry.Ray;

/**
 * Per-thread working memory of a BVH traversal: the nodes still to visit with the distance at
 * which the ray enters each (so that a node farther than the closest hit found meanwhile is
 * skipped without touching its box again), and the per-ray constants of the box and triangle
 * tests, set up once per ray by {@link #prepare}. Never share one between threads.
 */
public final class TraversalStack {
    final int[] refs = new int[Bvh.STACK_SIZE];
    /** Entry distances as float bits (non-negative floats order like their bits). */
    final int[] dist = new int[Bvh.STACK_SIZE];
    /** The four children's entry distances (or -1) of the node being visited. */
    final int[] lanes = new int[4];

    // Slab test: inverse direction, offsets of the near planes in a node, origin bounds for near and far planes.
    float ix, iy, iz;
    int nx, ny, nz;
    float onx, ony, onz, ofx, ofy, ofz;
    // Triangle test (Woop et al. 2013): axis permutation, shear and the permuted origin.
    int kx, ky, kz;
    double sx, sy, sz, okx, oky, okz;

    private final double[] d = new double[3], o = new double[3];

    /**
     * Sets up the per-ray constants without branches on the direction (random rays would
     * mispredict every one of them): selections go through small arrays and sign bits.
     */
    void prepare(Ray ray) {
        double ox = ray.o.x, oy = ray.o.y, oz = ray.o.z, dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
        // Float division: within 1 ulp of 1/d, as the traversal's margin assumes.
        ix = 1 / (float) dx;
        iy = 1 / (float) dy;
        iz = 1 / (float) dz;
        int sgx = Float.floatToRawIntBits(ix) >>> 31, sgy = Float.floatToRawIntBits(iy) >>> 31, sgz = Float.floatToRawIntBits(iz) >>> 31;
        nx = 12 * sgx;
        ny = 4 + 12 * sgy;
        nz = 8 + 12 * sgz;
        // Near planes take the upper origin bound for a positive direction, the lower one for a negative.
        float lox = below(ox), hix = above(ox), loy = below(oy), hiy = above(oy), loz = below(oz), hiz = above(oz);
        onx = pick(sgx, hix, lox);
        ofx = pick(sgx, lox, hix);
        ony = pick(sgy, hiy, loy);
        ofy = pick(sgy, loy, hiy);
        onz = pick(sgz, hiz, loz);
        ofz = pick(sgz, loz, hiz);

        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        int gxy = signBit(ay - ax), gxz = signBit(az - ax), gyz = signBit(az - ay);    // 1 where the first is larger
        int z = gxy * (2 - 2 * gxz) + (1 - gxy) * (2 - gyz);
        d[0] = dx;
        d[1] = dy;
        d[2] = dz;
        o[0] = ox;
        o[1] = oy;
        o[2] = oz;
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
    }

    private static int signBit(double v) {
        return (int) (Double.doubleToRawLongBits(v) >>> 63);
    }

    /** {@code sign == 0 ? positive : negative}, without a branch. */
    private static float pick(int sign, float positive, float negative) {
        int m = -sign;
        return Float.intBitsToFloat((Float.floatToRawIntBits(positive) & ~m) | (Float.floatToRawIntBits(negative) & m));
    }

    /** The float strictly above the double v (which lies strictly between {@link #below} and this). */
    static float above(double v) {
        float f = (float) v + 0f;                     // + 0 turns -0 into +0
        int b = Float.floatToRawIntBits(f);
        return Float.intBitsToFloat(b + 1 + 2 * (b >> 31));
    }

    /** The float strictly below the double v. */
    static float below(double v) {
        return -above(-v);
    }
}
