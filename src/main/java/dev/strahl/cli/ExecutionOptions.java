package dev.strahl.cli;

import dev.strahl.render.RenderSettings;
import picocli.CommandLine.Option;

/**
 * How the work is done on this machine: the "Execution" section of {@code render}, {@code view} and
 * {@code worker} (RenderSettings.Execution, and the ray kernel of {@link SimdOption}). None of it
 * changes the image's bits.
 */
final class ExecutionOptions extends SimdOption {

    @Option(names = "--threads", order = 0, defaultValue = "0", description = "Worker threads; 0 = all processors (default: ${DEFAULT-VALUE}).")
    int threads;

    /** {@code base} with these threads. */
    RenderSettings applyTo(RenderSettings base) {
        return base.withThreads(threads);
    }
}
