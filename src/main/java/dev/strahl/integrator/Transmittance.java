package dev.strahl.integrator;

import dev.strahl.accel.Aggregate;
import dev.strahl.accel.TraversalStack;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.color.MutableRgb;
import dev.strahl.medium.TrackingRandom;
import dev.strahl.world.Media;
import dev.strahl.world.SurfaceMaps;
import dev.strahl.world.World;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Shadow rays through a world with participating media: how much of the light along a segment
 * arrives. The segment is cut at every surface it crosses; an invisible surface
 * ({@link Media#isInvisible}) or a cut-away one lets the ray pass (an invisible boundary changes
 * the medium it travels in, by the rule of {@link Media#after}), any other surface blocks it. Each
 * piece multiplies the estimate by its medium's transmittance (exact for a homogeneous medium,
 * ratio tracking for a grid: {@link dev.strahl.medium.Medium#transmittance}). One per worker
 * thread; owns its scratch objects, allocates nothing.
 */
final class Transmittance {
    private final World world;
    private final Media media;
    private final Aggregate bvh;
    private final TraversalStack stack = new TraversalStack();
    private final Ray ray = new Ray();
    private final Hit hit = new Hit();
    private final SurfacePoint sp = new SurfacePoint();
    private final Vector3d previous = new Vector3d();
    /** The numbers of ratio tracking; the caller seeds it from its sampler before each query. */
    final TrackingRandom random = new TrackingRandom();
    long rays;

    Transmittance(World world) {
        this.world = world;
        this.media = world.media();
        this.bvh = world.bvh();
    }

    /**
     * Multiplies {@code tr} by the fraction of light that travels from {@code from} along the
     * unit direction {@code d} over {@code distance} (infinite: out of the scene) when it starts
     * in {@code medium} (−1: vacuum); returns false (and leaves {@code tr} black) if a surface
     * blocks the way or nothing arrives.
     */
    boolean along(Vector3dc from, Vector3dc d, double distance, int medium, MutableRgb tr) {
        ray.o.set(from);
        ray.d.set(d);
        double remaining = distance;
        for (int pass = 0; pass < Tracer.MAX_PASSES; pass++) {
            rays++;
            ray.tMax = remaining;
            hit.reset();
            boolean found = bvh.intersect(ray, hit, stack, false);
            if (medium >= 0) {
                media.medium(medium).transmittance(ray.o, ray.d, found ? hit.t : remaining, random, tr);
                if (tr.isBlack()) {
                    return false;
                }
            }
            if (!found) {
                return true;
            }
            world.surface(ray, hit, sp);
            SurfaceMaps maps = world.maps(sp.material);
            boolean cutAway = maps != null && maps.cutAway(sp.uv);
            if (!cutAway) {
                if (!media.isInvisible(sp.material)) {
                    tr.setZero();
                    return false;
                }
                medium = media.after(sp.material, medium, d.dot(sp.ng));
            }
            previous.set(ray.o);
            sp.spawnOrigin(d, ray.o);
            remaining -= previous.distance(ray.o);
            if (!(remaining > 0)) {
                return true;
            }
        }
        tr.setZero();
        return false;
    }
}
