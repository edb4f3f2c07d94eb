package dev.strahl.accel;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.RayTriangle;

/**
 * A four-wide bounding volume hierarchy over the primitives of a {@link Geometry}, in two flat
 * arrays. Built by {@link BvhBuilder}, which also reorders the primitives so that every leaf is a
 * contiguous range of {@link #geometry()}: hits name primitives of that geometry, not of the one
 * the hierarchy was built from. Immutable and shared by all render threads; each thread passes
 * its own {@link TraversalStack}.
 *
 * <p>Node i is {@value #NODE} floats at {@code nodes[28i ..]}, its four children's boxes and then the
 * children themselves (as float bits), so that a visit touches two cache lines: the boxes
 * coordinate by coordinate ({@code nodes[28i + 4k + c]} is coordinate k of child c, k = min x,
 * min y, min z, max x, max y, max z), so that the four slab tests read neighbouring values; then
 * the children at {@code nodes[28i + 24 + c]}: an interior node's index (≥ 0), a leaf as
 * {@link #leaf(int, int)} (sign bit set, first primitive, count), or {@link #EMPTY} (with an
 * empty box, which no ray enters). That is 112 bytes per node and about a third as many nodes
 * as leaves; the leaves' triangles are a copy of their vertices in leaf order (36 bytes each).
 */
public final class Bvh {
    /** Depth limit of the four-wide tree; the builder's median fallback keeps real trees far below. */
    static final int MAX_DEPTH = 80;
    /** Traversal stack entries: an interior node pushes at most three siblings per level. */
    public static final int STACK_SIZE = 3 * MAX_DEPTH + 4;
    /** A child slot without a child. */
    static final int EMPTY = Integer.MIN_VALUE;
    /** Largest error of a float slab distance in ulps, with room to spare (see {@link #intersect}). */
    private static final int MARGIN_ULPS = 8;

    private final Geometry geometry;
    private final int triangleCount;
    private final byte[] flags;
    /** The triangles' vertices in primitive (leaf) order, 9 floats each: no index lookup, a leaf's in one run. */
    private final float[] verts;
    /** Floats per node: 24 box coordinates, 4 children (their int bits). */
    static final int NODE = 28;
    private final float[] nodes;
    private final int nodeCount;
    /** Whether box tests take the Vector API path ({@link SimdNodes}). */
    private final boolean simd;
    /** Teaching option ({@code --accel none}): queries ignore the tree and test every primitive ({@link #bruteForce()}). */
    private final boolean bruteForce;

    Bvh(Geometry geometry, float[] nodes, int nodeCount) {
        this(geometry, nodes, nodeCount, SimdNodes.AVAILABLE, false, BvhWriter.leafVertices(geometry));
    }

    private Bvh(Geometry geometry, float[] nodes, int nodeCount, boolean simd, boolean bruteForce, float[] verts) {
        this.geometry = geometry;
        this.triangleCount = geometry.triangleCount();
        this.flags = geometry.flagArray();
        this.verts = verts;
        this.nodes = nodes;
        this.nodeCount = nodeCount;
        this.simd = simd;
        this.bruteForce = bruteForce;
    }

    /** The same tree with box tests on the Vector API path or not (for tests and benchmarks comparing the two). */
    Bvh withSimd(boolean on) {
        if (on && !SimdNodes.AVAILABLE) {
            throw new IllegalStateException("the Vector API path needs --add-modules jdk.incubator.vector");
        }
        return new Bvh(geometry, nodes, nodeCount, on, bruteForce, verts);
    }

    /**
     * Teaching option ({@code --accel none}): the same primitives without the tree, every query
     * testing every primitive in a loop, as a first ray tracer does (docs/experiments.md measures
     * what the tree buys). The arithmetic is {@link Geometry}'s, which the tree's leaves share, so
     * it finds the same hits; only the order in which primitives are tried differs.
     */
    public Bvh bruteForce() {
        return new Bvh(geometry, nodes, nodeCount, simd, true, verts);
    }

    /** Whether this is the brute-force loop of {@link #bruteForce()}. */
    public boolean isBruteForce() {
        return bruteForce;
    }

    /** Whether box tests use the Vector API (the JVM runs with {@code --add-modules jdk.incubator.vector}). */
    public boolean usesSimd() {
        return simd;
    }

    /**
     * Builds the hierarchy with a binned surface-area heuristic. The returned tree's
     * {@link #geometry()} holds the same primitives as {@code geometry} in leaf order; use it,
     * not the argument, to look up hits.
     */
    public static Bvh build(Geometry geometry) {
        return new BvhBuilder(geometry, Runtime.getRuntime().availableProcessors()).build();
    }

