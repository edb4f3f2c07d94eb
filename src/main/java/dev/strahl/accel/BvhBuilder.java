package dev.strahl.accel;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.RecursiveAction;

/**
 * Top-down construction of a binary BVH with the binned surface-area heuristic (Wald, "On fast
 * Construction of SAH-based Bounding Volume Hierarchies", 2007: centroids sorted into
 * {@value #BINS} bins on all three axes in one pass, the cheapest bin boundary taken), then
 * collapsed into the four-wide tree of {@link Bvh} by repeatedly opening the child of largest
 * surface area (as Embree and pbrt's wide BVHs do). Large ranges are built in parallel on a
 * fork/join pool, and the top splits, which have the references to themselves, bin them in
 * parallel chunks. The result does not depend on the thread count: chunks' bins are merged by
 * sums, minima and maxima, which do not depend on the order, and the final tree is written in
 * one depth-first pass over the binary one.
 *
 * <p>Leaves hold at most {@value #MAX_LEAF} primitives, all triangles or all spheres, so that
 * they are one contiguous range of the reordered {@link Geometry} (no index indirection).
 * Below depth {@value #MAX_SAH_DEPTH} splits fall back to the object median, which bounds the
 * depth (and so the traversal stack) whatever the input.
 */
final class BvhBuilder {
    static final int BINS = 32;
    static final int MAX_LEAF = 6;
    /** Cost of one box test relative to one primitive test, in the SAH. */
    static final double TRAVERSAL_COST = 2.0;
    private static final int MAX_SAH_DEPTH = 40;
    private static final int PARALLEL_MIN = 1 << 14;
    /** Ranges at least this large bin in parallel, in chunks of {@link #CHUNK} references. */
    private static final int PARALLEL_BIN_MIN = 1 << 16;
    private static final int CHUNK = 1 << 14;

