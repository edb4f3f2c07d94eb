package dev.strahl.light;

import dev.strahl.image.Rgb;
import org.joml.Vector3d;

/** A point sampled on a light, seen from a reference point; mutable, reused per thread. */
public final class LightSample {
    /** The point on the light and its geometric normal. */
    public final Vector3d p = new Vector3d();
    public final Vector3d ng = new Vector3d();
    /** Unit direction from the reference point towards {@link #p}. */
    public final Vector3d wi = new Vector3d();
    public double distance;
    /** Solid-angle density of wi at the reference point, light selection included. */
    public double pdf;
    /** Emitted radiance towards the reference point. */
    public Rgb radiance = Rgb.BLACK;
}
