package dev.strahl.accel;

/**
 * Where {@link Bvh} keeps what, in its two float arrays: the eight-wide nodes and the triangle
 * blocks of the leaves. Both kernels ({@link ScalarKernel}, {@link SimdKernel}) and the writer
 * ({@link BvhWriter}) read these constants, so that the layout is defined once.
 *
 * <p><b>Node</b> i is {@value #NODE} floats at {@code nodes[NODE·i ..]}: six planes of eight
 * floats, the children's boxes coordinate by coordinate (plane k at {@code 8k}: min x, min y,
 * min z, max x, max y, max z; lane c is child c), so that one 8-lane load reads one coordinate of
 * all children; then the eight children themselves as float bits at {@link #CHILDREN}: an
 * interior node's index (≥ 0), a leaf reference (negative, below), or {@link #EMPTY} with an
 * empty box (+∞ minima, −∞ maxima), which no ray enters. 224 bytes, four cache lines at most.
 *
 * <p><b>Block</b> j is {@value #BLOCK} floats at {@code blocks[BLOCK·j ..]}: up to four
 * triangles side by side, their nine vertex coordinates as planes of four ({@code 4·(3v + k)}
 * holds coordinate k of vertex v of the four triangles), then one word (int bits) at
 * {@link #BLOCK_PRIMS}: the first triangle's primitive id and the number of triangles,
 * {@code first << 2 | (count − 1)} ({@link #firstPrim}, {@link #primCount}). The triangles of a
 * block are consecutive primitives; unused lanes hold NaN vertices, which no test reports as a
 * hit. A leaf is one or more consecutive blocks. 148 bytes, 37–39 a triangle at the builder's
 * fill of 3.8 triangles a block.
 *
 * <p><b>References</b> (the children words): a triangle leaf is
 * {@code MIN_VALUE | firstBlock << 2 | (blocks − 1)}; a sphere leaf sets bit 30 as well and holds
 * its first primitive and count ({@code first << 3 | count}); {@link #EMPTY} is a sphere leaf of
 * no spheres.
 */
final class BvhLayout {
    private BvhLayout() {}

    /** Children per node, and lanes of the node test. */
    static final int WIDTH = 8;
    /** Floats per node: six box planes of eight, then the eight children. */
    static final int NODE = 7 * WIDTH;
    /** Offset of the children words in a node. */
    static final int CHILDREN = 6 * WIDTH;
    /** Triangles per block, and lanes of the leaf test. */
    static final int LANES = 4;
    /** Floats per block: nine coordinate planes of four, and the word of its primitives. */
    static final int BLOCK = 9 * LANES + 1;
    static final int BLOCK_PRIMS = 9 * LANES;
    /** Blocks a leaf may have. */
    static final int MAX_BLOCKS = 4;
    /** A child slot without a child. */
    static final int EMPTY = Integer.MIN_VALUE | 1 << 30;
    /** Depth limit of the tree; the builder's median fallback keeps real trees far below. */
    static final int MAX_DEPTH = 64;

    /** A triangle leaf of {@code blocks} blocks from block {@code first} on. */
    static int triangleLeaf(int first, int blocks) {
        if (first < 0 || first >= 1 << 28 || blocks < 1 || blocks > MAX_BLOCKS) {
            throw new IllegalArgumentException("triangle leaf out of range: block " + first + ", " + blocks + " blocks");
        }
        return Integer.MIN_VALUE | first << 2 | (blocks - 1);
    }

    /** A sphere leaf of {@code count} spheres from primitive {@code first} on. */
    static int sphereLeaf(int first, int count) {
        if (first < 0 || first >= 1 << 27 || count < 1 || count > 7) {
            throw new IllegalArgumentException("sphere leaf out of range: first " + first + ", count " + count);
        }
        return EMPTY | first << 3 | count;
    }

    static boolean isSphereLeaf(int ref) {
        return (ref & 1 << 30) != 0;
    }

    static int firstBlock(int ref) {
        return (ref & 0x3fffffff) >>> 2;
    }

    static int blockCount(int ref) {
        return (ref & 3) + 1;
    }

    static int firstSphere(int ref) {
        return (ref & 0x3fffffff) >>> 3;
    }

    static int sphereCount(int ref) {
        return ref & 7;
    }

    /** A block's word of primitives: {@code count} triangles from {@code first} on. */
    static int prims(int first, int count) {
        if (first < 0 || first >= 1 << 29 || count < 1 || count > LANES) {
            throw new IllegalArgumentException("block out of range: first " + first + ", count " + count);
        }
        return first << 2 | (count - 1);
    }

    static int firstPrim(int word) {
        return word >>> 2;
    }

    static int primCount(int word) {
        return (word & 3) + 1;
    }

    /** Traversal stack entries: at most seven siblings pushed per level, and room for one vector store of eight. */
    static final int STACK_SIZE = (WIDTH - 1) * MAX_DEPTH + 2 * WIDTH;
}
