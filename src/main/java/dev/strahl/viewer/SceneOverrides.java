package dev.strahl.viewer;

import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import java.nio.file.Path;

/**
 * What the command line ({@code strahl view --envmap --aperture --focus-distance}) changes in
 * every scene the viewer opens, the one named on the command line and those opened from the
 * window alike, as {@code strahl render} changes its scene. A null part leaves the scene's own.
 *
 * @param envmap        a latitude–longitude environment map that replaces the scene's environment (scale 1, no rotation)
 * @param aperture      the thin lens's radius in scene units (0 = pinhole)
 * @param focusDistance the distance in focus along the viewing direction
 */
public record SceneOverrides(Path envmap, Double aperture, Double focusDistance) {
    /** Nothing changed. */
    public static final SceneOverrides NONE = new SceneOverrides(null, null, null);

    /**
     * The scene with these changes.
     *
     * @throws SceneException if the environment map cannot be read (one line naming it)
     */
    Scene applyTo(Scene scene) throws SceneException {
        Scene s = scene;
        if (aperture != null || focusDistance != null) {
            Camera c = s.camera();
            s = s.withCamera(c.withLens(aperture != null ? aperture : c.aperture(),
                    focusDistance != null ? focusDistance : c.focusDistance()));
        }
        if (envmap != null) {
            s = s.withEnvironmentMap(SceneLoader.readImage(envmap), 1, 0);
        }
        return s;
    }
}
