package dev.strahl.accel;

import dev.strahl.geometry.Geometry;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;

/**
 * Top-down construction of a binary BVH with the binned surface-area heuristic (Wald, "On fast
 * Construction of SAH-based Bounding Volume Hierarchies", 2007: centroids sorted into
 * {@value #BINS} bins on all three axes in one pass, the cheapest bin boundary taken), then
 * collapsed into the eight-wide tree of {@link Bvh} by {@link BvhWriter}. Large ranges are built in parallel on a
 * fork/join pool, and the top splits, which have the references to themselves, bin them in
 * parallel chunks. The result does not depend on the thread count: chunks' bins are merged by
 * sums, minima and maxima, which do not depend on the order, and the final tree is written in
 * one depth-first pass over the binary one.
 *
 * <p>Leaves hold at most {@value #MAX_LEAF} primitives (one block of the leaf test), all
 * triangles or all spheres, so that they are one contiguous range of the reordered
 * {@link Geometry}. The SAH counts a leaf's cost in blocks ({@link #cost}) and a binary split's
 * at {@value #TRAVERSAL_COST} of a block test: the eight-wide tree absorbs about three binary
 * levels into one node, whose test takes less than half of a block test's time (measured:
 * docs/performance.md, round 7). Those constants were chosen by node visits and block tests per
 * ray on the benchmark meshes, and by memory: blocks are 3.6–3.9 triangles full on the meshes.
 * Below depth {@value #MAX_SAH_DEPTH} splits fall back to the object median, which bounds the
 * depth (and so the traversal stack) whatever the input.
 */
final class BvhBuilder {
    static final int BINS = 32;
    static final int MAX_LEAF = BvhLayout.LANES;
    /** Cost of a binary split relative to one leaf block test, in the SAH. */
    static final double TRAVERSAL_COST = 0.25;

    /**
     * The SAH cost of intersecting {@code n} primitives: the leaf blocks they fill, since a block
     * of four triangles costs one test whether it holds one or four. So the SAH prefers full
     * blocks, as Embree's builders for its four-triangle leaves do.
     */
    static int cost(int n) {
        return (n + BvhLayout.LANES - 1) / BvhLayout.LANES;
    }

    private static final int MAX_SAH_DEPTH = 40;
    private static final int PARALLEL_MIN = 1 << 14;
    /** Ranges at least this large bin in parallel, in chunks of {@link #CHUNK} references. */
    private static final int PARALLEL_BIN_MIN = 1 << 16;
    private static final int CHUNK = 1 << 14;

    private final Geometry geometry;
    private final int threads;
    private final int n;
    private final References refs;
    // Binary nodes: box (6 floats), and a = left child, b = right child (interior) or a = start, b = ~count (leaf).
    // Numbered without a shared counter: a split takes the next two free slots for its children
    // (siblings adjacent, in depth-first order), and the halves of a large split each get their
    // own stretch of 2 × references − 2 slots, the most their descendants can take, so forked
    // halves never share a counter and the threads write separate parts of the arrays.
    private final float[] nodeBox;
    private final int[] nodeA, nodeB;

    /** A builder on {@code threads} threads; the tree is the same for any number. */
    BvhBuilder(Geometry geometry, int threads) {
        this.geometry = geometry;
        this.threads = threads;
        this.n = geometry.primitiveCount();
        this.refs = new References(geometry);
        int capacity = Math.max(1, 2 * n);
        this.nodeBox = new float[6 * capacity];
        this.nodeA = new int[capacity];
        this.nodeB = new int[capacity];
    }

    Bvh build() {
        if (n == 0) {
            return new Bvh(geometry, new float[0], 0, new float[0]);
        }
        if (n >= PARALLEL_MIN && threads > 1) {
            ForkJoinPool pool = new ForkJoinPool(threads);
            try {
                pool.invoke(ForkJoinTask.adapt(this::top));
            } finally {
                pool.shutdown();
            }
        } else {
            top();
        }
        return new BvhWriter(geometry, refs.ref, nodeA, nodeB, nodeBox).write();
    }

