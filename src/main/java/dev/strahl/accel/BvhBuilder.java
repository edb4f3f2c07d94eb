package dev.strahl.accel;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import java.util.Arrays;

/**
 * Top-down BVH construction with the binned surface-area heuristic (Wald, "On fast Construction
 * of SAH-based Bounding Volume Hierarchies", 2007): centroids are sorted into {@value #BINS} bins
 * per axis and the cheapest of the bin boundaries is taken. Leaves hold at most
 * {@value #MAX_LEAF} primitives. Nodes are written depth-first into flat arrays.
 */
final class BvhBuilder {
    static final int BINS = 16;
    static final int MAX_LEAF = 4;
    /** Cost of visiting a node relative to one primitive test, in the SAH. */
    private static final double TRAVERSAL_COST = 1.0;

    private final Geometry geometry;
    private final int n;
    private final double[] boxes;      // per primitive: min x, y, z, max x, y, z
    private final double[] centroids;  // per primitive: x, y, z
    private final int[] primRef;

    private float[] bounds;
    private int[] info;
    private int nodeCount;

    // Per-bin scratch, reused at every split.
    private final int[] binCount = new int[BINS];
    private final double[] binBox = new double[6 * BINS];
    private final double[] rightArea = new double[BINS];
    private final int[] rightCount = new int[BINS];

    BvhBuilder(Geometry geometry) {
        this.geometry = geometry;
        this.n = geometry.primitiveCount();
        this.boxes = new double[6 * n];
        this.centroids = new double[3 * n];
        this.primRef = new int[n];
        Aabb box = new Aabb();
        for (int i = 0; i < n; i++) {
            box.reset();
            geometry.includeBounds(i, box);
            boxes[6 * i] = box.minX;
            boxes[6 * i + 1] = box.minY;
            boxes[6 * i + 2] = box.minZ;
            boxes[6 * i + 3] = box.maxX;
            boxes[6 * i + 4] = box.maxY;
            boxes[6 * i + 5] = box.maxZ;
            centroids[3 * i] = 0.5 * (box.minX + box.maxX);
            centroids[3 * i + 1] = 0.5 * (box.minY + box.maxY);
            centroids[3 * i + 2] = 0.5 * (box.minZ + box.maxZ);
            primRef[i] = i;
        }
        int capacity = Math.max(1, 2 * n);
        this.bounds = new float[6 * capacity];
        this.info = new int[2 * capacity];
    }

    Bvh build() {
        if (n > 0) {
            buildNode(0, n, 0);
        }
        return new Bvh(geometry, Arrays.copyOf(bounds, 6 * nodeCount), Arrays.copyOf(info, 2 * nodeCount), primRef, nodeCount);
    }

    private void buildNode(int start, int end, int depth) {
        int node = nodeCount++;
        double[] nb = rangeBounds(start, end);
        writeBounds(node, nb);
        int count = end - start;

        // Centroid bounds decide the binning range.
        double cminX = Double.POSITIVE_INFINITY, cminY = cminX, cminZ = cminX;
        double cmaxX = Double.NEGATIVE_INFINITY, cmaxY = cmaxX, cmaxZ = cmaxX;
        for (int k = start; k < end; k++) {
            int p = 3 * primRef[k];
            cminX = Math.min(cminX, centroids[p]);
            cmaxX = Math.max(cmaxX, centroids[p]);
            cminY = Math.min(cminY, centroids[p + 1]);
            cmaxY = Math.max(cmaxY, centroids[p + 1]);
            cminZ = Math.min(cminZ, centroids[p + 2]);
            cmaxZ = Math.max(cmaxZ, centroids[p + 2]);
        }
        double[] cmin = {cminX, cminY, cminZ};
        double[] cext = {cmaxX - cminX, cmaxY - cminY, cmaxZ - cminZ};

        int bestAxis = -1;
        int bestBin = -1;
        double bestCost = Double.POSITIVE_INFINITY;
        if (count > 1) {
            for (int axis = 0; axis < 3; axis++) {
                if (!(cext[axis] > 0)) {
                    continue;
                }
                double cost = bestSplit(start, end, axis, cmin[axis], cext[axis]);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = lastBestBin;
                }
            }
        }
        double leafCost = count;
        double parentArea = area(nb);
        double splitCost = parentArea > 0 ? TRAVERSAL_COST + bestCost / parentArea : Double.POSITIVE_INFINITY;
        boolean mustSplit = count > MAX_LEAF;
        if (count == 1 || (!mustSplit && leafCost <= splitCost)) {
            makeLeaf(node, start, count);
            return;
        }

