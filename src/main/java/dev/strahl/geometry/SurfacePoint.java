package dev.strahl.geometry;

import org.joml.Vector2d;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Where a ray met a surface: position, geometric normal {@code ng} (from the primitive's winding or
 * outward for spheres), shading normal {@code n} (interpolated vertex normals, else ng) and the
 * primitive's material, texture coordinates {@code uv} and the tangent dp/du (see
 * {@link Geometry#surface}). Mutable, reused per thread.
 */
public final class SurfacePoint {
    /** Creates a point for {@link Geometry} to fill in. */
    public SurfacePoint() {}

    /** Relative size of the offset that moves new ray origins off the surface. */
    private static final double OFFSET_SCALE = 1e-6;

    public final Vector3d p = new Vector3d();
    public final Vector3d ng = new Vector3d();
    public final Vector3d n = new Vector3d();
    /** Texture coordinates, (0, 0) at the image's bottom-left corner. */
    public final Vector2d uv = new Vector2d();
    /** ∂p/∂u, not normalised: the tangent of normal maps. */
    public final Vector3d dpdu = new Vector3d();
    /**
     * The handedness of the texture mapping: dp/dv points along tangentSign · (n × dp/du)
     * (MikkTSpace's bitangent sign); −1 where the mapping is mirrored.
     */
    public double tangentSign = 1;
    public int material;
    public int prim;

    /**
     * Moves a ray origin off this surface to the side {@code dir} leaves towards, so that the new
     * ray cannot hit the surface it starts on. The offset scales with the coordinates, since
     * round-off in the hit point does too. Writes into and returns {@code dest}.
     */
    public Vector3d spawnOrigin(Vector3dc dir, Vector3d dest) {
        return offset(p, ng, dir, dest);
    }

    /** The offset of {@link #spawnOrigin} for any point and normal. */
    public static Vector3d offset(Vector3dc p, Vector3dc ng, Vector3dc dir, Vector3d dest) {
        double scale = Math.max(Math.abs(p.x()), Math.max(Math.abs(p.y()), Math.abs(p.z())));
        double eps = OFFSET_SCALE * (1 + scale);
        if (ng.dot(dir) < 0) {
            eps = -eps;
        }
        return dest.set(p.x() + eps * ng.x(), p.y() + eps * ng.y(), p.z() + eps * ng.z());
    }
}