    /** The whole build: the references (in parallel chunks in a pool), then the splits. */
    private void top() {
        if (ForkJoinTask.inForkJoinPool()) {
            inChunks(0, n, (c, from, to) -> refs.init(from, to));
        } else {
            refs.init(0, n);
        }
        refs.box(0, n, nodeBox, 0);
        split(0, 0, n, 0, 1);
    }

    /** Work on chunk {@code c}, references [from, to), of a range. */
    private interface ChunkTask {
        void run(int c, int from, int to);
    }

    /** Runs {@code task} on the chunks of {@link #CHUNK} references of [start, end) in parallel, in the current pool. */
    private static void inChunks(int start, int end, ChunkTask task) {
        List<ForkJoinTask<?>> tasks = new ArrayList<>();
        for (int c = 0, from = start; from < end; c++, from += CHUNK) {
            int chunk = c, first = from, last = Math.min(end, from + CHUNK);
            tasks.add(ForkJoinTask.adapt(() -> task.run(chunk, first, last)));
        }
        ForkJoinTask.invokeAll(tasks);
    }

    /** Each thread's bins, reused at every split it makes (large splits take their own, see split). */
    private static final ThreadLocal<Bins> BINS_SCRATCH = ThreadLocal.withInitial(Bins::new);

    /** Builds binary node {@code node} over ref[start, end), numbering its descendants from {@code free}; returns the next free slot. */
    private int split(int node, int start, int end, int depth, int free) {
        int count = end - start;
        if (count == 1) {
            makeLeaf(node, start, count);
            return free;
        }
        // A large range bins in parallel and may run other splits while it waits for its chunks:
        // those use the thread's scratch bins, so it takes its own.
        boolean parallel = count >= PARALLEL_BIN_MIN && ForkJoinTask.inForkJoinPool();
        Bins s = parallel ? new Bins() : BINS_SCRATCH.get();
        // Fewer bins for few primitives: the sweep costs as much per bin as the binning per primitive.
        s.bins = Math.min(BINS, Math.max(2, count));
        boolean sah = depth < MAX_SAH_DEPTH;
        // Centroid bounds decide the binning range.
        float[] cb = s.centroidBounds;
        if (parallel) {
            binParallel(s, start, end, sah);
        } else {
            refs.centroidBounds(start, end, cb);
            if (sah) {
                s.fill(refs, start, end, cb);
            }
        }
        int bestAxis = -1, bestBin = -1;
        double bestCost = Double.POSITIVE_INFINITY;
        if (sah) {
            for (int axis = 0; axis < 3; axis++) {
                if (!(cb[3 + axis] > cb[axis])) {
                    continue;
                }
                double cost = s.sweep(axis, bestCost);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = s.lastBin;
                }
            }
        }
        double parentArea = area(nodeBox, 6 * node);
        double splitCost = parentArea > 0 ? TRAVERSAL_COST + bestCost / parentArea : Double.POSITIVE_INFINITY;
        if (count <= MAX_LEAF && (bestAxis < 0 || cost(count) <= splitCost)) {
            if (refs.isHomogeneous(start, end)) {
                makeLeaf(node, start, count);
                return free;
            }
            bestAxis = -1;            // mixed triangles and spheres: split by type below
        }

