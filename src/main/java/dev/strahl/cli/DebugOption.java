package dev.strahl.cli;

import picocli.CommandLine.Option;

/** {@code --debug}: errors are still one line, followed by the stack trace that explains them. */
final class DebugOption {
    @Option(names = "--debug", description = "After an error's one-line message, print its stack trace.")
    boolean enabled;
}
