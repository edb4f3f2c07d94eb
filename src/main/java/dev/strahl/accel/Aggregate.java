package dev.strahl.accel;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;

/**
 * What the renderer asks of its primitives: the closest hit along a ray and whether anything
 * blocks a ray, one ray at a time or for a batch of rays. {@link Bvh} answers with its tree,
 * {@link BruteForce} by testing every primitive (the teaching option {@code --accel none}); both
 * give the same answers. Implementations are immutable and shared by all threads; each thread
 * passes its own {@link TraversalStack}.
 *
 * <p>The batch queries run the single-ray kernel ray after ray today; they are the seam a
 * wavefront integrator (which traces a whole queue of rays at a time) and a kernel that follows
 * several rays down the tree at once plug into, without a change to their callers.
 */
public interface Aggregate {
    /** The primitives, in the order the hits' primitive ids refer to. */
    Geometry geometry();

    /**
     * Finds the closest hit in (0, ray.tMax): on success fills {@code hit} (distance, primitive,
     * barycentrics of a triangle) and shortens {@code ray.tMax} to the hit.
     *
     * @param cullBackFaces ignore back faces of closed meshes (camera and continuation rays only)
     */
    boolean intersect(Ray ray, Hit hit, TraversalStack stack, boolean cullBackFaces);

    /** Whether anything blocks the ray in (0, ray.tMax); leaves the ray alone. */
    boolean occluded(Ray ray, TraversalStack stack);

    /**
     * The closest hits of rays [from, to) of {@code rays}: for each, what
     * {@link #intersect(Ray, Hit, TraversalStack, boolean)} gives, into the batch's hit arrays
     * (primitive -1 for a miss; tMax shortened to a hit).
     */
    default void intersect(RayBatch rays, int from, int to, TraversalStack stack, boolean cullBackFaces) {
        Ray ray = stack.ray;
        Hit hit = stack.hit;
        for (int i = from; i < to; i++) {
            rays.load(i, ray);
            hit.reset();
            intersect(ray, hit, stack, cullBackFaces);
            rays.store(i, ray, hit);
        }
    }

    /** Whether each of rays [from, to) of {@code rays} is blocked, into {@link RayBatch#occluded}. */
    default void occluded(RayBatch rays, int from, int to, TraversalStack stack) {
        Ray ray = stack.ray;
        for (int i = from; i < to; i++) {
            rays.load(i, ray);
            rays.occluded[i] = occluded(ray, stack);
        }
    }

    /** The same primitives answered by a loop over all of them (the teaching option {@code --accel none}). */
    Aggregate bruteForce();

    /** Bytes of the acceleration structure itself (not counting {@link #geometry()}). */
    long byteSize();

    /** What answers the queries, for reports: "bvh8, simd (…)", "bvh8, scalar" or "brute force". */
    String kernel();
}
