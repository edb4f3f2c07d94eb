package dev.strahl.accel;

import static dev.strahl.accel.BvhBuilder.BINS;

/**
 * The bins of one split of {@link BvhBuilder}: per axis and bin the count of centroids in it
 * and the bounds of their boxes (as ordered keys, see {@link BvhBuilder#key}), and the SAH
 * sweep over them. One per thread, reused at every split it makes; chunks of a large range bin
 * into their own and are merged.
 */
final class Bins {
    final int[] count = new int[3 * BINS];
    final int[] box = new int[3 * BINS * 6];           // bin (axis, b) at 6 * (axis * BINS + b), as ordered keys
    // The sweep's running unions: at bin b, the area and count of bins b..last (right) and 0..b (left).
    private final double[] rightArea = new double[BINS], leftArea = new double[BINS];
    private final int[] rightCount = new int[BINS], leftCount = new int[BINS];
    final float[] centroidBounds = new float[6];
    int bins;                                           // bins in use at this split
    int lastBin;

    /** Sorts every reference of [start, end) into its bin on each axis over the centroid bounds {@code cb}, growing the bins' boxes. */
    void fill(References refs, int start, int end, float[] cb) {
        int nb = bins;
        int[] key = refs.key;
        float[] centroid = refs.centroid;
        clear();
        float sx = scale(cb, 0, nb), sy = scale(cb, 1, nb), sz = scale(cb, 2, nb);
        for (int p = start; p < end; p++) {
            int bx = bin(centroid[3 * p], cb[0], sx, nb);
            int by = BINS + bin(centroid[3 * p + 1], cb[1], sy, nb);
            int bz = 2 * BINS + bin(centroid[3 * p + 2], cb[2], sz, nb);
            count[bx]++;
            count[by]++;
            count[bz]++;
            int q = 6 * p;
            int x0 = key[q], y0 = key[q + 1], z0 = key[q + 2], x1 = key[q + 3], y1 = key[q + 4], z1 = key[q + 5];
            grow(box, 6 * bx, x0, y0, z0, x1, y1, z1);
            grow(box, 6 * by, x0, y0, z0, x1, y1, z1);
            grow(box, 6 * bz, x0, y0, z0, x1, y1, z1);
        }
    }

    /** Bins per unit of centroid extent on one axis (0 for no extent). */
    static float scale(float[] cb, int axis, int bins) {
        float ext = cb[3 + axis] - cb[axis];
        return ext > 0 ? bins / ext : 0;
    }

    /** The bin of a centroid: c ≥ cmin, so only the upper end needs clamping (a centroid on the upper bound). */
    static int bin(float c, float cmin, float scale, int bins) {
        return Math.min((int) ((c - cmin) * scale), bins - 1);
    }

    /** Adds another chunk's bins (order-independent: sums, minima, maxima). */
    void merge(Bins o) {
        for (int axis = 0; axis < 3; axis++) {
            for (int b = 0; b < bins; b++) {
                int i = axis * BINS + b;
                count[i] += o.count[i];
                grow(box, 6 * i, o.box[6 * i], o.box[6 * i + 1], o.box[6 * i + 2], o.box[6 * i + 3], o.box[6 * i + 4], o.box[6 * i + 5]);
            }
        }
    }

    /** Empties the bins in use. */
    void clear() {
        for (int axis = 0; axis < 3; axis++) {
            for (int b = 0; b < bins; b++) {
                count[axis * BINS + b] = 0;
                int o = 6 * (axis * BINS + b);
                box[o] = box[o + 1] = box[o + 2] = Integer.MAX_VALUE;
                box[o + 3] = box[o + 4] = box[o + 5] = Integer.MIN_VALUE;
            }
        }
    }

    /** The union of bins [from, to) on one axis, as floats into {@code dest[o .. o + 5]}. */
    void union(int axis, int from, int to, float[] dest, int o) {
        int[] b = emptyKeys();
        for (int k = from; k < to; k++) {
            int i = 6 * (axis * BINS + k);
            grow(b, 0, box[i], box[i + 1], box[i + 2], box[i + 3], box[i + 4], box[i + 5]);
        }
        unkey(b, dest, o);
    }

    /** An empty key box, to {@link #grow}. */
    static int[] emptyKeys() {
        return new int[] {Integer.MAX_VALUE, Integer.MAX_VALUE, Integer.MAX_VALUE, Integer.MIN_VALUE, Integer.MIN_VALUE, Integer.MIN_VALUE};
    }

    /** Grows the key box at {@code o}: integer minima and maxima of ordered keys are those of the floats. */
    static void grow(int[] b, int o, int x0, int y0, int z0, int x1, int y1, int z1) {
        b[o] = Math.min(b[o], x0);
        b[o + 1] = Math.min(b[o + 1], y0);
        b[o + 2] = Math.min(b[o + 2], z0);
        b[o + 3] = Math.max(b[o + 3], x1);
        b[o + 4] = Math.max(b[o + 4], y1);
        b[o + 5] = Math.max(b[o + 5], z1);
    }

    /** The floats of a key box into {@code dest[o .. o + 5]}. */
    static void unkey(int[] b, float[] dest, int o) {
        for (int c = 0; c < 6; c++) {
            dest[o + c] = BvhBuilder.unkey(b[c]);
        }
    }

    /**
     * SAH cost (unnormalised: Σ area × count) of the best bin boundary on one axis, if below
     * {@code bound}, else +∞; records the bin in {@code lastBin}.
     */
    double sweep(int axis, double bound) {
        int nb = bins, base = axis * BINS;
        accumulate(base, nb - 1, 0, -1, rightArea, rightCount);
        accumulate(base, 0, nb - 1, 1, leftArea, leftCount);
        double best = bound;
        lastBin = -1;
        for (int b = 0; b < nb - 1; b++) {
            int left = leftCount[b], right = rightCount[b + 1];
            if (left == 0 || right == 0) {
                continue;
            }
            double cost = leftArea[b] * BvhBuilder.cost(left) + rightArea[b + 1] * BvhBuilder.cost(right);
            if (cost < best) {
                best = cost;
                lastBin = b;
            }
        }
        return lastBin >= 0 ? best : Double.POSITIVE_INFINITY;
    }

    /**
     * The running union of the bins of one axis from bin {@code from} towards {@code to}
     * (exclusive) in steps of {@code step}: at each bin, the area (0 while empty) and count of
     * the bins passed so far, that one included.
     */
    private void accumulate(int base, int from, int to, int step, double[] area, int[] counts) {
        int x0 = Integer.MAX_VALUE, y0 = x0, z0 = x0, x1 = Integer.MIN_VALUE, y1 = x1, z1 = x1;
        int acc = 0;
        for (int b = from; b != to; b += step) {
            int o = 6 * (base + b);
            x0 = Math.min(x0, box[o]);
            y0 = Math.min(y0, box[o + 1]);
            z0 = Math.min(z0, box[o + 2]);
            x1 = Math.max(x1, box[o + 3]);
            y1 = Math.max(y1, box[o + 4]);
            z1 = Math.max(z1, box[o + 5]);
            acc += count[base + b];
            area[b] = acc == 0 ? 0 : keyArea(x0, y0, z0, x1, y1, z1);
            counts[b] = acc;
        }
    }

    private static double keyArea(int x0, int y0, int z0, int x1, int y1, int z1) {
        return BvhBuilder.area(BvhBuilder.unkey(x0), BvhBuilder.unkey(y0), BvhBuilder.unkey(z0), BvhBuilder.unkey(x1), BvhBuilder.unkey(y1), BvhBuilder.unkey(z1));
    }
}
