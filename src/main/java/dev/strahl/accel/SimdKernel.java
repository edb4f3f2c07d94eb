package dev.strahl.accel;

import static dev.strahl.accel.BvhLayout.BLOCK;
import static dev.strahl.accel.BvhLayout.BLOCK_PRIM;
import static dev.strahl.accel.BvhLayout.CHILDREN;
import static dev.strahl.accel.BvhLayout.LANES;
import static dev.strahl.accel.BvhLayout.NODE;
import static dev.strahl.accel.ScalarKernel.bits;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.RayTriangle;
import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.IntVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorShuffle;
import jdk.incubator.vector.VectorSpecies;

/**
 * The traversal of {@link Bvh} with the incubating Vector API (JEP 414): a node's eight child
 * boxes in one 8-lane slab test, a leaf block's four triangles in one 4-lane watertight test.
 * Loaded only where the module is in the boot layer ({@link Simd#AVAILABLE}); {@link ScalarKernel}
 * is its twin and the reference: the same operations, lane by lane, on the same values, and the
 * same order of visits, so both give the same bits.
 *
 * <p>Node: the keys of the children entered ({@link ScalarKernel#key}) in lanes; one child
 * entered is visited at once, several are sorted in lanes by a sorting network (bitonic, six
 * stages) and pushed with two vector stores, the nearest on top. Leaf block: the triangle test of
 * {@link RayTriangle} in double lanes, from the block's float vertices; a lane with an edge
 * function of exactly zero (a ray through an edge's line) sends the block to {@link RayTriangle}
 * itself, whose exact fallback decides; a lane that hits is recorded in lane order, as the scalar
 * loop would, with back-face culling checked there.
 */
final class SimdKernel {
    private SimdKernel() {}

    private static final VectorSpecies<Float> F8 = FloatVector.SPECIES_256;
    private static final VectorSpecies<Integer> I8 = IntVector.SPECIES_256;
    private static final VectorSpecies<Float> F4 = FloatVector.SPECIES_128;
    private static final VectorSpecies<Double> D4 = DoubleVector.SPECIES_256;
    private static final IntVector SLOTS = IntVector.fromArray(I8, new int[] {0, 1, 2, 3, 4, 5, 6, 7}, 0);

    // The bitonic network sorting eight lanes into descending order: partner i ^ j, and the lanes that keep the larger key.
    private static final VectorShuffle<Integer> P1 = partner(1), P2 = partner(2), P4 = partner(4);
    private static final VectorMask<Integer> M21 = larger(2, 1), M42 = larger(4, 2), M41 = larger(4, 1),
            M84 = larger(8, 4), M82 = larger(8, 2), M81 = larger(8, 1);

    private static VectorShuffle<Integer> partner(int j) {
        int[] p = new int[8];
        for (int i = 0; i < 8; i++) {
            p[i] = i ^ j;
        }
        return VectorShuffle.fromArray(I8, p, 0);
    }

    /** Lane i of stage (k, j) keeps the larger of its pair where it would keep the smaller in an ascending sort. */
    private static VectorMask<Integer> larger(int k, int j) {
        boolean[] m = new boolean[8];
        for (int i = 0; i < 8; i++) {
            m[i] = ((i & k) == 0) == (i < (i ^ j));
        }
        return VectorMask.fromArray(I8, m, 0);
    }

    private static IntVector stage(IntVector v, VectorShuffle<Integer> partner, VectorMask<Integer> larger) {
        IntVector p = v.rearrange(partner);
        return v.min(p).blend(v.max(p), larger);
    }

    /** The keys of the node's children (or -1), as the scalar {@link ScalarKernel#childKeys} computes them, lane by lane. */
    private static IntVector childKeys(float[] box, int o, TraversalStack s, int tMaxBits) {
        IntVector tnx = FloatVector.fromArray(F8, box, o + s.nx).sub(s.onx).mul(s.ix).reinterpretAsInts();
        IntVector tny = FloatVector.fromArray(F8, box, o + s.ny).sub(s.ony).mul(s.iy).reinterpretAsInts();
        IntVector tnz = FloatVector.fromArray(F8, box, o + s.nz).sub(s.onz).mul(s.iz).reinterpretAsInts();
        IntVector tn = tnx.max(tny).max(tnz.max(0));
        IntVector tfx = FloatVector.fromArray(F8, box, o + s.fx).sub(s.ofx).mul(s.ix).reinterpretAsInts();
        IntVector tfy = FloatVector.fromArray(F8, box, o + s.fy).sub(s.ofy).mul(s.iy).reinterpretAsInts();
        IntVector tfz = FloatVector.fromArray(F8, box, o + s.fz).sub(s.ofz).mul(s.iz).reinterpretAsInts();
        IntVector tf = tfx.min(tfy).min(tfz.min(tMaxBits)).add(ScalarKernel.MARGIN_ULPS);
        return tn.and(~7).or(SLOTS).blend(-1, tn.compare(VectorOperators.GT, tf));
    }

