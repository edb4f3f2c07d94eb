package dev.strahl.accel;

import static dev.strahl.accel.BvhLayout.BLOCK;
import static dev.strahl.accel.BvhLayout.BLOCK_PRIMS;
import static dev.strahl.accel.BvhLayout.CHILDREN;
import static dev.strahl.accel.BvhLayout.LANES;
import static dev.strahl.accel.BvhLayout.NODE;
import static dev.strahl.accel.BvhLayout.WIDTH;

import dev.strahl.geometry.Geometry;
import java.util.Arrays;

/**
 * Writes a {@link BvhBuilder}'s binary tree as the eight-wide {@link Bvh} ({@link BvhLayout}):
 * each wide node collects up to eight children by repeatedly opening the interior child of
 * largest surface area (as Embree's and pbrt's wide BVHs do), in one depth-first pass, so the
 * result does not depend on the order in which the parallel build made the binary nodes. A
 * node's children keep the binary tree's left-to-right order. Also hands the geometry its new
 * primitive order, in which every leaf is a contiguous range, and copies each triangle leaf's
 * vertices into blocks of four, in the order the leaves are met, so that a node's leaves lie
 * side by side.
 */
final class BvhWriter {
    private final Geometry geometry;
    private final int n;
    private final int triangleCount;
    private final int[] ref, nodeA, nodeB;
    private final float[] nodeBox;
    private final int[] newId;
    private int[] nodes;
    private int nodeCount;
    /** Per block: its first primitive (in the new order) and its triangle count. */
    private int[] blockPrim, blockSize;
    private int blockCount;

    /** Takes the builder's binary tree: node b has box nodeBox[6b..], and children nodeA[b], nodeB[b] or (leaf) range nodeA[b], ~nodeB[b] of ref. */
    BvhWriter(Geometry geometry, int[] ref, int[] nodeA, int[] nodeB, float[] nodeBox) {
        this.geometry = geometry;
        this.n = ref.length;
        this.ref = ref;
        this.nodeA = nodeA;
        this.nodeB = nodeB;
        this.nodeBox = nodeBox;
        this.newId = new int[n];
        this.triangleCount = geometry.triangleCount();
        this.nodes = new int[NODE * Math.max(1, n / 8)];
        this.blockPrim = new int[Math.max(1, triangleCount / 2)];
        this.blockSize = new int[blockPrim.length];
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
        float[] out = new float[NODE * nodeCount];
        for (int i = 0; i < out.length; i++) {
            out[i] = Float.intBitsToFloat(nodes[i]);
            if (Float.floatToRawIntBits(out[i]) != nodes[i]) {
                throw new IllegalStateException("float bits not preserved for node word " + i);
            }
        }
        Geometry leafOrder = geometry.permute(order);
        return new Bvh(leafOrder, out, nodeCount, blocks(leafOrder));
    }

    private int allocate() {
        int node = nodeCount++;
        if (NODE * nodeCount > nodes.length) {
            nodes = Arrays.copyOf(nodes, 2 * nodes.length);
        }
        int o = NODE * node;
        Arrays.fill(nodes, o, o + 3 * WIDTH, Float.floatToRawIntBits(Float.POSITIVE_INFINITY));
        Arrays.fill(nodes, o + 3 * WIDTH, o + 6 * WIDTH, Float.floatToRawIntBits(Float.NEGATIVE_INFINITY));
        Arrays.fill(nodes, o + CHILDREN, o + NODE, BvhLayout.EMPTY);
        return node;
    }

    /** Writes the wide node for interior binary node {@code b}; returns its index. */
    private int writeNode(int b, int depth) {
        if (depth > BvhLayout.MAX_DEPTH) {
            throw new IllegalStateException("BVH deeper than " + BvhLayout.MAX_DEPTH + " levels");
        }
        int k = 2;
        int[] kid = new int[WIDTH];
        kid[0] = nodeA[b];
        kid[1] = nodeB[b];
        while (k < WIDTH) {
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
            // The opened child's two children take its place, in order: the slots stay left to right.
            System.arraycopy(kid, open + 1, kid, open + 2, k - open - 1);
            int opened = kid[open];
            kid[open] = nodeA[opened];
            kid[open + 1] = nodeB[opened];
            k++;
        }
        int node = allocate();
        for (int i = 0; i < k; i++) {
            setChild(node, i, kid[i]);
        }
        for (int i = 0; i < k; i++) {
            if (nodeB[kid[i]] >= 0) {
                int child = writeNode(kid[i], depth + 1);     // may grow the arrays: index them after
                nodes[NODE * node + CHILDREN + i] = child;
            }
        }
        return node;
    }

    private void setChild(int node, int slot, int b) {
        int o = NODE * node + slot;
        for (int c = 0; c < 6; c++) {
            nodes[o + WIDTH * c] = Float.floatToRawIntBits(nodeBox[6 * b + c]);
        }
        if (nodeB[b] < 0) {
            nodes[NODE * node + CHILDREN + slot] = leaf(newId[nodeA[b]], ~nodeB[b]);
        }
    }

    /** The reference of a leaf of {@code count} primitives from {@code first} (new order) on; reserves its blocks. */
    private int leaf(int first, int count) {
        if (first >= triangleCount) {
            return BvhLayout.sphereLeaf(first, count);
        }
        int blocks = (count + LANES - 1) / LANES;
        if (blockCount + blocks > blockPrim.length) {
            blockPrim = Arrays.copyOf(blockPrim, 2 * blockPrim.length + blocks);
            blockSize = Arrays.copyOf(blockSize, blockPrim.length);
        }
        int firstBlock = blockCount;
        for (int j = 0; j < blocks; j++) {
            blockPrim[blockCount] = first + LANES * j;
            blockSize[blockCount] = Math.min(LANES, count - LANES * j);
            blockCount++;
        }
        return BvhLayout.triangleLeaf(firstBlock, blocks);
    }

    /** The blocks' contents: vertex planes from the reordered geometry, NaN in unused lanes, the word of primitives. */
    private float[] blocks(Geometry g) {
        float[] pos = g.positionArray();
        int[] tri = g.indexArray();
        float[] out = new float[BLOCK * blockCount];
        for (int j = 0; j < blockCount; j++) {
            int o = BLOCK * j;
            Arrays.fill(out, o, o + BLOCK_PRIMS, Float.NaN);
            for (int lane = 0; lane < blockSize[j]; lane++) {
                int prim = blockPrim[j] + lane;
                for (int v = 0; v < 3; v++) {
                    int p = 3 * tri[3 * prim + v];
                    for (int k = 0; k < 3; k++) {
                        out[o + LANES * (3 * v + k) + lane] = pos[p + k];
                    }
                }
            }
            out[o + BLOCK_PRIMS] = Float.intBitsToFloat(BvhLayout.prims(blockPrim[j], blockSize[j]));
        }
        return out;
    }
}
