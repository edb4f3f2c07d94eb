package dev.strahl.cli;

import dev.strahl.render.RenderSettings;
import picocli.CommandLine.Option;

/** The teaching option that {@code render} and {@code view} share; {@link TeachingOptions} adds render's other two. */
class ShadowsOption {

    @Option(names = "--shadows", defaultValue = "on", paramLabel = "on|off", order = 3,
            description = "Teaching option: off traces no shadow rays, so every light shines through everything onto whatever faces it: "
                    + "the picture without shadows (with path and photon only the direct light loses its shadows) (default: ${DEFAULT-VALUE}).")
    Shadows shadows;

    /** The values of --shadows. */
    enum Shadows { ON, OFF }

    /** Whether shadow rays are traced ({@code --shadows on}, the default). */
    boolean shadows() {
        return shadows != Shadows.OFF;
    }

    /** {@code base} with or without shadows. */
    RenderSettings applyTo(RenderSettings base) {
        return base.withShadows(shadows());
    }
}
