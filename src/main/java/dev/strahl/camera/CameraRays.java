package dev.strahl.camera;

import dev.strahl.geometry.Ray;
import dev.strahl.sampling.Warp;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Maps continuous film coordinates to camera rays: a pinhole, or a thin lens. Film x ∈ [0, W)
 * grows to the right, y ∈ [0, H) DOWNWARDS. With f = normalize(target − origin),
 * r = normalize(f × up), u = r × f and t = tan(vfov/2), the pinhole ray leaves the origin along
 * dir = normalize(f + (2x/W − 1)·t·(W/H)·r + (1 − 2y/H)·t·u).
 *
 * <p><b>Thin lens</b> (Mitsuba 3's {@code thinlens}, pbrt-v4 §5.2.3): a lens of radius
 * {@code lensRadius} centred on the origin, perpendicular to f. The point seen sharply through
 * film point (x, y) is where the pinhole ray meets the plane of focus, at distance
 * {@code focusDistance} along f: p = origin + focusDistance·(f + (2x/W − 1)·t·(W/H)·r + (1 − 2y/H)·t·u).
 * A ray starts at a point of the lens, origin + lensRadius·(a·r + b·u) with (a, b) uniform on the
 * unit disk (Shirley–Chiu concentric map), and goes towards p. Immutable, thread-safe.
 */
public final class CameraRays {
    private final double ox, oy, oz;
    private final double fx, fy, fz;
    private final double rx, ry, rz;   // right, scaled by t·W/H
    private final double ux, uy, uz;   // up, scaled by t
    private final double lrx, lry, lrz; // right, scaled by the lens radius
    private final double lux, luy, luz; // up, scaled by the lens radius
    private final double lensRadius, focusDistance;
    private final double invW, invH;

    /** How an API camera becomes rays; {@code dev.strahl.scene.Camera} installs it when it is loaded. */
    @FunctionalInterface
    public interface CameraAccess {
        /** The rays of {@code camera} (a {@code dev.strahl.scene.Camera}) for a film size: through its thin lens, or its pinhole. */
        CameraRays rays(Object camera, boolean pinhole, int width, int height);
    }

    private static volatile CameraAccess cameraAccess;

    /**
     * The rays of an API {@code dev.strahl.scene.Camera} for a film size, through its thin lens: the
     * one conversion of the API's camera, for strahl's own packages (the pattern of {@code World.of}).
     */
    public static CameraRays of(Object camera, int width, int height) {
        return cameraAccess.rays(camera, false, width, height);
    }

    /** As {@link #of}, through the camera's pinhole whatever its lens: the ray that picks a surface, the benchmark's rays. */
    public static CameraRays pinholeOf(Object camera, int width, int height) {
        return cameraAccess.rays(camera, true, width, height);
    }

    /** Called once, by the {@code Camera} class as it is loaded. */
    public static void installCameraAccess(CameraAccess access) {
        if (cameraAccess != null) {
            throw new IllegalStateException("camera access installed twice");
        }
        cameraAccess = access;
    }

    /** Pinhole rays of a camera at {@code from} looking at {@code at}, with a vertical field of view, for a film size. */
    public CameraRays(Vector3dc from, Vector3dc at, Vector3dc up, double fovDegrees, int width, int height) {
        this(from, at, up, fovDegrees, 0, 1, width, height);
    }

    /**
     * Rays of a thin-lens camera (a pinhole if {@code lensRadius} is 0).
     *
     * @param lensRadius    radius of the lens in scene units, ≥ 0
     * @param focusDistance distance of the plane in focus along the viewing direction, > 0
     */
    public CameraRays(Vector3dc from, Vector3dc at, Vector3dc up, double fovDegrees, double lensRadius, double focusDistance,
                      int width, int height) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("film size must be positive, got " + width + "x" + height);
        }
        if (!(lensRadius >= 0) || !(focusDistance > 0) || Double.isInfinite(lensRadius) || Double.isInfinite(focusDistance)) {
            throw new IllegalArgumentException("lens radius must be >= 0 and focus distance > 0, got " + lensRadius + ", " + focusDistance);
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
        double vx = cy * fz - cz * fy, vy = cz * fx - cx * fz, vz = cx * fy - cy * fx;
        double t = Math.tan(Math.toRadians(fovDegrees) / 2);
        double aspect = (double) width / height;
        rx = cx * t * aspect;
        ry = cy * t * aspect;
        rz = cz * t * aspect;
        ux = vx * t;
        uy = vy * t;
        uz = vz * t;
        lrx = cx * lensRadius;
        lry = cy * lensRadius;
        lrz = cz * lensRadius;
        lux = vx * lensRadius;
        luy = vy * lensRadius;
        luz = vz * lensRadius;
        this.lensRadius = lensRadius;
        this.focusDistance = focusDistance;
        ox = from.x();
        oy = from.y();
        oz = from.z();
        invW = 1.0 / width;
        invH = 1.0 / height;
    }

    /** Whether rays need a lens sample: the camera has a lens of positive radius. */
    public boolean hasLens() {
        return lensRadius > 0;
    }

    /** Sets {@code ray} to the pinhole ray through film point (x, y), tMax = ∞ (the lens's centre for a thin lens). */
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

    /**
     * Sets {@code ray} to the thin-lens ray through film point (x, y) from the lens point of
     * (lensU1, lensU2) ∈ [0, 1)²; {@code disk} is the caller's scratch.
     */
    public void generate(double x, double y, double lensU1, double lensU2, Vector3d disk, Ray ray) {
        if (lensRadius == 0) {
            generate(x, y, ray);
            return;
        }
        double sx = 2 * x * invW - 1;
        double sy = 1 - 2 * y * invH;
        double px = focusDistance * (fx + sx * rx + sy * ux);   // the point in focus, relative to the origin
        double py = focusDistance * (fy + sx * ry + sy * uy);
        double pz = focusDistance * (fz + sx * rz + sy * uz);
        Warp.concentricDisk(lensU1, lensU2, disk);
        double lx = disk.x * lrx + disk.y * lux, ly = disk.x * lry + disk.y * luy, lz = disk.x * lrz + disk.y * luz;
        double dx = px - lx, dy = py - ly, dz = pz - lz;
        double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        ray.o.set(ox + lx, oy + ly, oz + lz);
        ray.d.set(dx * inv, dy * inv, dz * inv);
        ray.tMax = Double.POSITIVE_INFINITY;
    }
}