    /** The primitives, in the order of the leaves; the primitive ids of hits refer to it. */
    public Geometry geometry() {
        return geometry;
    }

    public int nodeCount() {
        return nodeCount;
    }

    /** Bytes held by the node arrays and the leaf-ordered triangle vertices. */
    public long byteSize() {
        return 4L * nodes.length + 4L * verts.length;
    }

    /** A leaf child reference: {@code count} primitives from {@code first} on. */
    static int leaf(int first, int count) {
        if (first < 0 || first >= 1 << 28 || count < 1 || count > 7) {
            throw new IllegalArgumentException("leaf out of range: first " + first + ", count " + count);
        }
        return Integer.MIN_VALUE | first << 3 | count;
    }

    static int leafFirst(int ref) {
        return (ref & Integer.MAX_VALUE) >>> 3;
    }

    static int leafCount(int ref) {
        return ref & 7;
    }

    /** The node arrays themselves (not copies), for structural checks by tests in this package. */
    record Layout(float[] nodes) {
        /** Coordinate k (min x, y, z, max x, y, z) of child c's box in node i. */
        float box(int i, int k, int c) {
            return nodes[NODE * i + 4 * k + c];
        }

        int child(int i, int c) {
            return Float.floatToRawIntBits(nodes[NODE * i + 24 + c]);
        }
    }

    Layout layout() {
        return new Layout(nodes);
    }

    /**
     * The slab test of node {@code node}'s four children for a ray, as the traversal runs it:
     * entry distances (float bits) or -1 into {@code stack.lanes}. For micro-benchmarks and tests.
     */
    void testNode(int node, Ray ray, TraversalStack stack) {
        TraversalStack s = stack;
        s.prepare(ray);
        childEntries(nodes, NODE * node, s.nx, s.ny, s.nz, s.onx, s.ony, s.onz, s.ofx, s.ofy, s.ofz, s.ix, s.iy, s.iz,
                bits(BvhBuilder.roundUp(ray.tMax)), s.lanes);
    }

    /** Allocates a traversal stack for one thread. */
    public static TraversalStack newStack() {
        return new TraversalStack();
    }

    /**
     * Finds the closest hit in (0, ray.tMax): on success fills {@code hit} and shortens
     * {@code ray.tMax}. At an interior node the four children's boxes are tested; those the ray
     * enters are visited nearest first, the others pushed with their entry distance, so that a
     * node farther than a hit found meanwhile is dropped without another look. Triangles are
     * tested with {@link RayTriangle} (the watertight test of Woop et al. 2013), as
     * {@link Geometry#intersect(int, int, Ray, Hit, boolean)} does, so both give the same bits;
     * its per-ray set-up is done once per ray, with the box tests' ({@link TraversalStack#prepare}).
     *
     * <p>The slab tests run in float, kept conservative (never losing a box the exact ray
     * touches): the origin is bounded by the floats just below and above it and each slab uses
     * the bound that makes its distance err outwards; the remaining rounding of one subtraction,
     * one product and the float inverse (under 2 ulp on each end) is covered by
     * {@link #MARGIN_ULPS}. Distances are compared as float bits (see {@link #entry}).
     *
     * @param cullBackFaces ignore back faces of closed meshes (camera and continuation rays only)
     */
    public boolean intersect(Ray ray, Hit hit, TraversalStack stack, boolean cullBackFaces) {
        if (nodeCount == 0) {
            return false;
        }
        if (bruteForce) {
            return everyPrimitive(ray, hit, stack, cullBackFaces);
        }
        stack.prepare(ray);
        return closestHit(ray, hit, stack, cullBackFaces);
    }

    /**
     * {@code --accel none}: the closest hit among all triangles, with the leaves' test and the
     * thread's {@link RayTriangle} (nothing allocated per ray), then among all spheres.
     */
    private boolean everyPrimitive(Ray ray, Hit hit, TraversalStack stack, boolean cullBackFaces) {
        stack.prepare(ray);
        final RayTriangle tr = stack.triangle;
        double tHit = ray.tMax;
        int found = -1;
        for (int prim = 0; prim < triangleCount; prim++) {
            if (tr.hit(verts, 9 * prim, 9 * prim + 3, 9 * prim + 6, flags, prim, tHit, cullBackFaces)) {
                tHit = tr.t;
                found = prim;
            }
        }
        int spheres = geometry.primitiveCount() - triangleCount;
        if (spheres > 0) {
            ray.tMax = tHit;
            if (geometry.intersect(triangleCount, spheres, ray, hit, cullBackFaces)) {
                tHit = hit.t;
                found = hit.prim;
            }
        }
        return finish(ray, hit, found, tHit, tr);
    }

