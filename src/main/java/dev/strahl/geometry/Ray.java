package dev.strahl.geometry;

import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A ray o + t·d for t in (0, tMax). Mutable and reused per thread: the intersector shortens
 * {@code tMax} to the closest hit found so far.
 */
public final class Ray {
    /** Creates a ray to be {@link #set} before use. */
    public Ray() {}

    public final Vector3d o = new Vector3d();
    /** Unit direction. */
    public final Vector3d d = new Vector3d();
    public double tMax = Double.POSITIVE_INFINITY;

    public Ray set(Vector3dc origin, Vector3dc direction, double tMax) {
        o.set(origin);
        d.set(direction);
        this.tMax = tMax;
        return this;
    }

    /** The point at parameter t; writes into and returns {@code dest}. */
    public Vector3d at(double t, Vector3d dest) {
        return dest.set(o.x + t * d.x, o.y + t * d.y, o.z + t * d.z);
    }

    @Override
    public String toString() {
        return "Ray[o=" + o + ", d=" + d + ", tMax=" + tMax + "]";
    }
}