        int mid;
        if (bestAxis >= 0) {
            mid = partition(start, end, bestAxis, cmin[bestAxis], cext[bestAxis], bestBin);
        } else {
            mid = start + count / 2;   // all centroids coincide: any split is as good as another
        }
        if (mid == start || mid == end) {
            mid = start + count / 2;
        }
        int axis = Math.max(bestAxis, 0);
        buildNode(start, mid, depth + 1);
        int right = nodeCount;
        buildNode(mid, end, depth + 1);
        info[2 * node] = right;
        info[2 * node + 1] = axis;
        assert depth < Bvh.STACK_SIZE - 1 : "BVH deeper than the traversal stack";
    }

    private int lastBestBin;

    /** SAH cost (unnormalised: sum of area × count) of the best bin boundary on one axis. */
    private double bestSplit(int start, int end, int axis, double cmin, double cext) {
        Arrays.fill(binCount, 0);
        for (int b = 0; b < BINS; b++) {
            binBox[6 * b] = binBox[6 * b + 1] = binBox[6 * b + 2] = Double.POSITIVE_INFINITY;
            binBox[6 * b + 3] = binBox[6 * b + 4] = binBox[6 * b + 5] = Double.NEGATIVE_INFINITY;
        }
        double scale = BINS / cext;
        for (int k = start; k < end; k++) {
            int p = primRef[k];
            int b = bin(centroids[3 * p + axis], cmin, scale);
            binCount[b]++;
            for (int c = 0; c < 3; c++) {
                binBox[6 * b + c] = Math.min(binBox[6 * b + c], boxes[6 * p + c]);
                binBox[6 * b + 3 + c] = Math.max(binBox[6 * b + 3 + c], boxes[6 * p + 3 + c]);
            }
        }
        // Sweep from the right, then from the left; split after bin i puts bins 0..i on the left.
        double[] acc = newEmptyBox();
        int accCount = 0;
        for (int b = BINS - 1; b > 0; b--) {
            grow(acc, binBox, b);
            accCount += binCount[b];
            rightArea[b] = area(acc);
            rightCount[b] = accCount;
        }
        acc = newEmptyBox();
        accCount = 0;
        double best = Double.POSITIVE_INFINITY;
        lastBestBin = -1;
        for (int b = 0; b < BINS - 1; b++) {
            grow(acc, binBox, b);
            accCount += binCount[b];
            if (accCount == 0 || rightCount[b + 1] == 0) {
                continue;
            }
            double cost = area(acc) * accCount + rightArea[b + 1] * rightCount[b + 1];
            if (cost < best) {
                best = cost;
                lastBestBin = b;
            }
        }
        return best;
    }

    /** Moves primitives whose centroid falls in bins 0..splitBin to the front; returns the split index. */
    private int partition(int start, int end, int axis, double cmin, double cext, int splitBin) {
        double scale = BINS / cext;
        int i = start;
        int j = end - 1;
        while (i <= j) {
            if (bin(centroids[3 * primRef[i] + axis], cmin, scale) <= splitBin) {
                i++;
            } else {
                int tmp = primRef[i];
                primRef[i] = primRef[j];
                primRef[j] = tmp;
                j--;
            }
        }
        return i;
    }

    private static int bin(double c, double cmin, double scale) {
        int b = (int) ((c - cmin) * scale);
        return b < 0 ? 0 : (b >= BINS ? BINS - 1 : b);
    }

    private void makeLeaf(int node, int start, int count) {
        info[2 * node] = start;
        info[2 * node + 1] = count << 2;
    }

    private double[] rangeBounds(int start, int end) {
        double[] b = newEmptyBox();
        for (int k = start; k < end; k++) {
            grow(b, boxes, primRef[k]);
        }
        return b;
    }

    /** Stores the box rounded outwards to float, so that it still encloses its primitives. */
    private void writeBounds(int node, double[] b) {
        int o = 6 * node;
        for (int c = 0; c < 3; c++) {
            bounds[o + c] = roundDown(b[c]);
            bounds[o + 3 + c] = roundUp(b[3 + c]);
        }
    }

    private static float roundDown(double v) {
        float f = (float) v;
        return f > v ? Math.nextDown(f) : f;
    }

    private static float roundUp(double v) {
        float f = (float) v;
        return f < v ? Math.nextUp(f) : f;
    }

    private static double[] newEmptyBox() {
        return new double[] {
            Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
    }

    private static void grow(double[] acc, double[] src, int index) {
        int o = 6 * index;
        for (int c = 0; c < 3; c++) {
            acc[c] = Math.min(acc[c], src[o + c]);
            acc[3 + c] = Math.max(acc[3 + c], src[o + 3 + c]);
        }
    }

    private static double area(double[] b) {
        double dx = b[3] - b[0], dy = b[4] - b[1], dz = b[5] - b[2];
        if (dx < 0 || dy < 0 || dz < 0) {
            return 0;
        }
        return 2 * (dx * dy + dy * dz + dz * dx);
    }
}
