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
    /** The stack's size, where the SIMD kernel's node visits ({@link SimdKernel}) hand it over. */
    int sp;
    /** The keys of one node's eight children (or -1 for those the ray misses). */
    final int[] lanes = new int[BvhLayout.WIDTH];
    /** The distance of a leaf block's nearest hit ({@link SimdKernel}), infinite for none, and the block's scaled barycentrics. */
    double bestT;
    final double[] laneV = new double[BvhLayout.LANES], laneW = new double[BvhLayout.LANES], laneDet = new double[BvhLayout.LANES];

    // Slab test: inverse direction, offsets of the near and far planes in a node, origin bounds for near and far planes.
    float ix, iy, iz;
    int nx, ny, nz, fx, fy, fz;
    float onx, ony, onz, ofx, ofy, ofz;
    /** The triangle test's per-ray set-up; it also receives the scaled barycentrics of hits. */
    final RayTriangle triangle = new RayTriangle();

    /** The ray and hit record of a batch query's current ray. */
    final Ray ray = new Ray();
    final Hit hit = new Hit();

    /** A ray moved into an instance's coordinates and its hit ({@link TwoLevelBvh}). */
    final Ray instanceRay = new Ray();
    final Hit instanceHit = new Hit();
    /** The top-level tree's nodes still to visit and their entry distances, and its ray set-up ({@link InstanceTree}). */
    final int[] topNodes = new int[InstanceTree.MAX_DEPTH];
    final double[] topEntries = new double[InstanceTree.MAX_DEPTH];
    double topOx, topOy, topOz, topIx, topIy, topIz;

    /** What the scalar kernel visited, where it counts ({@link ScalarKernel#COUNT}). */
    long nodeVisits, blockTests;

    /** Node visits counted so far (only with {@code -Dstrahl.countVisits=true}, by the scalar kernel). */
    public long nodeVisits() {
        return nodeVisits;
    }

    /** Leaf blocks tested so far (as {@link #nodeVisits()}). */
    public long blockTests() {
        return blockTests;
    }

    /** Creates the working memory of one thread's traversals. */
    public TraversalStack() {}

    /**
     * Sets up the per-ray constants of the box tests (in float) and of the triangle test (in
     * double, as {@link RayTriangle} defines it) without branches on the direction: random rays
     * would mispredict every one of them, so selections go through sign bits.
     */
    void prepare(Ray ray) {
        double ox = ray.o.x, oy = ray.o.y, oz = ray.o.z, dx = ray.d.x, dy = ray.d.y, dz = ray.d.z;
        // Float division: within 1 ulp of 1/d, as the traversal's margin assumes.
        ix = 1 / (float) dx;
        iy = 1 / (float) dy;
        iz = 1 / (float) dz;
        int sgx = Float.floatToRawIntBits(ix) >>> 31, sgy = Float.floatToRawIntBits(iy) >>> 31, sgz = Float.floatToRawIntBits(iz) >>> 31;
        // The near plane is the minimum for a positive direction, the maximum (3 planes on) for a negative one.
        int w3 = 3 * BvhLayout.WIDTH;
        nx = w3 * sgx;
        ny = BvhLayout.WIDTH + w3 * sgy;
        nz = 2 * BvhLayout.WIDTH + w3 * sgz;
        fx = nx + w3 - 2 * w3 * sgx;
        fy = ny + w3 - 2 * w3 * sgy;
        fz = nz + w3 - 2 * w3 * sgz;
        // Origin bounds: o ± e with e = |o|·2^-22 + 2^-126 (at least two float spacings around o, and
        // more than the smallest normal float) rounded to float lie on either side of o. Near
        // planes take the upper bound for a positive direction, the lower one for a negative.
        double ex = Math.copySign(Math.abs(ox) * 0x1p-22 + 0x1p-126, dx);
        double ey = Math.copySign(Math.abs(oy) * 0x1p-22 + 0x1p-126, dy);
        double ez = Math.copySign(Math.abs(oz) * 0x1p-22 + 0x1p-126, dz);
        onx = (float) (ox + ex);
        ofx = (float) (ox - ex);
        ony = (float) (oy + ey);
        ofy = (float) (oy - ey);
        onz = (float) (oz + ez);
        ofz = (float) (oz - ez);
        triangle.prepare(ray);
    }
}
