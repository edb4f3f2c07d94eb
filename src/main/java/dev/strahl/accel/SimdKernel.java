package dev.strahl.accel;

import static dev.strahl.accel.BvhLayout.BLOCK;
import static dev.strahl.accel.BvhLayout.BLOCK_PRIMS;
import static dev.strahl.accel.BvhLayout.LANES;
import static dev.strahl.accel.BvhLayout.NODE;
import static dev.strahl.accel.ScalarKernel.bits;
import static dev.strahl.accel.ScalarKernel.child;

import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.RayTriangle;
import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.IntVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * The traversal of {@link Bvh} with the incubating Vector API (JEP 414): a node's eight child
 * boxes in one 8-lane slab test, a leaf block's four triangles in one 4-lane watertight test.
 * Loaded only where {@link Simd#AVAILABLE}; {@link ScalarKernel} is its twin and the reference:
 * the same operations, lane by lane, on the same values, and the same order of visits, so both
 * give the same bits. The traversal loop is the twin's; only the node and the block tests run in
 * lanes.
 *
 * <p>The lane work sits in methods of its own ({@link #visit}, {@link #blockTest})
 * that take and return plain values: C2 (JDK 17) stops inlining into a method once its graph is
 * large, and the Vector API's calls are large before they are optimised; a vector crossing a call
 * that was not inlined is allocated on the heap. Kept apart, each is compiled whole, and the
 * loop allocates nothing.
 *
 * <p>Within them, no vector or mask is used on only one side of a branch whose sides meet again:
 * the lane work comes first, then the decisions, on plain values; a branch amid the lane work may
 * only return. C2 (JDK 17) guards a lane operation with a check of its operand's class, which makes a
 * new value of that operand on one side only; where the sides meet, C2 merges the two, and a
 * merged vector is a heap object, allocated on every call. Whether that happens depended on the
 * profile C2 compiled with: {@code if (cull && hits.and(...).anyTrue())} cost two allocations a
 * leaf block once the warm-up ({@link SimdWarmUp}, whose rays cull) had compiled the kernel, and
 * none where only the renderer's rays had (docs/performance.md, round 7).
 *
 * <p>Leaf block: the triangle test of {@link RayTriangle} in double lanes, from the block's float
 * vertices. A lane with an edge function of exactly zero (a ray through an edge's line) sends the
 * block to {@link RayTriangle} itself, whose exact fallback decides; so does a back face to cull.
 * Of the lanes that hit, the nearest (the first of equal ones, as the scalar loop keeps) is found
 * in lanes; it and its scaled barycentrics are read back only where it is closer than the hit so far.
 */
final class SimdKernel {
    private SimdKernel() {}

    private static final VectorSpecies<Float> F8 = FloatVector.SPECIES_256;
    private static final VectorSpecies<Integer> I8 = IntVector.SPECIES_256;
    private static final VectorSpecies<Float> F4 = FloatVector.SPECIES_128;
    private static final VectorSpecies<Double> D4 = DoubleVector.SPECIES_256;
    private static final IntVector SLOTS = IntVector.fromArray(I8, new int[] {0, 1, 2, 3, 4, 5, 6, 7}, 0);

    /** What {@link #visit} returns where the ray enters no child: the next node comes off the stack. */
    static final int POP = BvhLayout.EMPTY;

    /** The closest hit in (0, ray.tMax), or false; see {@link Bvh#intersect}. */
    static boolean closestHit(Bvh bvh, Ray ray, Hit hit, TraversalStack s, boolean cull) {
        final float[] nodes = bvh.nodes, blocks = bvh.blocks;
        final int[] refs = s.refs, keys = s.keys;
        final RayTriangle tr = s.triangle;
        double tHit = ray.tMax;
        int tMaxBits = ScalarKernel.tMaxBits(tHit);
        int found = -1;
        s.sp = 0;
        int ref = 0;
        while (true) {
            if (ref >= 0) {
                ref = visit(nodes, NODE * ref, s, tMaxBits, true);
                if (ref != POP) {
                    continue;
                }
            } else if (!BvhLayout.isSphereLeaf(ref)) {
                for (int b = BvhLayout.firstBlock(ref), end = b + BvhLayout.blockCount(ref); b < end; b++) {
                    int o = BLOCK * b;
                    int prim = BvhLayout.firstPrim(bits(blocks[o + BLOCK_PRIMS]));
                    int lane = blockTest(blocks, o, tr, tHit, cull, false, s);
                    if (lane >= 0) {
                        double t = s.bestT;                   // infinite where no lane hit
                        if (t < tHit) {
                            tHit = t;
                            found = prim + lane;
                            tr.t = t;
                            tr.v = s.laneV[lane];
                            tr.w = s.laneW[lane];
                            tr.det = s.laneDet[lane];
                        }
                    } else {
                        // The lanes could not decide: the scalar test, lane after lane.
                        for (int l = 0, n = BvhLayout.primCount(bits(blocks[o + BLOCK_PRIMS])); l < n; l++) {
                            if (tr.hit(blocks, o + l, o + 3 * LANES + l, o + 6 * LANES + l, LANES, bvh.flags, prim + l, tHit, cull)) {
                                tHit = tr.t;
                                found = prim + l;
                            }
                        }
                    }
                }
                tMaxBits = ScalarKernel.tMaxBits(tHit);
            } else {
                ray.tMax = tHit;
                if (bvh.geometry.intersect(BvhLayout.firstSphere(ref), BvhLayout.sphereCount(ref), ray, hit, cull)) {
                    tHit = hit.t;
                    found = hit.prim;
                    tMaxBits = ScalarKernel.tMaxBits(tHit);
                }
            }
            // Pop the next node the ray enters before the closest hit so far.
            int cut = ScalarKernel.cut(tMaxBits), sp = s.sp;
            do {
                if (sp == 0) {
                    return ScalarKernel.finish(bvh, ray, hit, found, tHit, tr);
                }
                ref = refs[--sp];
            } while (keys[sp] > cut);
            s.sp = sp;
        }
    }

    /** Whether anything blocks the ray in (0, ray.tMax); see {@link Bvh#occluded}. */
    static boolean anyHit(Bvh bvh, Ray ray, TraversalStack s) {
        final float[] nodes = bvh.nodes, blocks = bvh.blocks;
        final int[] refs = s.refs;
        final RayTriangle tr = s.triangle;
        final double tMax = ray.tMax;
        final int tMaxBits = ScalarKernel.tMaxBits(tMax);
        s.sp = 0;
        int ref = 0;
        while (true) {
            if (ref >= 0) {
                ref = visit(nodes, NODE * ref, s, tMaxBits, false);
                if (ref != POP) {
                    continue;
                }
            } else if (!BvhLayout.isSphereLeaf(ref)) {
                for (int b = BvhLayout.firstBlock(ref), end = b + BvhLayout.blockCount(ref); b < end; b++) {
                    int o = BLOCK * b;
                    int lane = blockTest(blocks, o, tr, tMax, false, true, s);
                    if (lane >= 0) {
                        if (lane < LANES) {
                            return true;
                        }
                    } else {
                        for (int l = 0, n = BvhLayout.primCount(bits(blocks[o + BLOCK_PRIMS])); l < n; l++) {
                            if (tr.hit(blocks, o + l, o + 3 * LANES + l, o + 6 * LANES + l, LANES, null, 0, tMax, false)) {
                                return true;
                            }
                        }
                    }
                }
            } else if (bvh.geometry.occludes(BvhLayout.firstSphere(ref), BvhLayout.sphereCount(ref), ray)) {
                return true;
            }
            if (s.sp == 0) {
                return false;
            }
            ref = refs[--s.sp];
        }
    }

    /**
     * The slab test of the eight children of the node at {@code o} (the keys of
     * {@link ScalarKernel#childKeys}, lane by lane): returns the child to visit next, or
     * {@link #POP}. For the closest hit ({@code nearest}) that is the nearest child entered, and
     * the others are pushed sorted by key with the nearest on top, as
     * {@link ScalarKernel#pushSorted} does (one child entered is returned without touching the
     * stack, two are ordered by one comparison); for any hit the children entered are pushed in
     * slot order ({@link ScalarKernel#pushAll}) and the top one returned. One method for both, so
     * that it is too large for C2 to inline into the loops (see the class comment).
     */
    private static int visit(float[] box, int o, TraversalStack s, int tMaxBits, boolean nearest) {
        IntVector tnx = FloatVector.fromArray(F8, box, o + s.nx).sub(s.onx).mul(s.ix).reinterpretAsInts();
        IntVector tny = FloatVector.fromArray(F8, box, o + s.ny).sub(s.ony).mul(s.iy).reinterpretAsInts();
        IntVector tnz = FloatVector.fromArray(F8, box, o + s.nz).sub(s.onz).mul(s.iz).reinterpretAsInts();
        IntVector tn = tnx.max(tny).max(tnz.max(0));
        IntVector tfx = FloatVector.fromArray(F8, box, o + s.fx).sub(s.ofx).mul(s.ix).reinterpretAsInts();
        IntVector tfy = FloatVector.fromArray(F8, box, o + s.fy).sub(s.ofy).mul(s.iy).reinterpretAsInts();
        IntVector tfz = FloatVector.fromArray(F8, box, o + s.fz).sub(s.ofz).mul(s.iz).reinterpretAsInts();
        IntVector tf = tfx.min(tfy).min(tfz.min(tMaxBits)).add(ScalarKernel.MARGIN_ULPS);
        VectorMask<Integer> out = tn.compare(VectorOperators.GT, tf);
        VectorMask<Integer> in = out.not();
        int count = in.trueCount();
        if (count == 0) {
            return POP;
        }
        int a = in.firstTrue();
        if (count == 1) {
            return child(box, o, a);
        }
        int[] lanes = s.lanes;
        tn.and(~7).or(SLOTS).blend(-1, out).intoArray(lanes, 0);
        int sp;
        if (!nearest) {
            sp = ScalarKernel.pushAll(box, o, lanes, s.refs, s.sp) - 1;
        } else if (count == 2) {
            int b = in.lastTrue(), ka = lanes[a], kb = lanes[b];
            int m = (ka - kb) >> 31;                       // -1 if a is the nearer (keys are non-negative)
            int near = a & m | b & ~m;
            sp = s.sp;
            s.keys[sp] = ka ^ kb ^ (ka & m | kb & ~m);
            s.refs[sp] = child(box, o, a ^ b ^ near);
            s.sp = sp + 1;
            return child(box, o, near);
        } else {
            sp = ScalarKernel.pushSorted(box, o, lanes, s.refs, s.keys, s.sp) - 1;
        }
        s.sp = sp;
        return s.refs[sp];
    }

    /**
     * The four triangles of the block at {@code o} against the ray set up in {@code tr}: the
     * operations of {@link RayTriangle#hit} in double lanes. Returns the lane of the nearest hit
     * in (0, tMax) (the first of equal ones), with its distance in {@code s.bestT}, or
     * {@link BvhLayout#LANES} and an infinite distance where no lane hits; with {@code any}, any
     * lane that hits. Returns -1 where the lanes cannot decide: an edge function of exactly zero,
     * or, with {@code cull}, a back face hit (the scalar test knows which meshes are closed).
     */
    private static int blockTest(float[] blocks, int o, RayTriangle tr, double tMax, boolean cull, boolean any, TraversalStack s) {
        final int x = LANES * tr.kx, y = LANES * tr.ky, z = LANES * tr.kz, b = o + 3 * LANES, c = o + 6 * LANES;
        final double okx = tr.okx, oky = tr.oky, okz = tr.okz, sx = tr.sx, sy = tr.sy;
        DoubleVector az0 = load(blocks, o + z).sub(okz), bz0 = load(blocks, b + z).sub(okz), cz0 = load(blocks, c + z).sub(okz);
        DoubleVector axs = load(blocks, o + x).sub(okx).sub(az0.mul(sx)), ays = load(blocks, o + y).sub(oky).sub(az0.mul(sy));
        DoubleVector bxs = load(blocks, b + x).sub(okx).sub(bz0.mul(sx)), bys = load(blocks, b + y).sub(oky).sub(bz0.mul(sy));
        DoubleVector cxs = load(blocks, c + x).sub(okx).sub(cz0.mul(sx)), cys = load(blocks, c + y).sub(oky).sub(cz0.mul(sy));
        DoubleVector u = cxs.mul(bys).sub(cys.mul(bxs));
        DoubleVector v = axs.mul(cys).sub(ays.mul(cxs));
        DoubleVector w = bxs.mul(ays).sub(bys.mul(axs));
        VectorMask<Double> below = u.compare(VectorOperators.LT, 0).or(v.compare(VectorOperators.LT, 0)).or(w.compare(VectorOperators.LT, 0));
        VectorMask<Double> above = u.compare(VectorOperators.GT, 0).or(v.compare(VectorOperators.GT, 0)).or(w.compare(VectorOperators.GT, 0));
        VectorMask<Double> sameSign = below.and(above).not();
        VectorMask<Double> zero = u.compare(VectorOperators.EQ, 0).or(v.compare(VectorOperators.EQ, 0)).or(w.compare(VectorOperators.EQ, 0));
        if (zero.and(sameSign).anyTrue()) {
            return -1;
        }
        s.bestT = Double.POSITIVE_INFINITY;
        // Lanes of one sign, not all zero (unused lanes are NaN: neither below nor above): the others cannot hit.
        VectorMask<Double> inside = sameSign.and(below.or(above));
        if (!inside.anyTrue()) {
            return LANES;
        }
        DoubleVector det = u.add(v).add(w);
        DoubleVector t = u.mul(az0).add(v.mul(bz0)).add(w.mul(cz0)).mul(tr.sz).div(det);
        VectorMask<Double> hits = inside.and(t.compare(VectorOperators.GT, 0)).and(t.compare(VectorOperators.LT, tMax));
        if (any) {
            return hits.anyTrue() ? 0 : LANES;
        }
        // All lane work before the decisions below (see the class comment): the back faces hit,
        // the nearest distance (t is never NaN where it hits) and its first lane, the barycentrics.
        boolean backHit = hits.and(det.compare(VectorOperators.LT, 0)).anyTrue();
        double best = t.blend(Double.POSITIVE_INFINITY, hits.not()).reduceLanes(VectorOperators.MIN);
        int first = t.compare(VectorOperators.EQ, best).and(hits).firstTrue();   // LANES where none hits
        v.intoArray(s.laneV, 0);
        w.intoArray(s.laneW, 0);
        det.intoArray(s.laneDet, 0);
        if (cull && backHit) {
            return -1;
        }
        s.bestT = best;
        return first;
    }

    private static DoubleVector load(float[] a, int i) {
        return (DoubleVector) FloatVector.fromArray(F4, a, i).convertShape(VectorOperators.F2D, D4, 0);
    }
}