    /** The closest hit in (0, ray.tMax), or false; see {@link Bvh#intersect}. */
    static boolean closestHit(Bvh bvh, Ray ray, Hit hit, TraversalStack s, boolean cull) {
        final float[] nodes = bvh.nodes, blocks = bvh.blocks;
        final int[] refs = s.refs, keys = s.keys;
        final RayTriangle tr = s.triangle;
        double tHit = ray.tMax;
        int tMaxBits = ScalarKernel.tMaxBits(tHit);
        int found = -1;
        int sp = 0;
        int ref = 0;
        while (true) {
            if (ref >= 0) {
                int o = NODE * ref;
                IntVector k = childKeys(nodes, o, s, tMaxBits);
                VectorMask<Integer> in = k.compare(VectorOperators.GE, 0);
                int count = in.trueCount();
                if (count == 1) {
                    ref = ScalarKernel.child(nodes, o, in.firstTrue());
                    continue;
                }
                if (count == 2) {
                    // The nearer of two is visited, the other pushed: what sorting two keys gives, without the network.
                    k.intoArray(s.lanes, 0);
                    int a = in.firstTrue(), b = in.lastTrue(), ka = s.lanes[a], kb = s.lanes[b];
                    int m = (ka - kb) >> 31;                       // -1 if a is the nearer (keys are non-negative)
                    int near = a & m | b & ~m, far = a ^ b ^ near;
                    keys[sp] = ka ^ kb ^ (ka & m | kb & ~m);
                    refs[sp++] = ScalarKernel.child(nodes, o, far);
                    ref = ScalarKernel.child(nodes, o, near);
                    continue;
                }
                if (count > 2) {
                    IntVector sorted = stage(stage(stage(stage(stage(stage(k, P1, M21), P2, M42), P1, M41), P4, M84), P2, M82), P1, M81);
                    IntVector children = FloatVector.fromArray(F8, nodes, o + CHILDREN).reinterpretAsInts();
                    sorted.intoArray(keys, sp);
                    sorted.and(7).selectFrom(children).intoArray(refs, sp);
                    sp += count;
                    ref = refs[--sp];
                    continue;
                }
            } else if (!BvhLayout.isSphereLeaf(ref)) {
                int before = found;
                for (int b = BvhLayout.firstBlock(ref), end = b + BvhLayout.blockCount(ref); b < end; b++) {
                    int o = BLOCK * b;
                    int prim = bits(blocks[o + BLOCK_PRIM]);
                    int lanes = blockTest(blocks, o, tr, tHit, s);
                    if (lanes < 0) {
                        // A ray through an edge's line: the scalar test with its exact fallback, lane after lane.
                        for (int lane = 0, n = bits(blocks[o + BvhLayout.BLOCK_COUNT]); lane < n; lane++) {
                            if (tr.hit(blocks, o + lane, o + 3 * LANES + lane, o + 6 * LANES + lane, LANES, bvh.flags, prim + lane, tHit, cull)) {
                                tHit = tr.t;
                                found = prim + lane;
                            }
                        }
                    } else if (lanes > 0) {
                        for (int lane = 0; lane < LANES; lane++) {
                            double t = s.laneT[lane];
                            if (t < tHit && !(cull && s.laneDet[lane] < 0 && (bvh.flags[prim + lane] & Geometry.CLOSED) != 0)) {
                                tHit = t;
                                found = prim + lane;
                                tr.t = t;
                                tr.v = s.laneV[lane];
                                tr.w = s.laneW[lane];
                                tr.det = s.laneDet[lane];
                            }
                        }
                    }
                }
                if (found != before) {
                    tMaxBits = ScalarKernel.tMaxBits(tHit);
                }
            } else {
                ray.tMax = tHit;
                if (bvh.geometry.intersect(BvhLayout.firstSphere(ref), BvhLayout.sphereCount(ref), ray, hit, cull)) {
                    tHit = hit.t;
                    found = hit.prim;
                    tMaxBits = ScalarKernel.tMaxBits(tHit);
                }
            }
            int cut = ScalarKernel.cut(tMaxBits);
            do {
                if (sp == 0) {
                    return ScalarKernel.finish(bvh, ray, hit, found, tHit, tr);
                }
                ref = refs[--sp];
            } while (keys[sp] > cut);
        }
    }

