package dev.strahl.units;

import dev.strahl.scene.Camera;
import dev.strahl.scene.Scene;
import java.nio.file.Path;
import java.util.Objects;

/**
 * What a coordinator tells the members about a job: the scene file (the files it references are
 * shipped with it), the camera to render it with, the settings by name (as the render package
 * writes them) and the scene fingerprint.
 *
 * @param sceneFile the scene file on the coordinator
 * @param camera    the camera (the file's, or one the command line set)
 * @param settings  the render settings, {@code name=value} joined by ';'
 * @param digest    the fingerprint of the scene as the coordinator renders it
 * @param scene     the scene itself, which the coordinator's own member renders its units of (never sent)
 */
public record JobSpec(Path sceneFile, Camera camera, String settings, byte[] digest, Scene scene) {
    /**
     * Checks nothing is missing.
     *
     * @param sceneFile the scene file
     * @param camera    the camera
     * @param settings  the settings
     * @param digest    the fingerprint
     * @param scene     the scene
     */
    public JobSpec {
        Objects.requireNonNull(sceneFile, "sceneFile");
        Objects.requireNonNull(camera, "camera");
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(digest, "digest");
        Objects.requireNonNull(scene, "scene");
    }
}
