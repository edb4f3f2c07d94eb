package dev.strahl.accel;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;

/**
 * The references that {@link BvhBuilder} partitions into leaf ranges: per position k the
 * primitive id, its box rounded outwards as ordered keys ({@link BvhBuilder#key}) and its
 * centroid. Partitioning moves the three together, so that binning reads them in order.
 */
final class References {
    private final Geometry geometry;
    private final int triangleCount;
    /** Primitive ids, partitioned in place into leaf ranges. */
    final int[] ref;
    /** Box of position k: min x, y, z, max x, y, z at 6k, as ordered keys. */
    final int[] key;
    final float[] centroid;

    References(Geometry geometry) {
        int n = geometry.primitiveCount();
        this.geometry = geometry;
        this.triangleCount = geometry.triangleCount();
        this.ref = new int[n];
        this.key = new int[6 * n];
        this.centroid = new float[3 * n];
    }

    /** Positions [from, to): reference k = primitive k, its box rounded outwards and its centroid. */
    void init(int from, int to) {
        Aabb box = new Aabb();
        for (int i = from; i < to; i++) {
            box.reset();
            geometry.includeBounds(i, box);
            float[] b = {BvhBuilder.roundDown(box.minX), BvhBuilder.roundDown(box.minY), BvhBuilder.roundDown(box.minZ),
                BvhBuilder.roundUp(box.maxX), BvhBuilder.roundUp(box.maxY), BvhBuilder.roundUp(box.maxZ)};
            for (int c = 0; c < 6; c++) {
                key[6 * i + c] = BvhBuilder.key(b[c]);
            }
            for (int c = 0; c < 3; c++) {
                centroid[3 * i + c] = 0.5f * b[c] + 0.5f * b[3 + c];
            }
            ref[i] = i;
        }
    }

    /** The bounds of the centroids of [start, end) into {@code cb} (min x, y, z, max x, y, z). */
    void centroidBounds(int start, int end, float[] cb) {
        BvhBuilder.setEmpty(cb);
        for (int k = start; k < end; k++) {
            int p = 3 * k;
            for (int c = 0; c < 3; c++) {
                float v = centroid[p + c];
                cb[c] = Math.min(cb[c], v);
                cb[3 + c] = Math.max(cb[3 + c], v);
            }
        }
    }

    /** The union of the boxes of [start, end), as floats into {@code dest[o .. o + 5]}. */
    void box(int start, int end, float[] dest, int o) {
        int[] b = Bins.emptyKeys();
        for (int k = start; k < end; k++) {
            int q = 6 * k;
            Bins.grow(b, 0, key[q], key[q + 1], key[q + 2], key[q + 3], key[q + 4], key[q + 5]);
        }
        Bins.unkey(b, dest, o);
    }

    /** Moves references whose centroid falls in bins 0..splitBin on {@code axis} to the front; returns the split index. */
    int partition(int start, int end, int axis, float cmin, float scale, int bins, int splitBin) {
        int i = start;
        int j = end - 1;
        while (i <= j) {
            if (Bins.bin(centroid[3 * i + axis], cmin, scale, bins) <= splitBin) {
                i++;
            } else {
                swap(i, j--);
            }
        }
        return i;
    }

    /** Splits at the median centroid of the longest centroid axis (quickselect); bounds the depth. */
    int medianSplit(int start, int end, float[] cb) {
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
    int typeSplit(int start, int end) {
        int i = start;
        for (int k = start; k < end; k++) {
            if (ref[k] < triangleCount) {
                swap(i++, k);
            }
        }
        return i;
    }

    /** Whether [start, end) holds only triangles or only spheres (a leaf is one contiguous range of either). */
    boolean isHomogeneous(int start, int end) {
        boolean first = ref[start] < triangleCount;
        for (int k = start + 1; k < end; k++) {
            if ((ref[k] < triangleCount) != first) {
                return false;
            }
        }
        return true;
    }

    /** Swaps the references at positions i and j with their boxes and centroids. */
    private void swap(int i, int j) {
        int r = ref[i];
        ref[i] = ref[j];
        ref[j] = r;
        for (int c = 0; c < 6; c++) {
            int t = key[6 * i + c];
            key[6 * i + c] = key[6 * j + c];
            key[6 * j + c] = t;
        }
        for (int c = 0; c < 3; c++) {
            float t = centroid[3 * i + c];
            centroid[3 * i + c] = centroid[3 * j + c];
            centroid[3 * j + c] = t;
        }
    }
}