    /** {@code --accel none}: whether any primitive blocks the ray, tested one after another. */
    private boolean anyPrimitive(Ray ray, TraversalStack stack) {
        stack.prepare(ray);
        final RayTriangle tr = stack.triangle;
        for (int prim = 0; prim < triangleCount; prim++) {
            if (tr.hit(verts, 9 * prim, 9 * prim + 3, 9 * prim + 6, flags, prim, ray.tMax, false)) {
                return true;
            }
        }
        int spheres = geometry.primitiveCount() - triangleCount;
        return spheres > 0 && geometry.occludes(triangleCount, spheres, ray);
    }

    /**
     * The traversal loop of {@link #intersect}, in a method of its own: the per-ray set-up is
     * inlined into its caller, not into the loop, where it made the loop slower (both
     * measured: docs/performance.md, round 4). The loop keeps the box tests' set-up in locals
     * (reading it from the stack's fields made shadow rays about 5 % slower).
     */
    private boolean closestHit(Ray ray, Hit hit, TraversalStack stack, boolean cullBackFaces) {
        final float ix = stack.ix, iy = stack.iy, iz = stack.iz;
        final int nx = stack.nx, ny = stack.ny, nz = stack.nz;
        final float onx = stack.onx, ony = stack.ony, onz = stack.onz, ofx = stack.ofx, ofy = stack.ofy, ofz = stack.ofz;
        final RayTriangle tr = stack.triangle;
        final float[] verts = this.verts;
        final float[] box = nodes;
        final int[] refs = stack.refs;
        final int[] dist = stack.dist;
        final int[] lanes = stack.lanes;
        double tHit = ray.tMax;
        int tMax = bits(BvhBuilder.roundUp(tHit));
        int found = -1;
        int sp = 0;
        int ref = 0;
        while (true) {
            if (ref >= 0) {
                int o = NODE * ref;
                int c = o + 24;
                int base = sp;
                childEntries(box, o, nx, ny, nz, onx, ony, onz, ofx, ofy, ofz, ix, iy, iz, tMax, lanes);
                for (int k = 0; k < 4; k++) {
                    // Written always, kept only on a hit: no branch to mispredict.
                    int t = lanes[k];
                    refs[sp] = Float.floatToRawIntBits(box[c + k]);
                    dist[sp] = t;
                    sp += ~t >>> 31;
                }
                int pushed = sp - base;
                if (pushed > 0) {
                    // One bubble pass brings the nearest entry to the top; the rest stay pushed
                    // (and are skipped on pop if a hit comes closer).
                    for (int i = base; i < sp - 1; i++) {
                        orderPair(refs, dist, i);
                    }
                    ref = refs[--sp];
                    continue;
                }
            } else {
                int first = leafFirst(ref), end = first + leafCount(ref);
                if (first < triangleCount) {
                    boolean closer = false;
                    for (int prim = first, a = 9 * first; prim < end; prim++, a += 9) {
                        if (tr.hit(verts, a, a + 3, a + 6, flags, prim, tHit, cullBackFaces)) {
                            tHit = tr.t;
                            found = prim;
                            closer = true;
                        }
                    }
                    if (closer) {
                        tMax = bits(BvhBuilder.roundUp(tHit));
                    }
                } else {
                    ray.tMax = tHit;
                    if (geometry.intersect(first, end - first, ray, hit, cullBackFaces)) {
                        tHit = hit.t;
                        found = hit.prim;
                        tMax = bits(BvhBuilder.roundUp(tHit));
                    }
                }
            }
            // Pop the next node the ray enters before the closest hit so far.
            int cut = tMax + MARGIN_ULPS;
            do {
                if (sp == 0) {
                    return finish(ray, hit, found, tHit, tr);
                }
                ref = refs[--sp];
            } while (dist[sp] > cut);
        }
    }

    /** Records the closest hit; a triangle's barycentrics are in {@code tr}, which holds the last triangle hit it reported. */
    private boolean finish(Ray ray, Hit hit, int found, double t, RayTriangle tr) {
        if (found < 0) {
            return false;
        }
        ray.tMax = t;
        hit.t = t;
        hit.prim = found;
        if (found < triangleCount) {
            hit.b1 = tr.b1();
            hit.b2 = tr.b2();
        }
        return true;
    }

    /** Whether anything blocks the ray in (0, ray.tMax); stops at the first blocker found. */
    public boolean occluded(Ray ray, TraversalStack stack) {
        if (nodeCount == 0) {
            return false;
        }
        if (bruteForce) {
            return anyPrimitive(ray, stack);
        }
        stack.prepare(ray);
        return anyHit(ray, stack);
    }

