package dev.strahl.cli;

import dev.strahl.integrator.PathWavefront;
import dev.strahl.render.RenderSettings;
import picocli.CommandLine.Option;

/**
 * How the work is done on this machine: the "Execution" section of {@code render}, {@code view} and
 * {@code worker} (RenderSettings.Execution, the ray kernel of {@link SimdOption} and the path
 * tracer's loop, {@code --wavefront}). None of it changes the image's bits.
 */
final class ExecutionOptions extends SimdOption {

    @Option(names = "--threads", order = 0, defaultValue = "0", description = "Worker threads; 0 = all processors (default: ${DEFAULT-VALUE}).")
    int threads;

    /** Null unless given: then the JVM's own {@code -Dstrahl.wavefront}, or off, holds. */
    @Option(names = "--wavefront", order = 10, paramLabel = "on|off",
            description = "The path tracer's loop: on = a wavefront (batches of paths, stage by stage), off = one path at a time (the same images; default: off).")
    Mode wavefront;

    /** The kernel's choice and the wavefront's (when given), until closed. */
    @Override
    Scope apply() {
        Scope kernel = super.apply();
        if (wavefront == null) {
            return kernel;
        }
        String before = System.getProperty(PathWavefront.PROPERTY);
        System.setProperty(PathWavefront.PROPERTY, wavefront.name());
        return () -> {
            if (before == null) {
                System.clearProperty(PathWavefront.PROPERTY);
            } else {
                System.setProperty(PathWavefront.PROPERTY, before);
            }
            kernel.close();
        };
    }

    /** {@code base} with these threads. */
    RenderSettings applyTo(RenderSettings base) {
        return base.withThreads(threads);
    }
}