    static int rootOnly(Bvh bvh, Ray ray, TraversalStack s) {
        IntVector k = childKeys(bvh.nodes, 0, s, ScalarKernel.tMaxBits(ray.tMax));
        return k.compare(VectorOperators.GE, 0).trueCount();
    }

    /** Whether anything blocks the ray in (0, ray.tMax); see {@link Bvh#occluded}. */
    static boolean anyHit(Bvh bvh, Ray ray, TraversalStack s) {
        final float[] nodes = bvh.nodes, blocks = bvh.blocks;
        final int[] refs = s.refs, lanes = s.lanes;
        final RayTriangle tr = s.triangle;
        final double tMax = ray.tMax;
        final int tMaxBits = ScalarKernel.tMaxBits(tMax);
        int sp = 0;
        int ref = 0;
        while (true) {
            if (ref >= 0) {
                int o = NODE * ref;
                IntVector k = childKeys(nodes, o, s, tMaxBits);
                VectorMask<Integer> in = k.compare(VectorOperators.GE, 0);
                int count = in.trueCount();
                if (count == 1) {
                    ref = ScalarKernel.child(nodes, o, in.firstTrue());
                    continue;
                }
                if (count > 1) {
                    k.intoArray(lanes, 0);
                    sp = ScalarKernel.pushAll(nodes, o, lanes, refs, sp);
                }
            } else if (!BvhLayout.isSphereLeaf(ref)) {
                for (int b = BvhLayout.firstBlock(ref), end = b + BvhLayout.blockCount(ref); b < end; b++) {
                    int o = BLOCK * b;
                    int lanesHit = blockTest(blocks, o, tr, tMax, s);
                    if (lanesHit > 0) {
                        return true;
                    }
                    if (lanesHit < 0) {
                        for (int lane = 0, n = bits(blocks[o + BvhLayout.BLOCK_COUNT]); lane < n; lane++) {
                            if (tr.hit(blocks, o + lane, o + 3 * LANES + lane, o + 6 * LANES + lane, LANES, null, 0, tMax, false)) {
                                return true;
                            }
                        }
                    }
                }
            } else if (bvh.geometry.occludes(BvhLayout.firstSphere(ref), BvhLayout.sphereCount(ref), ray)) {
                return true;
            }
            if (sp == 0) {
                return false;
            }
            ref = refs[--sp];
        }
    }

    /**
     * The four triangles of the block at {@code o} against the ray set up in {@code tr}: the
     * operations of {@link RayTriangle#hit} in double lanes. Returns -1 if a lane's edge function
     * is exactly zero (the caller runs the scalar test on the block), else the number of lanes
     * hit in (0, tMax), whose t, v, w and det it wrote into the scratch arrays of {@code s} (NaN
     * as t of the lanes not hit). Back faces are left to the caller.
     */
    private static int blockTest(float[] blocks, int o, RayTriangle tr, double tMax, TraversalStack s) {
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
        // Lanes of one sign, not all zero (unused lanes are NaN: neither below nor above): the rest cannot hit.
        VectorMask<Double> inside = sameSign.and(below.or(above));
        if (!inside.anyTrue()) {
            return 0;
        }
        DoubleVector det = u.add(v).add(w);
        DoubleVector t = u.mul(az0).add(v.mul(bz0)).add(w.mul(cz0)).mul(tr.sz).div(det);
        VectorMask<Double> hits = inside.and(t.compare(VectorOperators.GT, 0)).and(t.compare(VectorOperators.LT, tMax));
        int count = hits.trueCount();
        if (count > 0) {
            t.blend(Double.NaN, hits.not()).intoArray(s.laneT, 0);
            v.intoArray(s.laneV, 0);
            w.intoArray(s.laneW, 0);
            det.intoArray(s.laneDet, 0);
        }
        return count;
    }

    private static DoubleVector load(float[] a, int i) {
        return (DoubleVector) FloatVector.fromArray(F4, a, i).convertShape(VectorOperators.F2D, D4, 0);
    }
}
