package dev.strahl.accel;

import dev.strahl.geometry.Ray;
import dev.strahl.geometry.RayTriangle;

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
    /** The triangle test's per-ray set-up; it also receives the scaled barycentrics of hits. */
    final RayTriangle triangle = new RayTriangle();

    /**
     * Sets up the per-ray constants of the box tests and of the triangle test without branches
     * on the direction (random rays would mispredict every one of them): selections go through
     * sign bits.
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
        triangle.prepare(ray);
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
