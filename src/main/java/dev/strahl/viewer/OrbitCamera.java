package dev.strahl.viewer;

import dev.strahl.scene.Camera;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A camera on a sphere around a target point: the viewer's navigation model, pure math without
 * Swing. Immutable; every move returns a new instance.
 *
 * <p>The position is given in spherical coordinates about the target in a frame fixed by the
 * scene's camera: {@code axisUp} is its (normalised) up vector, {@code axisRef} the horizontal
 * direction from the target to the original position. The position is
 * {@code target + distance · (cos pitch · (cos yaw · ref + sin yaw · side) + sin pitch · up)}
 * with {@code side = up × ref}. Orbiting changes yaw and pitch (pitch limited to
 * ±{@value #MAX_PITCH_DEGREES}° so that the view never becomes parallel to the up vector), panning
 * moves target and position together in the image plane, dollying scales the distance (never to
 * zero, so the camera never reaches or crosses the target).
 */
final class OrbitCamera {
    static final double MAX_PITCH_DEGREES = 89;
    private static final double MAX_PITCH = Math.toRadians(MAX_PITCH_DEGREES);
    /** Closest and farthest distances, relative to the scene camera's distance to its target. */
    static final double MIN_DISTANCE_FACTOR = 1e-3;
    static final double MAX_DISTANCE_FACTOR = 1e3;

    private final Vector3d target;
    private final Vector3d axisUp;
    private final Vector3d axisRef;
    private final double yaw;
    private final double pitch;
    private final double distance;
    private final double homeDistance;
    private final double fovDegrees;

    private OrbitCamera(Vector3dc target, Vector3dc axisUp, Vector3dc axisRef, double yaw, double pitch,
                        double distance, double homeDistance, double fovDegrees) {
        this.target = new Vector3d(target);
        this.axisUp = new Vector3d(axisUp);
        this.axisRef = new Vector3d(axisRef);
        this.yaw = yaw;
        this.pitch = pitch;
        this.distance = distance;
        this.homeDistance = homeDistance;
        this.fovDegrees = fovDegrees;
    }

    /** The orbit that starts exactly at {@code camera}. */
    static OrbitCamera of(Camera camera) {
        Vector3d up = new Vector3d(camera.up()).normalize();
        Vector3d offset = new Vector3d(camera.lookFrom()).sub(camera.lookAt());
        double distance = offset.length();
        double height = offset.dot(up);
        Vector3d ref = new Vector3d(offset).fma(-height, up);
        if (ref.lengthSquared() < 1e-24 * distance * distance) {
            ref = anyPerpendicular(up);       // looking straight along the up axis
        }
        ref.normalize();
        double pitch = Math.asin(Math.max(-1, Math.min(1, height / distance)));
        return new OrbitCamera(camera.lookAt(), up, ref, 0, pitch, distance, distance, camera.fovDegrees());
    }

    private static Vector3d anyPerpendicular(Vector3dc v) {
        Vector3d a = Math.abs(v.x()) < 0.9 ? new Vector3d(1, 0, 0) : new Vector3d(0, 1, 0);
        return a.cross(v);
    }

    /**
     * Turns the camera around the target: {@code dYaw} radians about the up axis, {@code dPitch}
     * radians up (positive: the camera rises and looks down more).
     */
    OrbitCamera orbit(double dYaw, double dPitch) {
        double p = Math.max(-MAX_PITCH, Math.min(MAX_PITCH, pitch + dPitch));
        return new OrbitCamera(target, axisUp, axisRef, yaw + dYaw, p, distance, homeDistance, fovDegrees);
    }

    /**
     * Moves position and target together in the image plane by fractions of the visible height at
     * the target's depth: positive {@code right} moves the camera to its right, positive
     * {@code up} moves it up (the picture moves the other way).
     */
    OrbitCamera pan(double right, double up) {
        double visibleHeight = 2 * distance * Math.tan(Math.toRadians(fovDegrees) / 2);
        Vector3d forward = new Vector3d(target).sub(eye()).normalize();
        Vector3d r = forward.cross(axisUp, new Vector3d()).normalize();
        Vector3d u = r.cross(forward, new Vector3d());
        Vector3d t = new Vector3d(target).fma(right * visibleHeight, r).fma(up * visibleHeight, u);
        return new OrbitCamera(t, axisUp, axisRef, yaw, pitch, distance, homeDistance, fovDegrees);
    }

    /**
     * Multiplies the distance to the target by {@code factor} (&lt; 1 moves closer), kept within
     * [{@value #MIN_DISTANCE_FACTOR}, {@value #MAX_DISTANCE_FACTOR}] times the original distance.
     */
    OrbitCamera dolly(double factor) {
        if (!(factor > 0) || !Double.isFinite(factor)) {
            throw new IllegalArgumentException("dolly factor must be positive and finite, got " + factor);
        }
        double d = Math.max(MIN_DISTANCE_FACTOR * homeDistance, Math.min(MAX_DISTANCE_FACTOR * homeDistance, distance * factor));
        return new OrbitCamera(target, axisUp, axisRef, yaw, pitch, d, homeDistance, fovDegrees);
    }

    /** The camera position. */
    Vector3d eye() {
        Vector3d side = axisUp.cross(axisRef, new Vector3d());
        double c = Math.cos(pitch);
        Vector3d dir = new Vector3d(axisRef).mul(c * Math.cos(yaw)).fma(c * Math.sin(yaw), side).fma(Math.sin(pitch), axisUp);
        return dir.mul(distance).add(target);
    }

    Vector3dc target() {
        return new Vector3d(target);
    }

    double distance() {
        return distance;
    }

    double pitch() {
        return pitch;
    }

    /** The pinhole camera at this position, looking at the target, with the scene's up vector and field of view. */
    Camera toCamera() {
        return new Camera(eye(), target, axisUp, fovDegrees);
    }

    @Override
    public String toString() {
        return "OrbitCamera[eye=" + eye() + ", target=" + target + "]";
    }
}
