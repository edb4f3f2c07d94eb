package dev.strahl.camera;

import org.joml.Vector3dc;
import dev.strahl.geometry.Ray;

/**
 * Maps continuous film coordinates to camera rays. Film x ∈ [0, W) grows to the right,
 * y ∈ [0, H) DOWNWARDS. With f = normalize(target − origin), r = normalize(f × up),
 * u = r × f and t = tan(vfov/2):
 * dir = normalize(f + (2x/W − 1)·t·(W/H)·r + (1 − 2y/H)·t·u). Immutable, thread-safe.
 */
public final class PinholeRays {
    private final double ox, oy, oz;
    private final double fx, fy, fz;
    private final double rx, ry, rz;   // right, scaled by t·W/H
    private final double ux, uy, uz;   // up, scaled by t
    private final double invW, invH;

    /** Rays of a camera at {@code from} looking at {@code at}, with a vertical field of view, for a film size. */
    public PinholeRays(Vector3dc from, Vector3dc at, Vector3dc up, double fovDegrees, int width, int height) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("film size must be positive, got " + width + "x" + height);
        }
        double dx = at.x() - from.x(), dy = at.y() - from.y(), dz = at.z() - from.z();
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        fx = dx / len;
        fy = dy / len;
        fz = dz / len;
        double cx = fy * up.z() - fz * up.y(), cy = fz * up.x() - fx * up.z(), cz = fx * up.y() - fy * up.x();
        double clen = Math.sqrt(cx * cx + cy * cy + cz * cz);
        cx /= clen;
        cy /= clen;
        cz /= clen;
        double t = Math.tan(Math.toRadians(fovDegrees) / 2);
        double aspect = (double) width / height;
        rx = cx * t * aspect;
        ry = cy * t * aspect;
        rz = cz * t * aspect;
        ux = (cy * fz - cz * fy) * t;
        uy = (cz * fx - cx * fz) * t;
        uz = (cx * fy - cy * fx) * t;
        ox = from.x();
        oy = from.y();
        oz = from.z();
        invW = 1.0 / width;
        invH = 1.0 / height;
    }

    /** Sets {@code ray} to the camera ray through film point (x, y), tMax = ∞. */
    public void generate(double x, double y, Ray ray) {
        double sx = 2 * x * invW - 1;
        double sy = 1 - 2 * y * invH;
        double dx = fx + sx * rx + sy * ux;
        double dy = fy + sx * ry + sy * uy;
        double dz = fz + sx * rz + sy * uz;
        double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        ray.o.set(ox, oy, oz);
        ray.d.set(dx * inv, dy * inv, dz * inv);
        ray.tMax = Double.POSITIVE_INFINITY;
    }
}
