package dev.strahl.cli;

import dev.strahl.scene.Camera;
import org.joml.Vector3d;
import picocli.CommandLine.Option;

/** {@code render}'s camera, replacing the scene's where given: the "Camera" section. */
final class CameraOptions {

    @Option(names = "--look-from", paramLabel = "X,Y,Z", converter = Vectors.class, description = "Camera position.")
    Vector3d lookFrom;

    @Option(names = "--look-at", paramLabel = "X,Y,Z", converter = Vectors.class, description = "Point the camera looks at.")
    Vector3d lookAt;

    @Option(names = "--up", paramLabel = "X,Y,Z", converter = Vectors.class, description = "Camera up vector.")
    Vector3d up;

    @Option(names = "--fov", paramLabel = "DEGREES", description = "Vertical field of view in degrees.")
    Double fov;

    /** Refuses a field of view that cannot be. */
    void check() {
        if (fov != null && !(fov > 0 && fov < 180)) {
            throw new IllegalArgumentException("--fov: the field of view must be in (0, 180) degrees, got " + fov);
        }
    }

    /**
     * The scene's camera {@code base} with what these options and the {@code lens} replace; a moved
     * camera without a focus distance focuses on its look-at point.
     */
    Camera camera(Camera base, LensOptions lens) {
        Camera c = new Camera(lookFrom != null ? lookFrom : base.lookFrom(), lookAt != null ? lookAt : base.lookAt(),
                up != null ? up : base.up(), fov != null ? fov : base.fovDegrees());
        boolean moved = lookFrom != null || lookAt != null;
        return c.withLens(lens.aperture != null ? lens.aperture : base.aperture(),
                lens.focusDistance != null ? lens.focusDistance : moved ? c.focusDistance() : base.focusDistance());
    }
}
