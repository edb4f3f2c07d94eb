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
    /** Traversal stack size: enough for any tree the builder makes (its depth is capped below). */
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
    public static int[] newStack() {
        return new int[STACK_SIZE];
    }

    /**
     * Finds the closest hit in (0, ray.tMax): on success fills {@code hit} and shortens
     * {@code ray.tMax}. Children are visited near-first along the split axis.
     *
     * @param cullBackFaces ignore back faces of closed meshes (camera and continuation rays only)
     */
    public boolean intersect(Ray ray, Hit hit, int[] stack, boolean cullBackFaces) {
        if (nodeCount == 0) {
            return false;
        }
        double ox = ray.o.x, oy = ray.o.y, oz = ray.o.z;
        double ix = 1 / ray.d.x, iy = 1 / ray.d.y, iz = 1 / ray.d.z;
        boolean negX = ix < 0, negY = iy < 0, negZ = iz < 0;
        boolean found = false;
        int sp = 0;
        int node = 0;
        while (true) {
            if (hitsBox(node, ox, oy, oz, ix, iy, iz, negX, negY, negZ, ray.tMax)) {
                int first = info[2 * node];
                int meta = info[2 * node + 1];
                int count = meta >>> 2;
                if (count > 0) {
                    for (int k = first, end = first + count; k < end; k++) {
                        found |= geometry.intersect(primRef[k], ray, hit, cullBackFaces);
                    }
                } else {
                    int axis = meta & 3;
                    boolean negative = axis == 0 ? negX : axis == 1 ? negY : negZ;
                    if (negative) {
                        stack[sp++] = node + 1;
                        node = first;
                    } else {
                        stack[sp++] = first;
                        node = node + 1;
                    }
                    continue;
                }
            }
            if (sp == 0) {
                return found;
            }
            node = stack[--sp];
        }
    }

    /** Whether anything blocks the ray in (0, ray.tMax); stops at the first blocker found. */
    public boolean occluded(Ray ray, int[] stack) {
        if (nodeCount == 0) {
            return false;
        }
        double ox = ray.o.x, oy = ray.o.y, oz = ray.o.z;
        double ix = 1 / ray.d.x, iy = 1 / ray.d.y, iz = 1 / ray.d.z;
        boolean negX = ix < 0, negY = iy < 0, negZ = iz < 0;
        int sp = 0;
        int node = 0;
        while (true) {
            if (hitsBox(node, ox, oy, oz, ix, iy, iz, negX, negY, negZ, ray.tMax)) {
                int first = info[2 * node];
                int count = info[2 * node + 1] >>> 2;
                if (count > 0) {
                    for (int k = first, end = first + count; k < end; k++) {
                        if (geometry.occludes(primRef[k], ray)) {
                            return true;
                        }
                    }
                } else {
                    stack[sp++] = first;
                    node = node + 1;
                    continue;
                }
            }
            if (sp == 0) {
                return false;
            }
            node = stack[--sp];
        }
    }

    /**
     * Slab test of node {@code node}'s box against t in (0, tMax). A NaN slab distance (origin on
     * a slab plane, direction parallel to it) fails every comparison and so does not cut the
     * interval, which keeps the test conservative.
     */
    private boolean hitsBox(int node, double ox, double oy, double oz, double ix, double iy, double iz,
                            boolean negX, boolean negY, boolean negZ, double tMax) {
        int b = 6 * node;
        double tx0 = ((negX ? bounds[b + 3] : bounds[b]) - ox) * ix;
        double tx1 = ((negX ? bounds[b] : bounds[b + 3]) - ox) * ix;
        double ty0 = ((negY ? bounds[b + 4] : bounds[b + 1]) - oy) * iy;
        double ty1 = ((negY ? bounds[b + 1] : bounds[b + 4]) - oy) * iy;
        double tz0 = ((negZ ? bounds[b + 5] : bounds[b + 2]) - oz) * iz;
        double tz1 = ((negZ ? bounds[b + 2] : bounds[b + 5]) - oz) * iz;
        double tNear = 0;
        double tFar = tMax;
        tNear = tx0 > tNear ? tx0 : tNear;
        tNear = ty0 > tNear ? ty0 : tNear;
        tNear = tz0 > tNear ? tz0 : tNear;
        tFar = tx1 < tFar ? tx1 : tFar;
        tFar = ty1 < tFar ? ty1 : tFar;
        tFar = tz1 < tFar ? tz1 : tFar;
        return tNear <= tFar;
    }
}
