package dev.strahl.accel;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;

/**
 * A bounding volume hierarchy over the primitives of a {@link Geometry}, flattened to arrays in
 * depth-first order: the left child of interior node i is i + 1. Built by {@link BvhBuilder}.
 * Immutable and shared by all render threads; each thread passes its own traversal stack.
 *
 * <p>Node i: {@code bounds[6i .. 6i+5]} = min x, y, z, max x, y, z; {@code info[2i]} = first
 * index into {@code primRef} for a leaf, index of the right child for an interior node;
 * {@code info[2i+1]} = (primitive count &lt;&lt; 2) | split axis, the count being 0 for interior nodes.
 */
public final class Bvh {
    /** Traversal stack size: deeper than any tree the builder makes from float coordinates (its depth is asserted at build time). */
    public static final int STACK_SIZE = 128;

    private final Geometry geometry;
    private final float[] bounds;
    private final int[] info;
    private final int[] primRef;
    private final int nodeCount;

    Bvh(Geometry geometry, float[] bounds, int[] info, int[] primRef, int nodeCount) {
        this.geometry = geometry;
        this.bounds = bounds;
        this.info = info;
        this.primRef = primRef;
        this.nodeCount = nodeCount;
    }

    /** Builds the hierarchy with a binned surface-area heuristic. */
    public static Bvh build(Geometry geometry) {
        return new BvhBuilder(geometry).build();
    }

    public Geometry geometry() {
        return geometry;
    }

    public int nodeCount() {
        return nodeCount;
    }

    /** Bytes held by the node and reference arrays. */
    public long byteSize() {
        return 4L * bounds.length + 4L * info.length + 4L * primRef.length;
    }

    /** The node arrays themselves (not copies), for structural checks by tests in this package. */
    record Layout(float[] bounds, int[] info, int[] primRef) {}

    Layout layout() {
        return new Layout(bounds, info, primRef);
    }

    /** Allocates a traversal stack for one thread. */
    public static TraversalStack newStack() {
        return new TraversalStack();
    }

    /**
     * Finds the closest hit in (0, ray.tMax): on success fills {@code hit} and shortens
     * {@code ray.tMax}. At an interior node both children's boxes are tested; the nearer one is
     * visited first and the farther one pushed with its entry distance, so that it is skipped if
     * a closer hit turns up meanwhile.
     *
     * @param cullBackFaces ignore back faces of closed meshes (camera and continuation rays only)
     */
    public boolean intersect(Ray ray, Hit hit, TraversalStack stack, boolean cullBackFaces) {
        if (nodeCount == 0) {
            return false;
        }
        double ix = 1 / ray.d.x, iy = 1 / ray.d.y, iz = 1 / ray.d.z;
        double ox = ray.o.x * ix, oy = ray.o.y * iy, oz = ray.o.z * iz;
        int nearX = ix < 0 ? 3 : 0, nearY = iy < 0 ? 4 : 1, nearZ = iz < 0 ? 5 : 2;
        if (entry(0, ox, oy, oz, ix, iy, iz, nearX, nearY, nearZ, ray.tMax) == MISS) {
            return false;
        }
        int[] nodes = stack.nodes;
        double[] entry = stack.entry;
        boolean found = false;
        int sp = 0;
        int node = 0;
        while (true) {
            int first = info[2 * node];
            int count = info[2 * node + 1] >>> 2;
            if (count > 0) {
                for (int k = first, end = first + count; k < end; k++) {
                    found |= geometry.intersect(primRef[k], ray, hit, cullBackFaces);
                }
            } else {
                int left = node + 1;
                double tLeft = entry(left, ox, oy, oz, ix, iy, iz, nearX, nearY, nearZ, ray.tMax);
                double tRight = entry(first, ox, oy, oz, ix, iy, iz, nearX, nearY, nearZ, ray.tMax);
                if (tLeft != MISS && tRight != MISS) {
                    if (tLeft <= tRight) {
                        nodes[sp] = first;
                        entry[sp++] = tRight;
                        node = left;
                    } else {
                        nodes[sp] = left;
                        entry[sp++] = tLeft;
                        node = first;
                    }
                    continue;
                }
                if (tLeft != MISS) {
                    node = left;
                    continue;
                }
                if (tRight != MISS) {
                    node = first;
                    continue;
                }
            }
            // Pop the next node the ray still enters before the closest hit.
            do {
                if (sp == 0) {
                    return found;
                }
                node = nodes[--sp];
            } while (entry[sp] > ray.tMax);
        }
    }

    /** Whether anything blocks the ray in (0, ray.tMax); stops at the first blocker found. */
    public boolean occluded(Ray ray, TraversalStack stack) {
        if (nodeCount == 0) {
            return false;
        }
        double ix = 1 / ray.d.x, iy = 1 / ray.d.y, iz = 1 / ray.d.z;
        double ox = ray.o.x * ix, oy = ray.o.y * iy, oz = ray.o.z * iz;
        int nearX = ix < 0 ? 3 : 0, nearY = iy < 0 ? 4 : 1, nearZ = iz < 0 ? 5 : 2;
        int[] nodes = stack.nodes;
        int sp = 0;
        int node = 0;
        while (true) {
            if (entry(node, ox, oy, oz, ix, iy, iz, nearX, nearY, nearZ, ray.tMax) != MISS) {
                int first = info[2 * node];
                int count = info[2 * node + 1] >>> 2;
                if (count > 0) {
                    for (int k = first, end = first + count; k < end; k++) {
                        if (geometry.occludes(primRef[k], ray)) {
                            return true;
                        }
                    }
                } else {
                    nodes[sp++] = first;
                    node = node + 1;
                    continue;
                }
            }
            if (sp == 0) {
                return false;
            }
            node = nodes[--sp];
        }
    }

    private static final double MISS = Double.POSITIVE_INFINITY;
    /** Widens the far slab distance by a few ulps so that round-off never loses a box the ray touches. */
    private static final double ROUNDING_MARGIN = 1 + 0x1p-50;

    /**
     * Slab test (Kay &amp; Kajiya 1986) of node {@code node}'s box for t in (0, tMax): the distance at
     * which the ray enters the box, or {@link #MISS}. The ray is given as its inverse direction
     * and origin·inverse direction, so that each slab costs one multiply and one subtract; near*
     * index the box corner the ray meets first on each axis. A NaN slab distance (origin on a slab
     * plane, direction parallel to it) fails every comparison and so does not cut the interval,
     * which keeps the test conservative.
     */
    private double entry(int node, double ox, double oy, double oz, double ix, double iy, double iz,
                         int nearX, int nearY, int nearZ, double tMax) {
        int b = 6 * node;
        double tx0 = bounds[b + nearX] * ix - ox;
        double tx1 = bounds[b + 3 - nearX] * ix - ox;
        double ty0 = bounds[b + nearY] * iy - oy;
        double ty1 = bounds[b + 5 - nearY] * iy - oy;
        double tz0 = bounds[b + nearZ] * iz - oz;
        double tz1 = bounds[b + 7 - nearZ] * iz - oz;
        double tNear = 0;
        double tFar = tMax;
        tNear = tx0 > tNear ? tx0 : tNear;
        tNear = ty0 > tNear ? ty0 : tNear;
        tNear = tz0 > tNear ? tz0 : tNear;
        tFar = tx1 < tFar ? tx1 : tFar;
        tFar = ty1 < tFar ? ty1 : tFar;
        tFar = tz1 < tFar ? tz1 : tFar;
        return tNear <= tFar * ROUNDING_MARGIN ? tNear : MISS;
    }
}
