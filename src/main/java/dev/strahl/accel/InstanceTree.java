package dev.strahl.accel;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.InstanceTransforms;
import dev.strahl.geometry.Ray;
import java.util.Arrays;
import java.util.Comparator;
import java.util.stream.IntStream;

/**
 * The top level of {@link TwoLevelBvh}: a binary tree over the instances' world bounds, split at
 * the median of the longest axis of the boxes' centres, leaves of at most {@value #LEAF}
 * instances. Instances number hundreds or thousands where triangles number millions, so this
 * level is small and tested in double; the depth is at most log2 of the instance count (below
 * {@link #MAX_DEPTH}). Node i is six doubles of box at {@code box[6i]} (minima, maxima) and two
 * ints at {@code link[2i]}: its children, or for a leaf {@code -1 - first} and the count of its
 * instances in {@code order}.
 */
final class InstanceTree {
    /** Instances a leaf may hold. */
    static final int LEAF = 2;
    /** Depth no tree reaches (2^31 instances would); the traversal stack's size. */
    static final int MAX_DEPTH = 64;
    /** The entry distance of a box the ray misses. */
    static final double MISS = Double.POSITIVE_INFINITY;

    private final double[] box;
    private final int[] link;
    private final int[] order;
    private int nodes;

    private InstanceTree(int instances) {
        int capacity = Math.max(1, 2 * instances);
        box = new double[6 * capacity];
        link = new int[2 * capacity];
        order = new int[instances];
    }

    /** The tree over instance i's world box: the box of its group's {@code groupBoxes} moved by its transform. */
    static InstanceTree build(InstanceTransforms instances, Aabb[] groupBoxes) {
        int n = instances.count();
        InstanceTree t = new InstanceTree(n);
        if (n == 0) {
            return t;
        }
        Aabb[] boxes = new Aabb[n];
        double[][] centre = new double[n][3];
        for (int i = 0; i < n; i++) {
            boxes[i] = instances.bounds(i, groupBoxes[instances.group(i)], new Aabb());
            for (int k = 0; k < 3; k++) {
                centre[i][k] = 0.5 * (boxes[i].min(k) + boxes[i].max(k));
            }
        }
        Integer[] ids = IntStream.range(0, n).boxed().toArray(Integer[]::new);
        t.nodes = 1;
        t.split(0, ids, 0, n, boxes, centre);
        return t;
    }

    private void split(int node, Integer[] ids, int from, int to, Aabb[] boxes, double[][] centre) {
        Aabb b = new Aabb(), c = new Aabb();
        for (int k = from; k < to; k++) {
            b.include(boxes[ids[k]]);
            c.include(centre[ids[k]][0], centre[ids[k]][1], centre[ids[k]][2]);
        }
        // A margin of a few ulps of the largest coordinate: the instances' boxes were moved in double.
        double pad = 1e-12 * Math.max(Math.max(Math.abs(b.minX), Math.abs(b.maxX)), Math.max(Math.max(Math.abs(b.minY), Math.abs(b.maxY)),
                Math.max(Math.abs(b.minZ), Math.abs(b.maxZ))));
        double[] bounds = {b.minX - pad, b.minY - pad, b.minZ - pad, b.maxX + pad, b.maxY + pad, b.maxZ + pad};
        System.arraycopy(bounds, 0, box, 6 * node, 6);
        if (to - from <= LEAF) {
            link[2 * node] = -1 - from;
            link[2 * node + 1] = to - from;
            for (int k = from; k < to; k++) {
                order[k] = ids[k];
            }
            return;
        }
        int axis = c.extent(0) >= c.extent(1) && c.extent(0) >= c.extent(2) ? 0 : c.extent(1) >= c.extent(2) ? 1 : 2;
        // Sorted by centre, ties by instance: the same tree on every run.
        Arrays.sort(ids, from, to, Comparator.<Integer>comparingDouble(i -> centre[i][axis]).thenComparingInt(i -> i));
        int mid = (from + to) >>> 1, left = nodes, right = nodes + 1;
        nodes += 2;
        link[2 * node] = left;
        link[2 * node + 1] = right;
        split(left, ids, from, mid, boxes, centre);
        split(right, ids, mid, to, boxes, centre);
    }

    boolean isEmpty() {
        return order.length == 0;
    }

    boolean isLeaf(int node) {
        return link[2 * node] < 0;
    }

    int left(int node) {
        return link[2 * node];
    }

    int right(int node) {
        return link[2 * node + 1];
    }

    int first(int node) {
        return -1 - link[2 * node];
    }

    int count(int node) {
        return link[2 * node + 1];
    }

    int instance(int k) {
        return order[k];
    }

    /** Sets up the ray's slab constants in {@code s}; whether the ray enters the root's box before ray.tMax. */
    boolean prepare(Ray ray, TraversalStack s) {
        s.topOx = ray.o.x;
        s.topOy = ray.o.y;
        s.topOz = ray.o.z;
        s.topIx = 1 / ray.d.x;
        s.topIy = 1 / ray.d.y;
        s.topIz = 1 / ray.d.z;
        return entry(0, s, ray.tMax) != MISS;
    }

    /**
     * Where the ray prepared in {@code s} enters node i's box, clamped to 0, or {@link #MISS} if it
     * does not before {@code tMax}. A slab whose distances are NaN (the origin on its plane, the
     * direction along it) does not cut the interval: the test errs towards entering.
     */
    double entry(int node, TraversalStack s, double tMax) {
        int o = 6 * node;
        double tn = 0, tf = tMax;
        double a = (box[o] - s.topOx) * s.topIx, b = (box[o + 3] - s.topOx) * s.topIx;
        tn = Math.min(a, b) > tn ? Math.min(a, b) : tn;
        tf = Math.max(a, b) < tf ? Math.max(a, b) : tf;
        a = (box[o + 1] - s.topOy) * s.topIy;
        b = (box[o + 4] - s.topOy) * s.topIy;
        tn = Math.min(a, b) > tn ? Math.min(a, b) : tn;
        tf = Math.max(a, b) < tf ? Math.max(a, b) : tf;
        a = (box[o + 2] - s.topOz) * s.topIz;
        b = (box[o + 5] - s.topOz) * s.topIz;
        tn = Math.min(a, b) > tn ? Math.min(a, b) : tn;
        tf = Math.max(a, b) < tf ? Math.max(a, b) : tf;
        // The far distance grown by a few ulps: the slabs' own round-off must not lose a box the ray grazes.
        return tn <= tf * (1 + 1e-12) ? tn : MISS;
    }

    long byteSize() {
        return 8L * box.length + 4L * link.length + 4L * order.length;
    }
}
