package dev.strahl.accel;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.RecursiveAction;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Top-down construction of a binary BVH with the binned surface-area heuristic (Wald, "On fast
 * Construction of SAH-based Bounding Volume Hierarchies", 2007: centroids sorted into
 * {@value #BINS} bins on all three axes in one pass, the cheapest bin boundary taken), then
 * collapsed into the four-wide tree of {@link Bvh} by repeatedly opening the child of largest
 * surface area (as Embree and pbrt's wide BVHs do). Large ranges are built in parallel on a
 * fork/join pool; the result does not depend on the thread count, because the final tree is
 * written in one depth-first pass over the binary one.
 *
 * <p>Leaves hold at most {@value #MAX_LEAF} primitives, all triangles or all spheres, so that
 * they are one contiguous range of the reordered {@link Geometry} (no index indirection).
 * Below depth {@value #MAX_SAH_DEPTH} splits fall back to the object median, which bounds the
 * depth (and so the traversal stack) whatever the input.
 */
final class BvhBuilder {
    static final int BINS = 32;
    static final int MAX_LEAF = 4;
    /** Cost of one box test relative to one primitive test, in the SAH. */
    static final double TRAVERSAL_COST = 1.0;
    private static final int MAX_SAH_DEPTH = 40;
    private static final int PARALLEL_MIN = 1 << 14;

    private final Geometry geometry;
    private final int n;
    private final int triangleCount;
    private final float[] primBox;     // per primitive: min x, y, z, max x, y, z (rounded outwards)
    private final float[] centroid;    // per primitive: x, y, z
    private final int[] ref;           // primitive ids, partitioned in place into leaf ranges
    // Binary nodes: box (6 floats), and a = left child, b = right child (interior) or a = start, b = ~count (leaf).
    private final float[] nodeBox;
    private final int[] nodeA, nodeB;
    private final AtomicInteger nodes = new AtomicInteger(1);

    BvhBuilder(Geometry geometry) {
        this.geometry = geometry;
        this.n = geometry.primitiveCount();
        this.triangleCount = geometry.triangleCount();
        this.primBox = new float[6 * n];
        this.centroid = new float[3 * n];
        this.ref = new int[n];
        Aabb box = new Aabb();
        for (int i = 0; i < n; i++) {
            box.reset();
            geometry.includeBounds(i, box);
            int o = 6 * i;
            primBox[o] = roundDown(box.minX);
            primBox[o + 1] = roundDown(box.minY);
            primBox[o + 2] = roundDown(box.minZ);
            primBox[o + 3] = roundUp(box.maxX);
            primBox[o + 4] = roundUp(box.maxY);
            primBox[o + 5] = roundUp(box.maxZ);
            for (int c = 0; c < 3; c++) {
                centroid[3 * i + c] = 0.5f * primBox[o + c] + 0.5f * primBox[o + 3 + c];
            }
            ref[i] = i;
        }
        int capacity = Math.max(1, 2 * n);
        this.nodeBox = new float[6 * capacity];
        this.nodeA = new int[capacity];
        this.nodeB = new int[capacity];
    }

    Bvh build() {
        if (n == 0) {
            return new Bvh(geometry, new float[0], new int[0], 0);
        }
        float[] root = emptyBox();
        for (int i = 0; i < n; i++) {
            grow(root, 0, primBox, 6 * i);
        }
        System.arraycopy(root, 0, nodeBox, 0, 6);
        if (n >= PARALLEL_MIN && Runtime.getRuntime().availableProcessors() > 1) {
            ForkJoinPool pool = new ForkJoinPool(Runtime.getRuntime().availableProcessors());
            try {
                pool.invoke(new Split(0, 0, n, 0));
            } finally {
                pool.shutdown();
            }
        } else {
            new Split(0, 0, n, 0).compute();
        }
        return new WideWriter().write();
    }

    /** Per-thread binning memory, reused at every split a thread makes. */
    private static final class Bins {
        final int[] count = new int[3 * BINS];
        final float[] box = new float[3 * BINS * 6];
        final float[] rightBox = new float[BINS * 6];
        final int[] rightCount = new int[BINS];
        final float[] acc = new float[6];
        final float[] bestLeft = new float[6], bestRight = new float[6];
        int lastBin;
    }

    private static final ThreadLocal<Bins> BINS_SCRATCH = ThreadLocal.withInitial(Bins::new);

    /** Builds the subtree of one binary node over ref[start, end); forks halves of large ranges. */
    private final class Split extends RecursiveAction {
        private final int node, start, end, depth;

        Split(int node, int start, int end, int depth) {
            this.node = node;
            this.start = start;
            this.end = end;
            this.depth = depth;
        }

        @Override
        protected void compute() {
            split(node, start, end, depth);
        }
    }

    private void split(int node, int start, int end, int depth) {
        int count = end - start;
        if (count == 1) {
            makeLeaf(node, start, count);
            return;
        }
        Bins s = BINS_SCRATCH.get();
        // Centroid bounds decide the binning range.
        float[] cb = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
            Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        for (int k = start; k < end; k++) {
            int p = 3 * ref[k];
            for (int c = 0; c < 3; c++) {
                float v = centroid[p + c];
                cb[c] = Math.min(cb[c], v);
                cb[3 + c] = Math.max(cb[3 + c], v);
            }
        }
        int bestAxis = -1, bestBin = -1;
        double bestCost = Double.POSITIVE_INFINITY;
        if (depth < MAX_SAH_DEPTH) {
            binAll(s, start, end, cb);
            for (int axis = 0; axis < 3; axis++) {
                if (!(cb[3 + axis] > cb[axis])) {
                    continue;
                }
                double cost = sweep(s, axis, bestCost);
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
                return;
            }
            bestAxis = -1;            // mixed triangles and spheres: split by type below
        }

        int mid;
        int left = nodes.getAndAdd(2), right = left + 1;
        if (bestAxis >= 0) {
            mid = partition(start, end, bestAxis, cb[bestAxis], BINS / (cb[3 + bestAxis] - cb[bestAxis]), bestBin);
            System.arraycopy(s.bestLeft, 0, nodeBox, 6 * left, 6);
            System.arraycopy(s.bestRight, 0, nodeBox, 6 * right, 6);
        } else {
            mid = isHomogeneous(start, end) ? medianSplit(start, end, cb) : typeSplit(start, end);
            rangeBox(start, mid, 6 * left);
            rangeBox(mid, end, 6 * right);
        }
        assert mid > start && mid < end;
        nodeA[node] = left;
        nodeB[node] = right;
        if (count >= PARALLEL_MIN && ForkJoinTask.inForkJoinPool()) {
            Split l = new Split(left, start, mid, depth + 1);
            l.fork();
            split(right, mid, end, depth + 1);
            l.join();
        } else {
            split(left, start, mid, depth + 1);
            split(right, mid, end, depth + 1);
        }
    }

    /** Sorts every primitive of the range into its bin on each axis, growing the bins' boxes. */
    private void binAll(Bins s, int start, int end, float[] cb) {
        java.util.Arrays.fill(s.count, 0);
        float[] box = s.box;
        for (int i = 0; i < 3 * BINS; i++) {
            int o = 6 * i;
            box[o] = box[o + 1] = box[o + 2] = Float.POSITIVE_INFINITY;
            box[o + 3] = box[o + 4] = box[o + 5] = Float.NEGATIVE_INFINITY;
        }
        float sx = binScale(cb, 0), sy = binScale(cb, 1), sz = binScale(cb, 2);
        for (int k = start; k < end; k++) {
            int p = ref[k];
            int bx = bin(centroid[3 * p], cb[0], sx);
            int by = BINS + bin(centroid[3 * p + 1], cb[1], sy);
            int bz = 2 * BINS + bin(centroid[3 * p + 2], cb[2], sz);
            s.count[bx]++;
            s.count[by]++;
            s.count[bz]++;
            grow(box, 6 * bx, primBox, 6 * p);
            grow(box, 6 * by, primBox, 6 * p);
            grow(box, 6 * bz, primBox, 6 * p);
        }
    }

    private static float binScale(float[] cb, int axis) {
        float ext = cb[3 + axis] - cb[axis];
        return ext > 0 ? BINS / ext : 0;
    }

    /**
     * SAH cost (unnormalised: Σ area × count) of the best bin boundary on one axis, if below
     * {@code bound}; records the bin in {@code s.lastBin} and the two boxes in the scratch.
     */
    private double sweep(Bins s, int axis, double bound) {
        int base = axis * BINS;
        float[] acc = s.acc;
        setEmpty(acc);
        int accCount = 0;
        for (int b = BINS - 1; b > 0; b--) {
            grow(acc, 0, s.box, 6 * (base + b));
            accCount += s.count[base + b];
            System.arraycopy(acc, 0, s.rightBox, 6 * b, 6);
            s.rightCount[b] = accCount;
        }
        setEmpty(acc);
        accCount = 0;
        double best = bound;
        s.lastBin = -1;
        for (int b = 0; b < BINS - 1; b++) {
            grow(acc, 0, s.box, 6 * (base + b));
            accCount += s.count[base + b];
            int rightCount = s.rightCount[b + 1];
            if (accCount == 0 || rightCount == 0) {
                continue;
            }
            double cost = area(acc, 0) * accCount + area(s.rightBox, 6 * (b + 1)) * rightCount;
            if (cost < best) {
                best = cost;
                s.lastBin = b;
                System.arraycopy(acc, 0, s.bestLeft, 0, 6);
                System.arraycopy(s.rightBox, 6 * (b + 1), s.bestRight, 0, 6);
            }
        }
        return s.lastBin >= 0 ? best : Double.POSITIVE_INFINITY;
    }

    /** Moves primitives whose centroid falls in bins 0..splitBin to the front; returns the split index. */
    private int partition(int start, int end, int axis, float cmin, float scale, int splitBin) {
        int i = start;
        int j = end - 1;
        while (i <= j) {
            if (bin(centroid[3 * ref[i] + axis], cmin, scale) <= splitBin) {
                i++;
            } else {
                int tmp = ref[i];
                ref[i] = ref[j];
                ref[j--] = tmp;
            }
        }
        return i;
    }

    private static int bin(float c, float cmin, float scale) {
        int b = (int) ((c - cmin) * scale);
        return b < 0 ? 0 : (b >= BINS ? BINS - 1 : b);
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
            float pivot = centroid[3 * ref[(lo + hi) >>> 1] + axis];
            int i = lo, j = hi;
            while (i <= j) {
                while (centroid[3 * ref[i] + axis] < pivot) {
                    i++;
                }
                while (centroid[3 * ref[j] + axis] > pivot) {
                    j--;
                }
                if (i <= j) {
                    int tmp = ref[i];
                    ref[i++] = ref[j];
                    ref[j--] = tmp;
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
                int tmp = ref[i];
                ref[i++] = ref[k];
                ref[k] = tmp;
            }
        }
        return i;
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
        float[] b = emptyBox();
        for (int k = start; k < end; k++) {
            grow(b, 0, primBox, 6 * ref[k]);
        }
        System.arraycopy(b, 0, nodeBox, dest, 6);
    }

    /** Writes the four-wide tree and the primitive order of its leaves. */
    private final class WideWriter {
        private final int[] newId = new int[n];
        private float[] boxes = new float[24 * Math.max(1, n / 4)];
        private int[] children = new int[4 * Math.max(1, n / 4)];
        private int count;

        WideWriter() {
            // Leaf ranges of ref become contiguous ranges of the reordered geometry: triangles in
            // the order of ref, then spheres in the order of ref.
            int t = 0, s = triangleCount;
            for (int k = 0; k < n; k++) {
                newId[k] = ref[k] < triangleCount ? t++ : s++;
            }
        }

        Bvh write() {
            int[] order = new int[n];
            for (int k = 0; k < n; k++) {
                order[newId[k]] = ref[k];
            }
            if (nodeB[0] < 0) {
                int node = allocate();
                setChild(node, 0, 0);
            } else {
                writeNode(0, 1);
            }
            return new Bvh(geometry.permute(order), java.util.Arrays.copyOf(boxes, 24 * count),
                    java.util.Arrays.copyOf(children, 4 * count), count);
        }

        private int allocate() {
            int node = count++;
            if (4 * count > children.length) {
                boxes = java.util.Arrays.copyOf(boxes, 2 * boxes.length);
                children = java.util.Arrays.copyOf(children, 2 * children.length);
            }
            for (int c = 0; c < 4; c++) {
                int o = 24 * node + c;
                for (int k = 0; k < 3; k++) {
                    boxes[o + 4 * k] = Float.POSITIVE_INFINITY;
                    boxes[o + 4 * (3 + k)] = Float.NEGATIVE_INFINITY;
                }
                children[4 * node + c] = Bvh.EMPTY;
            }
            return node;
        }

        /** Writes the wide node for interior binary node {@code b}; returns its index. */
        private int writeNode(int b, int depth) {
            if (depth > Bvh.MAX_DEPTH) {
                throw new IllegalStateException("BVH deeper than " + Bvh.MAX_DEPTH + " levels");
            }
            int k = 2;
            int[] kid = new int[4];
            kid[0] = nodeA[b];
            kid[1] = nodeB[b];
            while (k < 4) {
                int open = -1;
                double largest = -1;
                for (int i = 0; i < k; i++) {
                    if (nodeB[kid[i]] >= 0) {
                        double a = area(nodeBox, 6 * kid[i]);
                        if (a > largest) {
                            largest = a;
                            open = i;
                        }
                    }
                }
                if (open < 0) {
                    break;
                }
                int opened = kid[open];
                kid[open] = nodeA[opened];
                kid[k++] = nodeB[opened];
            }
            int node = allocate();
            for (int i = 0; i < k; i++) {
                setChild(node, i, kid[i]);
            }
            for (int i = 0; i < k; i++) {
                if (nodeB[kid[i]] >= 0) {
                    int child = writeNode(kid[i], depth + 1);     // may grow the arrays: index them after
                    children[4 * node + i] = child;
                }
            }
            return node;
        }

        private void setChild(int node, int slot, int b) {
            int o = 24 * node + slot;
            for (int c = 0; c < 6; c++) {
                boxes[o + 4 * c] = nodeBox[6 * b + c];
            }
            if (nodeB[b] < 0) {
                children[4 * node + slot] = Bvh.leaf(newId[nodeA[b]], ~nodeB[b]);
            }
        }
    }

    // ---- small box helpers on float[6] slices ----------------------------------------------------

    private static float[] emptyBox() {
        float[] b = new float[6];
        setEmpty(b);
        return b;
    }

    private static void setEmpty(float[] b) {
        b[0] = b[1] = b[2] = Float.POSITIVE_INFINITY;
        b[3] = b[4] = b[5] = Float.NEGATIVE_INFINITY;
    }

    private static void grow(float[] acc, int a, float[] src, int s) {
        for (int c = 0; c < 3; c++) {
            acc[a + c] = Math.min(acc[a + c], src[s + c]);
            acc[a + 3 + c] = Math.max(acc[a + 3 + c], src[s + 3 + c]);
        }
    }

    private static double area(float[] b, int o) {
        double dx = b[o + 3] - b[o], dy = b[o + 4] - b[o + 1], dz = b[o + 5] - b[o + 2];
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
