package dev.strahl.accel;

import dev.strahl.geometry.Geometry;

/**
 * Writes a {@link BvhBuilder}'s binary tree as the four-wide {@link Bvh}: each wide node collects
 * up to four children by repeatedly opening the interior child of largest surface area (as
 * Embree's and pbrt's wide BVHs do), in one depth-first pass, so the result does not depend on
 * the order in which the parallel build made the binary nodes. Also hands the geometry its new
 * primitive order, in which every leaf is a contiguous range.
 */
final class BvhWriter {
    private final Geometry geometry;
    private final int n;
    private final int[] ref, nodeA, nodeB;
    private final float[] nodeBox;
    private final int[] newId;
    private int[] nodes;
    private int count;

    /** Takes the builder's binary tree: node b has box nodeBox[6b..], and children nodeA[b], nodeB[b] or (leaf) range nodeA[b], ~nodeB[b] of ref. */
    BvhWriter(Geometry geometry, int[] ref, int[] nodeA, int[] nodeB, float[] nodeBox) {
        this.geometry = geometry;
        this.n = ref.length;
        this.ref = ref;
        this.nodeA = nodeA;
        this.nodeB = nodeB;
        this.nodeBox = nodeBox;
        this.newId = new int[n];
        this.nodes = new int[Bvh.NODE * Math.max(1, n / 4)];
        int triangleCount = geometry.triangleCount();
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
        // Stored as floats: the children's int bits pass through intBitsToFloat and back
        // unchanged on the JVM's 64-bit platforms (checked here, since the spec does not promise it for NaN patterns).
        float[] out = new float[Bvh.NODE * count];
        for (int i = 0; i < out.length; i++) {
            out[i] = Float.intBitsToFloat(nodes[i]);
            if (Float.floatToRawIntBits(out[i]) != nodes[i]) {
                throw new IllegalStateException("float bits not preserved for node word " + i);
            }
        }
        return new Bvh(geometry.permute(order), out, count);
    }

    private int allocate() {
        int node = count++;
        if (Bvh.NODE * count > nodes.length) {
            nodes = java.util.Arrays.copyOf(nodes, 2 * nodes.length);
        }
        for (int c = 0; c < 4; c++) {
            int o = Bvh.NODE * node + c;
            for (int k = 0; k < 3; k++) {
                nodes[o + 4 * k] = Float.floatToRawIntBits(Float.POSITIVE_INFINITY);
                nodes[o + 4 * (3 + k)] = Float.floatToRawIntBits(Float.NEGATIVE_INFINITY);
            }
            nodes[Bvh.NODE * node + 24 + c] = Bvh.EMPTY;
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
                    double a = BvhBuilder.area(nodeBox, 6 * kid[i]);
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
                nodes[Bvh.NODE * node + 24 + i] = child;
            }
        }
        return node;
    }

    private void setChild(int node, int slot, int b) {
        int o = Bvh.NODE * node + slot;
        for (int c = 0; c < 6; c++) {
            nodes[o + 4 * c] = Float.floatToRawIntBits(nodeBox[6 * b + c]);
        }
        if (nodeB[b] < 0) {
            nodes[Bvh.NODE * node + 24 + slot] = Bvh.leaf(newId[nodeA[b]], ~nodeB[b]);
        }
    }

    /** The triangles' vertices copied out in primitive order, 9 floats each: {@link Bvh}'s leaf triangles. */
    static float[] leafVertices(Geometry g) {
        float[] pos = g.positionArray();
        int[] tri = g.indexArray();
        float[] v = new float[9 * g.triangleCount()];
        for (int i = 0, k = 0; i < 3 * g.triangleCount(); i++, k += 3) {
            int p = 3 * tri[i];
            v[k] = pos[p];
            v[k + 1] = pos[p + 1];
            v[k + 2] = pos[p + 2];
        }
        return v;
    }
}
