package dev.strahl.geometry;

/**
 * The closest intersection found so far: distance, primitive and its surface parameters
 * (barycentrics b1, b2 of vertices 1 and 2 for triangles), and the instance it belongs to, if any.
 * Mutable, reused per thread.
 */
public final class Hit {
    /** Creates an empty record; {@link #reset} before each query. */
    public Hit() {}

    public double t;
    /** Primitive index in {@link Geometry}, or -1 for no hit. */
    public int prim = -1;
    public double b1, b2;
    /**
     * The instance whose group holds {@link #prim} ({@link InstanceTransforms}), or -1 for a
     * primitive of the scene's own geometry.
     */
    public int instance = -1;

    public Hit reset() {
        prim = -1;
        instance = -1;
        t = Double.POSITIVE_INFINITY;
        return this;
    }

    public boolean found() {
        return prim >= 0;
    }
}
