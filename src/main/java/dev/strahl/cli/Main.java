package dev.strahl.cli;

import dev.strahl.accel.Simd;
import picocli.CommandLine.Command;
import picocli.CommandLine;

/** The {@code strahl} command: a physically based renderer. */
@Command(name = "strahl",
        mixinStandardHelpOptions = true,
        versionProvider = Main.Version.class,
        description = "A physically based ray tracer and Monte Carlo path tracer.",
        subcommands = {RenderCommand.class, WorkerCommand.class, ViewCommand.class, BenchCommand.class, CommandLine.HelpCommand.class})
public final class Main implements Runnable {

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    public static void main(String[] args) {
        int code = SimdLauncher.relaunch(args);
        if (code >= 0) {
            // Halt: this JVM ran nothing, and a recording or hook of its own must not overwrite the child's.
            Runtime.getRuntime().halt(code);
        }
        SimdLauncher.setUpChild();
        System.exit(run(args));
    }

    /** Runs the command line and returns the exit code (0 ok, 1 render failure, 2 bad usage or input). */
    public static int run(String... args) {
        return commandLine().execute(args);
    }

    static CommandLine commandLine() {
        return new CommandLine(new Main()).setCaseInsensitiveEnumValuesAllowed(true)
                .setParameterExceptionHandler(Main::usageError)
                .setExecutionExceptionHandler(Main::internalError);
    }

    /**
     * What a command did not handle itself is a bug: still one line (exit code 1), with the stack
     * trace only under {@code --debug}, where it is what the bug report needs.
     */
    private static int internalError(Exception e, CommandLine cmd, CommandLine.ParseResult parsed) {
        boolean debug = false;
        for (CommandLine.ParseResult p = parsed; p != null; p = p.subcommand()) {
            debug |= p.hasMatchedOption("--debug");
        }
        cmd.getErr().println("strahl: internal error: " + dev.strahl.codec.Printable.line(String.valueOf(e)) + (debug ? "" : " (run with --debug for the stack trace)"));
        if (debug) {
            e.printStackTrace(cmd.getErr());
        }
        cmd.getErr().flush();
        return 1;
    }

    /**
     * A usage error is one line on stderr, like every other error (STYLE.md habit 11), instead of
     * picocli's default of the message followed by the whole usage text, which buries the message.
     */
    private static int usageError(CommandLine.ParameterException e, String[] args) {
        CommandLine cmd = e.getCommandLine();
        String hint = "";
        if (e instanceof CommandLine.UnmatchedArgumentException u && !u.getSuggestions().isEmpty()) {
            hint = "; did you mean " + String.join(" or ", u.getSuggestions()) + "?";
        }
        cmd.getErr().println("strahl: " + e.getMessage() + hint + " (see '" + cmd.getCommandSpec().qualifiedName() + " --help')");
        cmd.getErr().flush();
        return cmd.getCommandSpec().exitCodeOnInvalidInput();
    }

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "missing command: try 'strahl render SCENE -o OUT.png'");
    }

    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = Main.class.getPackage().getImplementationVersion();
            return new String[] {"strahl " + (v != null ? v : "(development build)"),
                "Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vm.name") + ")",
                "ray kernel: " + Simd.describe(Simd.enabled())};
        }
    }
}