        int mid = bestAxis >= 0 ? refs.partition(start, end, bestAxis, cb[bestAxis], Bins.scale(cb, bestAxis, s.bins), s.bins, bestBin)
                : refs.isHomogeneous(start, end) ? refs.medianSplit(start, end, cb) : refs.typeSplit(start, end);
        assert mid > start && mid < end;
        int left = free, right = free + 1;
        free += 2;
        if (bestAxis >= 0) {
            s.union(bestAxis, 0, bestBin + 1, nodeBox, 6 * left);
            s.union(bestAxis, bestBin + 1, s.bins, nodeBox, 6 * right);
        } else {
            refs.box(start, mid, nodeBox, 6 * left);
            refs.box(mid, end, nodeBox, 6 * right);
        }
        nodeA[node] = left;
        nodeB[node] = right;
        if (count < PARALLEL_MIN) {
            return split(right, mid, end, depth + 1, split(left, start, mid, depth + 1, free));
        }
        int rightFree = free + 2 * (mid - start) - 2;
        if (ForkJoinTask.inForkJoinPool()) {
            int leftFree = free;
            ForkJoinTask<?> l = ForkJoinTask.adapt(() -> split(left, start, mid, depth + 1, leftFree)).fork();
            split(right, mid, end, depth + 1, rightFree);
            l.join();
        } else {
            split(left, start, mid, depth + 1, free);
            split(right, mid, end, depth + 1, rightFree);
        }
        return rightFree + 2 * (end - mid) - 2;
    }

    /**
     * Centroid bounds and (if {@code sah}) bins of a large range into {@code s}, from chunks
     * run in parallel. The top split would otherwise run on one thread while the others wait.
     */
    private void binParallel(Bins s, int start, int end, boolean sah) {
        Bins[] part = new Bins[(end - start + CHUNK - 1) / CHUNK];
        for (int c = 0; c < part.length; c++) {
            part[c] = new Bins();
            part[c].bins = s.bins;
        }
        inChunks(start, end, (c, from, to) -> refs.centroidBounds(from, to, part[c].centroidBounds));
        setEmpty(s.centroidBounds);
        for (Bins p : part) {
            include(s.centroidBounds, p.centroidBounds);
        }
        if (sah) {
            inChunks(start, end, (c, from, to) -> part[c].fill(refs, from, to, s.centroidBounds));
            s.clear();
            for (Bins p : part) {
                s.merge(p);
            }
        }
    }

    /**
     * A float as an int that orders like the float (for all but NaN): the bits of a non-negative
     * float, the bits with the magnitude bits flipped for a negative one. Binning then takes
     * box bounds with integer minima and maxima, one conditional move each.
     */
    static int key(float f) {
        int b = Float.floatToRawIntBits(f);
        return b ^ ((b >> 31) >>> 1);
    }

    /** The float of a {@link #key}. */
    static float unkey(int k) {
        return Float.intBitsToFloat(k ^ ((k >> 31) >>> 1));
    }

    private void makeLeaf(int node, int start, int count) {
        nodeA[node] = start;
        nodeB[node] = ~count;
    }

    // ---- small box helpers on float[6] slices ----------------------------------------------------

    static void setEmpty(float[] b) {
        b[0] = b[1] = b[2] = Float.POSITIVE_INFINITY;
        b[3] = b[4] = b[5] = Float.NEGATIVE_INFINITY;
    }

    /** Grows box {@code b} by box {@code o}; minima and maxima, so in any order the same. */
    private static void include(float[] b, float[] o) {
        for (int c = 0; c < 3; c++) {
            b[c] = Math.min(b[c], o[c]);
            b[3 + c] = Math.max(b[3 + c], o[3 + c]);
        }
    }

    static double area(float[] b, int o) {
        return area(b[o], b[o + 1], b[o + 2], b[o + 3], b[o + 4], b[o + 5]);
    }

    static double area(float x0, float y0, float z0, float x1, float y1, float z1) {
        double dx = x1 - x0, dy = y1 - y0, dz = z1 - z0;
        if (!(dx >= 0 && dy >= 0 && dz >= 0)) {
            return 0;
        }
        return 2 * (dx * dy + dy * dz + dz * dx);
    }

    static float roundDown(double v) {
        float f = (float) v;
        return f > v ? Math.nextDown(f) : f;
    }

    static float roundUp(double v) {
        float f = (float) v;
        return f < v ? Math.nextUp(f) : f;
    }
}
