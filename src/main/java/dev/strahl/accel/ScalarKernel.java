package dev.strahl.accel;

import static dev.strahl.accel.BvhLayout.BLOCK;
import static dev.strahl.accel.BvhLayout.BLOCK_PRIMS;
import static dev.strahl.accel.BvhLayout.CHILDREN;
import static dev.strahl.accel.BvhLayout.LANES;
import static dev.strahl.accel.BvhLayout.NODE;
import static dev.strahl.accel.BvhLayout.WIDTH;

import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.RayTriangle;

/**
 * The traversal of {@link Bvh} one lane at a time: the scalar twin of {@link SimdKernel}, used
 * where the Vector API module is absent (or switched off) and as the reference the SIMD kernel is
 * tested against. Both run the same arithmetic on the same values and visit the nodes in the same
 * order, so they give the same bits: the slab test below is the one the SIMD kernel runs on eight
 * lanes, and the triangles go through {@link RayTriangle}, whose operations the SIMD kernel runs
 * on four.
 *
 * <p>Closest hit: at a node, the children the ray enters get a key, their entry distance (float
 * bits) with the three low bits replaced by the slot ({@link #key}): one child entered is visited
 * at once, without the stack; several are pushed sorted by key, the nearest on top, and a popped
 * node whose key lies beyond the closest hit found meanwhile is dropped. Any hit: the children
 * entered are pushed in slot order (sorting found blockers no sooner than it cost).
 */
final class ScalarKernel {
    private ScalarKernel() {}

    /**
     * Largest error of a float slab distance in ulps, with room to spare: the origin is bounded
     * by floats on either side of it ({@link TraversalStack#prepare}) and each slab uses the bound
     * that makes its distance err outwards; what remains is the rounding of one subtraction, one
     * product and the float inverse (under 2 ulp on each end).
     */
    static final int MARGIN_ULPS = 8;

    /**
     * Whether the scalar kernel counts its node visits and block tests into the stack
     * ({@code -Dstrahl.countVisits=true}, for docs/bench/VisitCounts.java); a constant, so the
     * compiled loops have no trace of it otherwise. The SIMD kernel visits the same nodes.
     */
    static final boolean COUNT = Boolean.getBoolean("strahl.countVisits");

    /**
     * The stack key of a child entered at distance bits {@code entry} ≥ 0 in slot {@code slot}:
     * the order of visits (nearest first, ties by slot), unique within a node. It lies within 7
     * of the entry bits, which the cut on pop allows for ({@link #cut}).
     */
    static int key(int entry, int slot) {
        return entry & ~7 | slot;
    }

    /**
     * The bits of the float just at or above a distance t &gt; 0 (t rounded up to float), which the
     * slab tests compare with: a cast and one conditional increment, where
     * {@code Math.nextUp} would branch on NaN and infinity. For t ≤ 0 nothing can be hit anyway.
     */
    static int tMaxBits(double t) {
        float f = (float) t;
        return bits(f) + (f < t ? 1 : 0);
    }

    /** Keys above this are beyond the closest hit so far (its distance as float bits, rounded up). */
    static int cut(int tMaxBits) {
        return tMaxBits + MARGIN_ULPS + 7;
    }

    /** The closest hit in (0, ray.tMax), or false; see {@link Bvh#intersect}. */
    static boolean closestHit(Bvh bvh, Ray ray, Hit hit, TraversalStack s, boolean cull) {
        final float[] nodes = bvh.nodes, blocks = bvh.blocks;
        final byte[] flags = bvh.flags;
        final int[] refs = s.refs, keys = s.keys, lanes = s.lanes;
        final RayTriangle tr = s.triangle;
        double tHit = ray.tMax;
        int tMaxBits = tMaxBits(tHit);
        int found = -1;
        int sp = 0;
        int ref = 0;
        while (true) {
            if (ref >= 0) {
                int o = NODE * ref;
                int hits = childKeys(nodes, o, s, tMaxBits, lanes);
                if (COUNT) {
                    s.nodeVisits++;
                }
                if (hits != 0) {
                    if ((hits & hits - 1) == 0) {
                        ref = child(nodes, o, Integer.numberOfTrailingZeros(hits));
                        continue;
                    }
                    sp = pushSorted(nodes, o, lanes, refs, keys, sp);
                    ref = refs[--sp];
                    continue;
                }
            } else if (!BvhLayout.isSphereLeaf(ref)) {
                boolean closer = false;
                if (COUNT) {
                    s.blockTests += BvhLayout.blockCount(ref);
                }
                for (int b = BvhLayout.firstBlock(ref), end = b + BvhLayout.blockCount(ref); b < end; b++) {
                    int o = BLOCK * b, word = bits(blocks[o + BLOCK_PRIMS]), prim = BvhLayout.firstPrim(word), n = BvhLayout.primCount(word);
                    for (int lane = 0; lane < n; lane++) {
                        if (tr.hit(blocks, o + lane, o + 3 * LANES + lane, o + 6 * LANES + lane, LANES, flags, prim + lane, tHit, cull)) {
                            tHit = tr.t;
                            found = prim + lane;
                            closer = true;
                        }
                    }
                }
                if (closer) {
                    tMaxBits = tMaxBits(tHit);
                }
            } else {
                ray.tMax = tHit;
                if (bvh.geometry.intersect(BvhLayout.firstSphere(ref), BvhLayout.sphereCount(ref), ray, hit, cull)) {
                    tHit = hit.t;
                    found = hit.prim;
                    tMaxBits = tMaxBits(tHit);
                }
            }
            // Pop the next node the ray enters before the closest hit so far.
            int cut = cut(tMaxBits);
            do {
                if (sp == 0) {
                    return finish(bvh, ray, hit, found, tHit, tr);
                }
                ref = refs[--sp];
            } while (keys[sp] > cut);
        }
    }

