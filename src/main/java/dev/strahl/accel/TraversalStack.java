package dev.strahl.accel;

import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.RayTriangle;

/**
 * Per-thread working memory of a traversal: the nodes still to visit with the key at which the
 * ray enters each (so that a node farther than the closest hit found meanwhile is skipped without
 * touching its boxes again), the per-ray constants of the box and triangle tests, set up once per
 * ray by {@link #prepare}, and scratch for the kernels and the batch queries. Never share one
 * between threads.
 */
public final class TraversalStack {
    /** Node references still to visit, and their keys ({@link ScalarKernel#key}): both grow upwards. */
    final int[] refs = new int[BvhLayout.STACK_SIZE];
    final int[] keys = new int[BvhLayout.STACK_SIZE];
    /** The keys of one node's eight children (or -1 for those the ray misses). */
    final int[] lanes = new int[BvhLayout.WIDTH];
    /** A leaf block's per-lane results, read back on a hit: t, the scaled barycentrics v, w and det. */
    final double[] laneT = new double[BvhLayout.LANES], laneV = new double[BvhLayout.LANES],
            laneW = new double[BvhLayout.LANES], laneDet = new double[BvhLayout.LANES];

    // Slab test: inverse direction, offsets of the near and far planes in a node, origin bounds for near and far planes.
    float ix, iy, iz;
    int nx, ny, nz, fx, fy, fz;
    float onx, ony, onz, ofx, ofy, ofz;
    /** The triangle test's per-ray set-up; it also receives the scaled barycentrics of hits. */
    final RayTriangle triangle = new RayTriangle();

    /** The ray and hit record of a batch query's current ray. */
    final Ray ray = new Ray();
    final Hit hit = new Hit();

    /** Creates the working memory of one thread's traversals. */
    public TraversalStack() {}

    /**
     * Sets up the per-ray constants of the box tests (in float) and of the triangle test (in
     * double, as {@link RayTriangle} defines it) without branches on the direction: random rays
     * would mispredict every one of them, so selections go through sign bits.
     */
    void prepare(Ray ray) {
        double ox = ray.o.x, oy = ray.o.y, oz = ray.o.z;
        // Float division: within 1 ulp of 1/d, as the traversal's margin assumes.
        ix = 1 / (float) ray.d.x;
        iy = 1 / (float) ray.d.y;
        iz = 1 / (float) ray.d.z;
        int sgx = Float.floatToRawIntBits(ix) >>> 31, sgy = Float.floatToRawIntBits(iy) >>> 31, sgz = Float.floatToRawIntBits(iz) >>> 31;
        // The near plane is the minimum for a positive direction, the maximum (3 planes on) for a negative one.
        int w3 = 3 * BvhLayout.WIDTH;
        nx = w3 * sgx;
        ny = BvhLayout.WIDTH + w3 * sgy;
        nz = 2 * BvhLayout.WIDTH + w3 * sgz;
        fx = nx + w3 - 2 * w3 * sgx;
        fy = ny + w3 - 2 * w3 * sgy;
        fz = nz + w3 - 2 * w3 * sgz;
        // Near planes take the upper origin bound for a positive direction, the lower one for a
        // negative: with sign s = ±1, s·above(s·o) is above(o) or below(o) (negations are exact).
        double sx = Math.copySign(1.0, ix), sy = Math.copySign(1.0, iy), sz = Math.copySign(1.0, iz);
        onx = (float) sx * above(sx * ox);
        ofx = (float) -sx * above(-sx * ox);
        ony = (float) sy * above(sy * oy);
        ofy = (float) -sy * above(-sy * oy);
        onz = (float) sz * above(sz * oz);
        ofz = (float) -sz * above(-sz * oz);
        triangle.prepare(ray);
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
