package dev.strahl.cli;

import dev.strahl.render.RenderSettings;
import picocli.CommandLine.Option;

/**
 * The "Sampling" section's {@code --seed}, which {@code render} and {@code view} share; each adds
 * its {@code --spp} (render's sample count, view's stop-at count).
 */
class SamplingOptions {

    @Option(names = "--seed", defaultValue = "0", order = 2, description = "Random seed; the same seed gives the same image (default: ${DEFAULT-VALUE}).")
    long seed;

    /** {@code base} with this seed. */
    RenderSettings applyTo(RenderSettings base) {
        return base.withSeed(seed);
    }
}