    /** Whether anything blocks the ray in (0, ray.tMax); see {@link Bvh#occluded}. */
    static boolean anyHit(Bvh bvh, Ray ray, TraversalStack s) {
        final float[] nodes = bvh.nodes, blocks = bvh.blocks;
        final int[] refs = s.refs, lanes = s.lanes;
        final RayTriangle tr = s.triangle;
        final double tMax = ray.tMax;
        final int tMaxBits = tMaxBits(tMax);
        int sp = 0;
        int ref = 0;
        while (true) {
            if (ref >= 0) {
                int o = NODE * ref;
                if (COUNT) {
                    s.nodeVisits++;
                }
                if (childKeys(nodes, o, s, tMaxBits, lanes) != 0) {
                    sp = pushAll(nodes, o, lanes, refs, sp);
                }
            } else if (!BvhLayout.isSphereLeaf(ref)) {
                if (COUNT) {
                    s.blockTests += BvhLayout.blockCount(ref);
                }
                for (int b = BvhLayout.firstBlock(ref), end = b + BvhLayout.blockCount(ref); b < end; b++) {
                    int o = BLOCK * b, n = BvhLayout.primCount(bits(blocks[o + BLOCK_PRIMS]));
                    for (int lane = 0; lane < n; lane++) {
                        if (tr.hit(blocks, o + lane, o + 3 * LANES + lane, o + 6 * LANES + lane, LANES, null, 0, tMax, false)) {
                            return true;
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
     * The keys of the eight children of the node at {@code o} into {@code lanes} (-1 for those the
     * ray misses); returns the mask of the children entered.
     */
    static int childKeys(float[] box, int o, TraversalStack s, int tMaxBits, int[] lanes) {
        final int nx = s.nx, ny = s.ny, nz = s.nz, fx = s.fx, fy = s.fy, fz = s.fz;
        final float onx = s.onx, ony = s.ony, onz = s.onz, ofx = s.ofx, ofy = s.ofy, ofz = s.ofz, ix = s.ix, iy = s.iy, iz = s.iz;
        int hits = 0;
        for (int c = 0; c < WIDTH; c++) {
            int b = o + c;
            int tn = Math.max(Math.max(bits((box[b + nx] - onx) * ix), bits((box[b + ny] - ony) * iy)),
                    Math.max(bits((box[b + nz] - onz) * iz), 0));
            int tf = Math.min(Math.min(bits((box[b + fx] - ofx) * ix), bits((box[b + fy] - ofy) * iy)),
                    Math.min(bits((box[b + fz] - ofz) * iz), tMaxBits));
            int in = tn <= tf + MARGIN_ULPS ? -1 : 0;
            lanes[c] = key(tn, c) | ~in;
            hits |= in & 1 << c;
        }
        return hits;
    }

    /**
     * Pushes the children with a key (≥ 0) in {@code lanes}, sorted by key with the smallest on
     * top; returns the new stack size. Insertion sort: the SIMD kernel's sorting network gives the
     * same order, the keys being distinct.
     */
    static int pushSorted(float[] nodes, int o, int[] lanes, int[] refs, int[] keys, int sp) {
        int base = sp;
        for (int c = 0; c < WIDTH; c++) {
            int k = lanes[c];
            if (k >= 0) {
                int r = child(nodes, o, c), i = sp++;
                for (; i > base && keys[i - 1] < k; i--) {
                    keys[i] = keys[i - 1];
                    refs[i] = refs[i - 1];
                }
                keys[i] = k;
                refs[i] = r;
            }
        }
        return sp;
    }

    /** Pushes the children with a key (≥ 0) in {@code lanes} in slot order; returns the new stack size. */
    static int pushAll(float[] nodes, int o, int[] lanes, int[] refs, int sp) {
        for (int c = 0; c < WIDTH; c++) {
            // Written always, kept only when entered: no branch to mispredict.
            refs[sp] = child(nodes, o, c);
            sp += ~lanes[c] >>> 31;
        }
        return sp;
    }

    static int child(float[] nodes, int o, int slot) {
        return bits(nodes[o + CHILDREN + slot]);
    }

    /** Records the closest hit; a triangle's barycentrics are in {@code tr}, which holds the closest triangle hit. */
    static boolean finish(Bvh bvh, Ray ray, Hit hit, int found, double t, RayTriangle tr) {
        if (found < 0) {
            return false;
        }
        ray.tMax = t;
        hit.t = t;
        hit.prim = found;
        if (found < bvh.triangleCount) {
            hit.b1 = tr.b1();
            hit.b2 = tr.b2();
        }
        return true;
    }

    static int bits(float f) {
        return Float.floatToRawIntBits(f);
    }
}
