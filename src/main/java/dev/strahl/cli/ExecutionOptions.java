package dev.strahl.cli;

import dev.strahl.render.RenderSettings;
import picocli.CommandLine.Option;

/**
 * How the work is done on this machine: the "Execution" section of {@code render}, {@code view} and
 * {@code worker} (RenderSettings.Execution). None of it changes the image's bits.
 */
final class ExecutionOptions {

    @Option(names = "--threads", defaultValue = "0", description = "Worker threads; 0 = all processors (default: ${DEFAULT-VALUE}).")
    int threads;

    /** {@code base} with these threads. */
    RenderSettings applyTo(RenderSettings base) {
        return base.withThreads(threads);
    }
}
