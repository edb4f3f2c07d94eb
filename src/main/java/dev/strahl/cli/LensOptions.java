package dev.strahl.cli;

import picocli.CommandLine.Option;

/**
 * The thin lens that replaces the scene camera's, which {@code render} and {@code view} share
 * (their "Lens" section). Null where not given: the scene's own value stays.
 */
final class LensOptions {

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
}
