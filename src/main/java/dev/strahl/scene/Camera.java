package dev.strahl.scene;

import dev.strahl.camera.CameraRays;
import dev.strahl.geometry.Aabb;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A camera: position, target, up vector and VERTICAL full field of view in degrees; a pinhole, or
 * a thin lens (as Mitsuba 3's {@code thinlens}) when {@code aperture} is positive: rays start on a
 * disk of radius {@code aperture} around the position, perpendicular to the viewing direction, and
 * points at distance {@code focusDistance} along the viewing direction are in focus.
 *
 * @param lookFrom      the camera position
 * @param lookAt        the point looked at
 * @param up            the up direction, not parallel to the viewing direction
 * @param fovDegrees    vertical full field of view in degrees, in (0, 180)
 * @param aperture      the lens radius in scene units; 0 is a pinhole (everything sharp)
 * @param focusDistance distance of the plane in focus from the camera along the viewing direction, positive
 */
public record Camera(Vector3dc lookFrom, Vector3dc lookAt, Vector3dc up, double fovDegrees, double aperture, double focusDistance) {
    static {
        // the one conversion of this API record to the renderer's rays (CameraRays.of)
        CameraRays.installCameraAccess((c, pinhole, width, height) -> {
            Camera k = (Camera) c;
            return pinhole ? new CameraRays(k.lookFrom, k.lookAt, k.up, k.fovDegrees, width, height)
                    : new CameraRays(k.lookFrom, k.lookAt, k.up, k.fovDegrees, k.aperture, k.focusDistance, width, height);
        });
    }

    /** Azimuth of the framing camera, degrees from +Z towards +X, around the scene's centre. */
    static final double FRAMING_AZIMUTH = 40;
    /** Elevation of the framing camera above the horizontal plane through the scene's centre, degrees. */
    static final double FRAMING_ELEVATION = 25;
    /** What the notes say about the framing. */
    static final String FRAMING_DESCRIPTION = "a raised three-quarter view (azimuth 40° from +Z towards +X, elevation 25°, 40° field of view)";

    /**
     * Checks the field of view, the lens and that the vectors are finite and not degenerate; copies them.
     *
     * @param lookFrom      the camera position
     * @param lookAt        the point looked at
     * @param up            the up direction, not parallel to the viewing direction
     * @param fovDegrees    vertical full field of view in degrees, in (0, 180)
     * @param aperture      the lens radius, finite and ≥ 0
     * @param focusDistance the distance in focus, finite and positive
     */
    public Camera {
        if (!(fovDegrees > 0 && fovDegrees < 180)) {
            throw new IllegalArgumentException("field of view must be in (0, 180) degrees, got " + fovDegrees);
        }
        if (!(aperture >= 0) || Double.isInfinite(aperture)) {
            throw new IllegalArgumentException("aperture (lens radius) must be finite and >= 0, got " + aperture);
        }
        if (!(focusDistance > 0) || Double.isInfinite(focusDistance)) {
            throw new IllegalArgumentException("focus distance must be finite and positive, got " + focusDistance);
        }
        if (!lookFrom.isFinite() || !lookAt.isFinite() || !up.isFinite()) {
            throw new IllegalArgumentException("camera vectors must be finite");
        }
        Vector3d f = new Vector3d(lookAt).sub(lookFrom);
        if (f.lengthSquared() == 0) {
            throw new IllegalArgumentException("camera position and target coincide at " + format(lookFrom));
        }
        if (f.normalize().cross(up, new Vector3d()).lengthSquared() < 1e-18) {
            throw new IllegalArgumentException("camera up vector " + format(up) + " is parallel to the viewing direction");
        }
        lookFrom = new Vector3d(lookFrom);
        lookAt = new Vector3d(lookAt);
        up = new Vector3d(up);
    }

    /**
     * A pinhole camera (aperture 0), focused on {@code lookAt} should a lens be added with
     * {@link #withLens}.
     *
     * @param lookFrom   the camera position
     * @param lookAt     the point looked at
     * @param up         the up direction, not parallel to the viewing direction
     * @param fovDegrees vertical full field of view in degrees, in (0, 180)
     */
    public Camera(Vector3dc lookFrom, Vector3dc lookAt, Vector3dc up, double fovDegrees) {
        this(lookFrom, lookAt, up, fovDegrees, 0, targetDistance(lookFrom, lookAt));
    }

    private static double targetDistance(Vector3dc from, Vector3dc at) {
        double d = from.distance(at);
        return d > 0 && Double.isFinite(d) ? d : 1;      // the canonical constructor names a degenerate camera
    }

    /**
     * A camera that frames a bounding box from a raised three-quarter view: from azimuth
     * {@value #FRAMING_AZIMUTH}° (from +Z towards +X) and elevation {@value #FRAMING_ELEVATION}°
     * around the box's centre, +Y up, far enough that the box's bounding sphere fits into the
     * vertical field of view.
     *
     * @param box        the bounds to frame
     * @param fovDegrees vertical field of view in degrees
     * @return the camera
     */
    static Camera framing(Aabb box, double fovDegrees) {
        if (box.isEmpty()) {
            return new Camera(new Vector3d(0, 0, 1), new Vector3d(), new Vector3d(0, 1, 0), fovDegrees);
        }
        Vector3d center = new Vector3d((box.minX + box.maxX) / 2, (box.minY + box.maxY) / 2, (box.minZ + box.maxZ) / 2);
        double radius = Math.max(box.diagonal() / 2, 1e-6);
        double distance = radius / Math.sin(Math.toRadians(fovDegrees) / 2) * 1.05;
        double azimuth = Math.toRadians(FRAMING_AZIMUTH), elevation = Math.toRadians(FRAMING_ELEVATION);
        Vector3d dir = new Vector3d(Math.sin(azimuth) * Math.cos(elevation), Math.sin(elevation), Math.cos(azimuth) * Math.cos(elevation));
        Vector3d from = new Vector3d(dir).mul(distance).add(center);
        return new Camera(from, center, new Vector3d(0, 1, 0), fovDegrees);
    }

    /**
     * A camera that frames a bounding box from +Z, looking down −Z with +Y up: the box's bounding
     * sphere fits into the vertical field of view.
     *
     * @param box        the bounds to frame
     * @param fovDegrees vertical field of view in degrees
     * @return the camera
     */
    static Camera frontFraming(Aabb box, double fovDegrees) {
        if (box.isEmpty()) {
            return new Camera(new Vector3d(0, 0, 1), new Vector3d(), new Vector3d(0, 1, 0), fovDegrees);
        }
        Vector3d center = new Vector3d((box.minX + box.maxX) / 2, (box.minY + box.maxY) / 2, (box.minZ + box.maxZ) / 2);
        double radius = Math.max(box.diagonal() / 2, 1e-6);
        double distance = radius / Math.sin(Math.toRadians(fovDegrees) / 2);
        Vector3d from = new Vector3d(center.x, center.y, center.z + distance * 1.05);
        return new Camera(from, center, new Vector3d(0, 1, 0), fovDegrees);
    }

    /** "(x, y, z)", as a user would write the vector. */
    static String format(Vector3dc v) {
        return "(" + v.x() + ", " + v.y() + ", " + v.z() + ")";
    }

    /**
     * The same camera with another field of view.
     *
     * @param fov vertical field of view in degrees, in (0, 180)
     * @return a new camera
     */
    public Camera withFov(double fov) {
        return new Camera(lookFrom, lookAt, up, fov, aperture, focusDistance);
    }

    /**
     * The same camera with a thin lens.
     *
     * @param lensRadius the aperture: lens radius in scene units, ≥ 0 (0: a pinhole)
     * @param distance   the focus distance along the viewing direction, positive
     * @return a new camera
     */
    public Camera withLens(double lensRadius, double distance) {
        return new Camera(lookFrom, lookAt, up, fovDegrees, lensRadius, distance);
    }
}
