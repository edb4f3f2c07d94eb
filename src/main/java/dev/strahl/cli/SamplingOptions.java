package dev.strahl.cli;

import dev.strahl.render.RenderSettings;
import picocli.CommandLine.Option;

/**
 * The "Sampling" section's {@code --seed} and {@code --noise-threshold}, which {@code render} and
 * {@code view} share; each adds its {@code --spp} (render's sample count, view's stop-at count).
 */
class SamplingOptions {

    @Option(names = "--seed", defaultValue = "0", order = 2, description = "Random seed; the same seed gives the same image (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--noise-threshold", defaultValue = "0", order = 3, paramLabel = "T",
            description = {"Adaptive sampling: samples go where the noise is until every pixel's relative standard error is at most T"
                    + " (0.01 = 1 %%; luminance, measured against 0.05 where a pixel is darker); --spp is then the most a pixel takes."
                    + " 0 = off, every pixel takes --spp (default: ${DEFAULT-VALUE})."})
    double noiseThreshold;

    /** {@code base} with this seed and noise threshold (checked: 0 or in (0, 1]). */
    RenderSettings applyTo(RenderSettings base) {
        try {
            return base.withSeed(seed).withNoiseThreshold(noiseThreshold);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--noise-threshold must be 0 (off) or in (0, 1] (0.01 = 1 %), got " + noiseThreshold);
        }
    }
}