    private final Geometry geometry;
    private final int threads;
    private final int n;
    private final int triangleCount;
    // Per reference position k (not primitive: partitioning moves them along with ref, so that
    // binning reads them in order): the box, rounded outwards, as ordered keys (see key()), and the centroid.
    private final int[] primKey;
    private final float[] centroid;
    private final int[] ref;           // primitive ids, partitioned in place into leaf ranges
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
        this.triangleCount = geometry.triangleCount();
        this.primKey = new int[6 * n];
        this.centroid = new float[3 * n];
        this.ref = new int[n];
        int capacity = Math.max(1, 2 * n);
        this.nodeBox = new float[6 * capacity];
        this.nodeA = new int[capacity];
        this.nodeB = new int[capacity];
    }

    Bvh build() {
        if (n == 0) {
            return new Bvh(geometry, new float[0], 0);
        }
        if (n >= PARALLEL_MIN && threads > 1) {
            ForkJoinPool pool = new ForkJoinPool(threads);
            try {
                pool.invoke(new Top());
            } finally {
                pool.shutdown();
            }
        } else {
            new Top().compute();
        }
        return new BvhWriter(geometry, ref, nodeA, nodeB, nodeBox).write();
    }

    /** The whole build: the references' boxes (in parallel chunks in a pool), then the splits. */
    private final class Top extends RecursiveAction {
        @Override
        protected void compute() {
            if (ForkJoinTask.inForkJoinPool()) {
                References[] chunks = new References[(n + CHUNK - 1) / CHUNK];
                for (int c = 0; c < chunks.length; c++) {
                    chunks[c] = new References(c * CHUNK, Math.min(n, (c + 1) * CHUNK));
                }
                ForkJoinTask.invokeAll(chunks);
            } else {
                new References(0, n).compute();
            }
            rangeBox(0, n, 0);
            split(0, 0, n, 0, 1);
        }
    }

    /** References [from, to): reference k = primitive k, its box rounded outwards, as keys, and its centroid. */
    private final class References extends RecursiveAction {
        private final int from, to;

        References(int from, int to) {
            this.from = from;
            this.to = to;
        }

        @Override
        protected void compute() {
            Aabb box = new Aabb();
            for (int i = from; i < to; i++) {
                box.reset();
                geometry.includeBounds(i, box);
                int o = 6 * i;
                float[] b = {roundDown(box.minX), roundDown(box.minY), roundDown(box.minZ), roundUp(box.maxX), roundUp(box.maxY), roundUp(box.maxZ)};
                for (int c = 0; c < 6; c++) {
                    primKey[o + c] = key(b[c]);
                }
                for (int c = 0; c < 3; c++) {
                    centroid[3 * i + c] = 0.5f * b[c] + 0.5f * b[3 + c];
                }
                ref[i] = i;
            }
        }
    }

    /** One chunk of a large range: its centroid bounds ({@code cb} null) or its bins over {@code cb}. */
    private final class BinChunk extends RecursiveAction {
        private final int start, end;
        private final float[] cb;
        final Bins bins = new Bins();

        BinChunk(int start, int end, float[] cb, int nb) {
            this.start = start;
            this.end = end;
            this.cb = cb;
            bins.bins = nb;
        }

        @Override
        protected void compute() {
            if (cb == null) {
                centroidBounds(start, end, bins.centroidBounds);
            } else {
                binAll(bins, start, end, cb);
            }
        }
    }

    /** Each thread's bins, reused at every split it makes (large splits take their own, see split). */
    private static final ThreadLocal<Bins> BINS_SCRATCH = ThreadLocal.withInitial(Bins::new);

    /** Builds the subtree of one binary node over ref[start, end); forks halves of large ranges. */
    private final class Split extends RecursiveAction {
        private final int node, start, end, depth, free;

        Split(int node, int start, int end, int depth, int free) {
            this.node = node;
            this.start = start;
            this.end = end;
            this.depth = depth;
            this.free = free;
        }

        @Override
        protected void compute() {
            split(node, start, end, depth, free);
        }
    }

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
            centroidBounds(start, end, cb);
            if (sah) {
                binAll(s, start, end, cb);
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
        if (count <= MAX_LEAF && (bestAxis < 0 || count <= splitCost)) {
            if (isHomogeneous(start, end)) {
                makeLeaf(node, start, count);
                return free;
            }
            bestAxis = -1;            // mixed triangles and spheres: split by type below
        }

        int mid = bestAxis >= 0 ? partition(start, end, bestAxis, cb[bestAxis], binScale(cb, bestAxis, s.bins), s.bins, bestBin)
                : isHomogeneous(start, end) ? medianSplit(start, end, cb) : typeSplit(start, end);
        assert mid > start && mid < end;
        int left = free, right = free + 1;
        free += 2;
        if (bestAxis >= 0) {
            binsBox(s, bestAxis, 0, bestBin + 1, 6 * left);
            binsBox(s, bestAxis, bestBin + 1, s.bins, 6 * right);
        } else {
            rangeBox(start, mid, 6 * left);
            rangeBox(mid, end, 6 * right);
        }
        nodeA[node] = left;
        nodeB[node] = right;
        if (count < PARALLEL_MIN) {
            return split(right, mid, end, depth + 1, split(left, start, mid, depth + 1, free));
        }
        int rightFree = free + 2 * (mid - start) - 2;
        if (ForkJoinTask.inForkJoinPool()) {
            Split l = new Split(left, start, mid, depth + 1, free);
            l.fork();
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
        BinChunk[] chunks = new BinChunk[(end - start + CHUNK - 1) / CHUNK];
        for (int pass = 0; pass < (sah ? 2 : 1); pass++) {
            float[] cb = pass == 0 ? null : s.centroidBounds;
            for (int c = 0; c < chunks.length; c++) {
                int from = start + c * CHUNK;
                chunks[c] = new BinChunk(from, Math.min(end, from + CHUNK), cb, s.bins);
            }
            ForkJoinTask.invokeAll(chunks);
            if (pass == 0) {
                setEmpty(s.centroidBounds);
                for (BinChunk c : chunks) {
                    include(s.centroidBounds, c.bins.centroidBounds);
                }
            } else {
                s.clear();
                for (BinChunk c : chunks) {
                    s.merge(c.bins);
                }
            }
        }
    }

    private void centroidBounds(int start, int end, float[] cb) {
        setEmpty(cb);
        for (int k = start; k < end; k++) {
            int p = 3 * k;
            for (int c = 0; c < 3; c++) {
                float v = centroid[p + c];
                cb[c] = Math.min(cb[c], v);
                cb[3 + c] = Math.max(cb[3 + c], v);
            }
        }
    }

    /** Sorts every primitive of the range into its bin on each axis, growing the bins' boxes. */
    private void binAll(Bins s, int start, int end, float[] cb) {
        int nb = s.bins;
        int[] count = s.count;
        int[] box = s.box;
        s.clear();
        float sx = binScale(cb, 0, nb), sy = binScale(cb, 1, nb), sz = binScale(cb, 2, nb);
        for (int k = start; k < end; k++) {
            int p = k;
            int bx = bin(centroid[3 * p], cb[0], sx, nb);
            int by = BINS + bin(centroid[3 * p + 1], cb[1], sy, nb);
            int bz = 2 * BINS + bin(centroid[3 * p + 2], cb[2], sz, nb);
            count[bx]++;
            count[by]++;
            count[bz]++;
            int q = 6 * p;
            int x0 = primKey[q], y0 = primKey[q + 1], z0 = primKey[q + 2], x1 = primKey[q + 3], y1 = primKey[q + 4], z1 = primKey[q + 5];
            Bins.grow(box, 6 * bx, x0, y0, z0, x1, y1, z1);
            Bins.grow(box, 6 * by, x0, y0, z0, x1, y1, z1);
            Bins.grow(box, 6 * bz, x0, y0, z0, x1, y1, z1);
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

    private static float binScale(float[] cb, int axis, int bins) {
        float ext = cb[3 + axis] - cb[axis];
        return ext > 0 ? bins / ext : 0;
    }

    /** The union of bins [from, to) on one axis, written to nodeBox at {@code dest}. */
    private void binsBox(Bins s, int axis, int from, int to, int dest) {
        int[] b = {Integer.MAX_VALUE, Integer.MAX_VALUE, Integer.MAX_VALUE, Integer.MIN_VALUE, Integer.MIN_VALUE, Integer.MIN_VALUE};
        for (int k = from; k < to; k++) {
            int o = 6 * (axis * BINS + k);
            Bins.grow(b, 0, s.box[o], s.box[o + 1], s.box[o + 2], s.box[o + 3], s.box[o + 4], s.box[o + 5]);
        }
        for (int c = 0; c < 6; c++) {
            nodeBox[dest + c] = unkey(b[c]);
        }
    }

    /** Moves primitives whose centroid falls in bins 0..splitBin to the front; returns the split index. */
    private int partition(int start, int end, int axis, float cmin, float scale, int bins, int splitBin) {
        int i = start;
        int j = end - 1;
        while (i <= j) {
            if (bin(centroid[3 * i + axis], cmin, scale, bins) <= splitBin) {
                i++;
            } else {
                swap(i, j--);
            }
        }
        return i;
    }

    /** The bin of a centroid: c ≥ cmin, so only the upper end needs clamping (a centroid on the upper bound). */
    private static int bin(float c, float cmin, float scale, int bins) {
        return Math.min((int) ((c - cmin) * scale), bins - 1);
    }

    /** Splits at the median centroid of the longest centroid axis (quickselect); bounds the depth. */
    private int medianSplit(int start, int end, float[] cb) {
        int axis = 0;
        for (int c = 1; c < 3; c++) {
            if (cb[3 + c] - cb[c] > cb[3 + axis] - cb[axis]) {
                axis = c;
            }
        }
        int mid = (start + end) >>> 1;
        int lo = start, hi = end - 1;
        while (lo < hi) {
            float pivot = centroid[3 * ((lo + hi) >>> 1) + axis];
            int i = lo, j = hi;
            while (i <= j) {
                while (centroid[3 * i + axis] < pivot) {
                    i++;
                }
                while (centroid[3 * j + axis] > pivot) {
                    j--;
                }
                if (i <= j) {
                    swap(i++, j--);
                }
            }
            if (mid <= j) {
                hi = j;
            } else if (mid >= i) {
                lo = i;
            } else {
                break;
            }
        }
        return mid;
    }

    /** Moves triangles before spheres; returns the index of the first sphere. */
    private int typeSplit(int start, int end) {
        int i = start;
        for (int k = start; k < end; k++) {
            if (ref[k] < triangleCount) {
                swap(i++, k);
            }
        }
        return i;
    }

    /** Swaps the references at positions i and j with their boxes and centroids. */
    private void swap(int i, int j) {
        int r = ref[i];
        ref[i] = ref[j];
        ref[j] = r;
        for (int c = 0; c < 6; c++) {
            int t = primKey[6 * i + c];
            primKey[6 * i + c] = primKey[6 * j + c];
            primKey[6 * j + c] = t;
        }
        for (int c = 0; c < 3; c++) {
            float t = centroid[3 * i + c];
            centroid[3 * i + c] = centroid[3 * j + c];
            centroid[3 * j + c] = t;
        }
    }

    private boolean isHomogeneous(int start, int end) {
        boolean first = ref[start] < triangleCount;
        for (int k = start + 1; k < end; k++) {
            if ((ref[k] < triangleCount) != first) {
                return false;
            }
        }
        return true;
    }

    private void makeLeaf(int node, int start, int count) {
        nodeA[node] = start;
        nodeB[node] = ~count;
    }

    private void rangeBox(int start, int end, int dest) {
        int[] b = {Integer.MAX_VALUE, Integer.MAX_VALUE, Integer.MAX_VALUE, Integer.MIN_VALUE, Integer.MIN_VALUE, Integer.MIN_VALUE};
        for (int k = start; k < end; k++) {
            int q = 6 * k;
            Bins.grow(b, 0, primKey[q], primKey[q + 1], primKey[q + 2], primKey[q + 3], primKey[q + 4], primKey[q + 5]);
        }
        for (int c = 0; c < 6; c++) {
            nodeBox[dest + c] = unkey(b[c]);
        }
    }

    // ---- small box helpers on float[6] slices ----------------------------------------------------

    private static void setEmpty(float[] b) {
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
