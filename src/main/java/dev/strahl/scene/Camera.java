package dev.strahl.scene;

import dev.strahl.geometry.Aabb;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A pinhole camera: position, target, up vector and VERTICAL full field of view in degrees.
 *
 * @param lookFrom   the camera position
 * @param lookAt     the point looked at
 * @param up         the up direction, not parallel to the viewing direction
 * @param fovDegrees vertical full field of view in degrees, in (0, 180)
 */
public record Camera(Vector3dc lookFrom, Vector3dc lookAt, Vector3dc up, double fovDegrees) {

    /**
     * Checks the field of view and that the vectors are finite and not degenerate; copies them.
     *
     * @param lookFrom   the camera position
     * @param lookAt     the point looked at
     * @param up         the up direction, not parallel to the viewing direction
     * @param fovDegrees vertical full field of view in degrees, in (0, 180)
     */
    public Camera {
        if (!(fovDegrees > 0 && fovDegrees < 180)) {
            throw new IllegalArgumentException("field of view must be in (0, 180) degrees, got " + fovDegrees);
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
     * A camera that frames a bounding box from +Z, looking down -Z with +Y up: the box's bounding
     * sphere fits into the vertical field of view.
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
        return new Camera(lookFrom, lookAt, up, fov);
    }
}
