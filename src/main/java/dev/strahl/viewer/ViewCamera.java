package dev.strahl.viewer;

import dev.strahl.scene.Camera;
import dev.strahl.scene.Scene;
import java.util.function.UnaryOperator;

/**
 * What the viewer looks through: the orbit camera the mouse moves, the scene's camera it started
 * from (home, where a reset goes back to) and the thin lens (the scene camera's radius, the focus
 * distance Ctrl+click sets). Not thread-safe: {@link RenderController} uses it under its lock.
 */
final class ViewCamera {
    private final Camera sceneCamera;
    private final OrbitCamera home;
    private OrbitCamera orbit;
    private double focusDistance;

    ViewCamera(Camera sceneCamera) {
        this.sceneCamera = sceneCamera;
        this.home = OrbitCamera.of(sceneCamera);
        this.orbit = home;
        this.focusDistance = sceneCamera.focusDistance();
    }

    OrbitCamera orbit() {
        return orbit;
    }

    /** Orbits, pans or dollies. */
    void move(UnaryOperator<OrbitCamera> move) {
        orbit = move.apply(orbit);
    }

    /** Back to the scene's camera and its focus. */
    void reset() {
        orbit = home;
        focusDistance = sceneCamera.focusDistance();
    }

    /**
     * Focuses on the surface of {@code scene} under a point of the image (fractions of its width and
     * height from the top left, at this aspect), as the orbit camera sees it.
     *
     * @return the new focus distance, or NaN (nothing changes) where no surface is hit
     */
    double focusAt(Scene scene, double fx, double fy, double aspect) {
        double d = scene.focusDistance(orbit.toCamera(), fx, fy, aspect);
        if (d > 0) {
            focusDistance = d;
        }
        return d;
    }

    /** The camera the render sees through: the orbit camera with the lens. */
    Camera camera() {
        return orbit.toCamera().withLens(sceneCamera.aperture(), focusDistance);
    }
}
