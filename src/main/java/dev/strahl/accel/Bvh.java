package dev.strahl.accel;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.RayTriangle;

/**
 * An eight-wide bounding volume hierarchy over the primitives of a {@link Geometry}: nodes with
 * their children's boxes side by side, and leaves whose triangles are copied into blocks of four
 * ({@link BvhLayout}), so that one node is one 8-lane slab test and one block one 4-lane
 * triangle test. Built by {@link BvhBuilder} (binned SAH, then collapsed by {@link BvhWriter}),
 * which also reorders the primitives so that every leaf is a contiguous range of
 * {@link #geometry()}: hits name primitives of that geometry, not of the one the hierarchy was
 * built from. Immutable and shared by all render threads; each thread passes its own
 * {@link TraversalStack}.
 *
 * <p>Two kernels traverse it: {@link SimdKernel} (the Vector API) where {@link Simd#enabled()},
 * once C2 has compiled it ({@link SimdWarmUp}), else {@link ScalarKernel}, its twin; both give
 * the same bits (hits, distances, barycentrics), so the switch does not show in any image.
 * Triangles are tested with {@link RayTriangle} (the watertight test of Woop et al. 2013, in
 * double from the float vertices), as {@link Geometry#intersect(int, int, Ray, Hit, boolean)}
 * does, so the tree and a loop over all primitives agree bit for bit.
 */
public final class Bvh implements Aggregate {
    final Geometry geometry;
    final int triangleCount;
    final byte[] flags;
    /** The nodes, {@link BvhLayout#NODE} floats each; node 0 is the root. */
    final float[] nodes;
    private final int nodeCount;
    /** The leaves' triangle blocks, {@link BvhLayout#BLOCK} floats each. */
    final float[] blocks;
    /** Which kernel answers: {@link #SCALAR}, {@link #WHEN_WARM} or {@link #ALWAYS}. */
    private final int kernel;
    /** The scalar kernel; the SIMD one once {@link SimdWarmUp#ready()}, the scalar one until then; the SIMD one. */
    private static final int SCALAR = 0, WHEN_WARM = 1, ALWAYS = 2;

    Bvh(Geometry geometry, float[] nodes, int nodeCount, float[] blocks) {
        this(geometry, nodes, nodeCount, blocks, !Simd.enabled() ? SCALAR : Simd.ALWAYS.equals(System.getProperty(Simd.PROPERTY)) ? ALWAYS : WHEN_WARM);
    }

    private Bvh(Geometry geometry, float[] nodes, int nodeCount, float[] blocks, int kernel) {
        this.geometry = geometry;
        this.triangleCount = geometry.triangleCount();
        this.flags = geometry.flagArray();
        this.nodes = nodes;
        this.nodeCount = nodeCount;
        this.blocks = blocks;
        this.kernel = kernel;
    }

    /**
     * Builds the hierarchy with a binned surface-area heuristic. The returned tree's
     * {@link #geometry()} holds the same primitives as {@code geometry} in leaf order; use it,
     * not the argument, to look up hits. Takes the SIMD kernel if {@link Simd#enabled()}.
     */
    public static Bvh build(Geometry geometry) {
        return new BvhBuilder(geometry, Runtime.getRuntime().availableProcessors()).build();
    }

    /**
     * The same tree traversed by the SIMD kernel from the first query on, warm or not, or by the
     * scalar one (for tests and benchmarks comparing the two).
     *
     * @throws IllegalStateException if the SIMD kernel is asked for where it cannot run
     */
    public Bvh withSimd(boolean on) {
        if (on && !Simd.AVAILABLE) {
            throw new IllegalStateException("the SIMD kernel needs the JVM option --add-modules jdk.incubator.vector"
                    + " and a processor with 256-bit vectors");
        }
        return new Bvh(geometry, nodes, nodeCount, blocks, on ? ALWAYS : SCALAR);
    }

    /** Whether queries take the Vector API kernel (once it is compiled, for a tree built with the default). */
    public boolean usesSimd() {
        return kernel != SCALAR;
    }

    @Override
    public String kernel() {
        return "bvh8, " + Simd.describe(kernel != SCALAR);
    }

    private boolean simdNow() {
        return kernel == ALWAYS || kernel == WHEN_WARM && SimdWarmUp.ready();
    }

    /** The same primitives without the tree ({@link BruteForce}). */
    @Override
    public Aggregate bruteForce() {
        return new BruteForce(geometry);
    }

    @Override
    public Geometry geometry() {
        return geometry;
    }

    public int nodeCount() {
        return nodeCount;
    }

    /** Bytes held by the nodes and the leaves' triangle blocks. */
    @Override
    public long byteSize() {
        return 4L * nodes.length + 4L * blocks.length;
    }

    /** The arrays themselves (not copies), for structural checks by tests in this package. */
    record Layout(float[] nodes, float[] blocks) {
        /** Coordinate k (min x, y, z, max x, y, z) of child c's box in node i. */
        float box(int i, int k, int c) {
            return nodes[BvhLayout.NODE * i + BvhLayout.WIDTH * k + c];
        }

        int child(int i, int c) {
            return Float.floatToRawIntBits(nodes[BvhLayout.NODE * i + BvhLayout.CHILDREN + c]);
        }

        int blockPrim(int block) {
            return BvhLayout.firstPrim(Float.floatToRawIntBits(blocks[BvhLayout.BLOCK * block + BvhLayout.BLOCK_PRIMS]));
        }

        int blockCount(int block) {
            return BvhLayout.primCount(Float.floatToRawIntBits(blocks[BvhLayout.BLOCK * block + BvhLayout.BLOCK_PRIMS]));
        }
    }

    Layout layout() {
        return new Layout(nodes, blocks);
    }

    /** Allocates a traversal stack for one thread. */
    public static TraversalStack newStack() {
        return new TraversalStack();
    }

    /**
     * Finds the closest hit in (0, ray.tMax): on success fills {@code hit} and shortens
     * {@code ray.tMax}. At an interior node the eight children's boxes are tested; those the ray
     * enters are visited nearest first, the others pushed, so that a node farther than a hit
     * found meanwhile is dropped without another look. The per-ray set-up
     * ({@link TraversalStack#prepare}) is done once, here, out of the kernels' loops.
     *
     * <p>The slab tests run in float, kept conservative (never losing a box the exact ray
     * touches): the origin is bounded by the floats just below and above it, each slab uses the
     * bound that makes its distance err outwards, and the remaining rounding is covered by
     * {@link ScalarKernel#MARGIN_ULPS}. Distances are compared as float bits.
     *
     * @param cullBackFaces ignore back faces of closed meshes (camera and continuation rays only)
     */
    @Override
    public boolean intersect(Ray ray, Hit hit, TraversalStack stack, boolean cullBackFaces) {
        if (nodeCount == 0) {
            return false;
        }
        stack.prepare(ray);
        return simdNow() ? SimdKernel.closestHit(this, ray, hit, stack, cullBackFaces) : ScalarKernel.closestHit(this, ray, hit, stack, cullBackFaces);
    }

    /** Whether anything blocks the ray in (0, ray.tMax); stops at the first blocker found. Never culls. */
    @Override
    public boolean occluded(Ray ray, TraversalStack stack) {
        if (nodeCount == 0) {
            return false;
        }
        stack.prepare(ray);
        return simdNow() ? SimdKernel.anyHit(this, ray, stack) : ScalarKernel.anyHit(this, ray, stack);
    }
}