    /** The traversal loop of {@link #occluded}, apart from its set-up as in {@link #closestHit}. */
    private boolean anyHit(Ray ray, TraversalStack stack) {
        final float ix = stack.ix, iy = stack.iy, iz = stack.iz;
        final int nx = stack.nx, ny = stack.ny, nz = stack.nz;
        final float onx = stack.onx, ony = stack.ony, onz = stack.onz, ofx = stack.ofx, ofy = stack.ofy, ofz = stack.ofz;
        final RayTriangle tr = stack.triangle;
        final double tHit = ray.tMax;
        final int tMax = bits(BvhBuilder.roundUp(tHit));
        final float[] verts = this.verts;
        final float[] box = nodes;
        final int[] refs = stack.refs;
        final int[] lanes = stack.lanes;
        int sp = 0;
        int ref = 0;
        while (true) {
            if (ref >= 0) {
                int o = NODE * ref;
                childEntries(box, o, nx, ny, nz, onx, ony, onz, ofx, ofy, ofz, ix, iy, iz, tMax, lanes);
                // Unordered: sorting cost more than it found blockers sooner (docs/performance.md).
                for (int k = 0; k < 4; k++) {
                    refs[sp] = Float.floatToRawIntBits(box[o + 24 + k]);
                    sp += ~lanes[k] >>> 31;
                }
            } else {
                int first = leafFirst(ref), end = first + leafCount(ref);
                if (first >= triangleCount) {
                    if (geometry.occludes(first, end - first, ray)) {
                        return true;
                    }
                } else {
                    for (int prim = first, a = 9 * first; prim < end; prim++, a += 9) {
                        if (tr.hit(verts, a, a + 3, a + 6, flags, prim, tHit, false)) {
                            return true;
                        }
                    }
                }
            }
            if (sp == 0) {
                return false;
            }
            ref = refs[--sp];
        }
    }

    /**
     * Slab test (Kay &amp; Kajiya 1986) of one child box for t in [0, tMax]: the distance at
     * which the ray enters it as float bits, or -1 if it misses. {@code o} is the node's box
     * offset plus the child slot; n* are the offsets of the near planes on each axis (the far
     * ones are the other half of the node).
     *
     * <p>Maximum and minimum are taken on the float bits as ints, which is exact for
     * non-negative floats and one conditional move each, where {@link Math#max(float, float)}
     * costs several instructions for its NaN and −0 rules. A negative slab distance then counts
     * as below every non-negative one, which is all the test needs: entry distances are clamped
     * at 0, and any negative exit distance means a miss.
     */
    private static int entry(float[] box, int o, int nx, int ny, int nz, float onx, float ony, float onz,
                             float ofx, float ofy, float ofz, float ix, float iy, float iz, int tMaxBits) {
        int tn = Math.max(Math.max(bits((box[o + nx] - onx) * ix), bits((box[o + ny] - ony) * iy)),
                Math.max(bits((box[o + nz] - onz) * iz), 0));
        int tf = Math.min(Math.min(bits((box[o + (nx ^ 12)] - ofx) * ix), bits((box[o + (ny ^ 20)] - ofy) * iy)),
                Math.min(bits((box[o + (nz ^ 28)] - ofz) * iz), tMaxBits));
        return tn <= tf + MARGIN_ULPS ? tn : -1;
    }


    /**
     * The entry distances (float bits) of the four children of the node whose boxes start at
     * {@code o}, or -1 for those the ray misses, into {@code lanes}; on the Vector API path or
     * the scalar one. The box set-up comes as arguments, kept in locals by the traversal loops.
     */
    private void childEntries(float[] box, int o, int nx, int ny, int nz, float onx, float ony, float onz,
                              float ofx, float ofy, float ofz, float ix, float iy, float iz, int tMax, int[] lanes) {
        if (simd) {
            SimdNodes.entries(box, o, nx, ny, nz, onx, ony, onz, ofx, ofy, ofz, ix, iy, iz, tMax, MARGIN_ULPS, lanes);
        } else {
            for (int k = 0; k < 4; k++) {
                lanes[k] = entry(box, o + k, nx, ny, nz, onx, ony, onz, ofx, ofy, ofz, ix, iy, iz, tMax);
            }
        }
    }

    private static int bits(float f) {
        return Float.floatToRawIntBits(f);
    }


    /** Puts the nearer of entries i and i + 1 on top (at i + 1), without a branch. */
    private static void orderPair(int[] refs, int[] dist, int i) {
        int d0 = dist[i], d1 = dist[i + 1], r0 = refs[i], r1 = refs[i + 1];
        int m = (d0 - d1) >> 31;                     // -1 if d0 < d1 (both are non-negative)
        dist[i] = Math.max(d0, d1);
        dist[i + 1] = Math.min(d0, d1);
        refs[i] = (r0 & ~m) | (r1 & m);
        refs[i + 1] = (r1 & ~m) | (r0 & m);
    }

}
