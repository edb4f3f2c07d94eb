package dev.strahl.geometry;

import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * An analytic sphere; its geometric normal points outwards.
 *
 * @param center the centre (copied)
 * @param radius the radius, positive and finite
 */
public record Sphere(Vector3dc center, double radius) {
    /**
     * Checks the radius and the centre.
     *
     * @param center the centre (copied)
     * @param radius the radius, positive and finite
     */
    public Sphere {
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("sphere radius must be positive and finite, got " + radius);
        }
        if (!center.isFinite()) {
            throw new IllegalArgumentException("sphere centre must be finite, got " + center);
        }
        center = new Vector3d(center);
    }
}
