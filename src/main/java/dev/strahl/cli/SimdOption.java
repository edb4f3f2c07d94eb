package dev.strahl.cli;

import dev.strahl.accel.Simd;
import picocli.CommandLine.Option;

/**
 * {@code --simd on|off}, in the "Execution" section of render, view, worker (through
 * {@link ExecutionOptions}) and bench: off takes the scalar ray kernel instead of the
 * Vector API one, to compare the two (same images). It sets {@link Simd#PROPERTY} for the BVHs the
 * command builds, and puts it back when the command ends ({@link #apply}), so that commands run
 * one after another in one JVM (tests) do not inherit it. {@link SimdLauncher} does not start a
 * second JVM for {@code --simd off}.
 */
class SimdOption {
    enum Mode { on, off }

    @Option(names = "--simd", order = 9, paramLabel = "on|off", defaultValue = "on",
            description = "Ray kernel: on = SIMD (Vector API) where the JVM has it, off = the scalar twin (same images, to compare) (default: ${DEFAULT-VALUE}).")
    Mode mode = Mode.on;

    /** The command's kernel choice, until closed. */
    interface Scope extends AutoCloseable {
        @Override
        void close();
    }

    Scope apply() {
        if (mode == Mode.on) {
            return () -> { };
        }
        String before = System.getProperty(Simd.PROPERTY);
        System.setProperty(Simd.PROPERTY, "false");
        return () -> {
            if (before == null) {
                System.clearProperty(Simd.PROPERTY);
            } else {
                System.setProperty(Simd.PROPERTY, before);
            }
        };
    }
}
