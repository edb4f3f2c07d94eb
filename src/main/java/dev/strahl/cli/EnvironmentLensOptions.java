package dev.strahl.cli;

import dev.strahl.viewer.SceneOverrides;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * The options that replace a scene's environment and lens, which {@code render} and {@code view}
 * share, defined once. Null where not given: the scene's own value stays.
 */
final class EnvironmentLensOptions {

    @Option(names = "--envmap", paramLabel = "FILE",
            description = "Light the scene with this latitude-longitude environment map (.hdr, .exr or .pfm; +Y up, centre column"
                    + " along +Z) instead of its own environment.")
    Path envmap;

    @Option(names = "--aperture", paramLabel = "RADIUS",
            description = "Thin-lens camera: the lens radius in scene units; 0 = pinhole, everything sharp (default: the scene's camera's).")
    Double aperture;

    @Option(names = "--focus-distance", paramLabel = "DISTANCE",
            description = "Thin-lens camera: the distance in focus along the viewing direction (default: the scene's camera's; for render,"
                    + " the distance to --look-at when the camera is moved).")
    Double focusDistance;

    /** Refuses a lens that cannot be: a negative or infinite radius, a focus distance that is not positive. */
    void check() {
        if (aperture != null && !(aperture >= 0 && aperture < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("--aperture: the lens radius must be finite and >= 0, got " + aperture);
        }
        if (focusDistance != null && !(focusDistance > 0 && focusDistance < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("--focus-distance: the distance must be finite and positive, got " + focusDistance);
        }
    }

    /** The checked options as the viewer applies them to every scene it opens. */
    SceneOverrides overrides() {
        check();
        return new SceneOverrides(envmap, aperture, focusDistance);
    }
}
