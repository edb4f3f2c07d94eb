package dev.strahl.cli;

import dev.strahl.accel.Simd;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.lang.management.ManagementFactory;
import java.lang.module.ModuleFinder;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

/**
 * Gives {@code java -jar strahl.jar …} the SIMD ray kernel without a flag: the Vector API module
 * ({@code jdk.incubator.vector}) can only join a JVM at its start, so where this JVM lacks it and
 * the JDK has it, {@code main} starts the same command again in a JVM with
 * {@code --add-modules jdk.incubator.vector} and the user's JVM options, and waits for it.
 *
 * <p>What the user sees stays as it was. The child inherits stdin and stdout; its stderr passes
 * through this process, which drops the line the JVM prints for every incubating module
 * ({@value #WARNING}) and copies the rest byte for byte as it comes; the child is told whether
 * that stderr is a terminal ({@link Terminal}), so the progress bar appears where it did. The
 * exit code is the child's. Ctrl-C and SIGTERM: a terminal sends SIGINT to the whole foreground
 * process group (both JVMs), {@code kill PID} only to this one; so that the child sees each signal
 * exactly once (the first asks a render to stop and write its image, a second exits at once),
 * the child ignores SIGINT and SIGTERM and this process forwards each one it gets as SIGUSR1 or
 * SIGURG, which the child takes for them ({@link #osSignal}; not SIGUSR2, with which HotSpot
 * suspends threads for the flight recorder's samples). A child whose parent is gone exits.
 *
 * <p>Not relaunched: {@code --simd off} or {@code -Dstrahl.simd=false} (the scalar kernel is
 * wanted anyway), a JDK without the module, a JVM without C2 ({@code -Xint},
 * {@code -XX:TieredStopAtLevel=1}: the lanes would be slow), and a JVM with an agent or debugger
 * attached (the second JVM would fight over its port). docs/performance.md (round 7) gives the start-up cost.
 */
final class SimdLauncher {
    private SimdLauncher() {}

    static final String MODULE = "jdk.incubator.vector";
    static final String WARNING = "WARNING: Using incubator modules: " + MODULE;
    /** Set on the child: it was started by this launcher, which forwards signals ("forward") or not ("direct"). */
    static final String LAUNCHED = "strahl.launched";
    /** Set on the child: whether the launcher's stderr, which the child's reaches through a pipe, is a terminal. */
    static final String STDERR_TERMINAL = "strahl.stderr.terminal";
    private static final int SIGUSR1_EXIT = 128 + 10;

    /**
     * Runs the command in a JVM with the Vector API module if this one can use one and lacks it.
     *
     * @return the child's exit code, or -1 if the command is to run in this JVM
     */
    static int relaunch(String[] args) {
        if (ModuleLayer.boot().findModule(MODULE).isPresent() || ModuleFinder.ofSystem().find(MODULE).isEmpty()
                || "false".equals(System.getProperty(Simd.PROPERTY)) || simdOff(args)) {
            return -1;
        }
        List<String> jvm = ManagementFactory.getRuntimeMXBean().getInputArguments();
        if (!Simd.c2(jvm)) {
            return -1;
        }
        for (String a : jvm) {
            if (a.startsWith("-agentlib") || a.startsWith("-agentpath") || a.startsWith("-javaagent") || a.startsWith("-Xrunjdwp") || a.equals("-Xdebug")) {
                return -1;
            }
        }
        boolean forward = !System.getProperty("os.name", "").startsWith("Windows");
        List<String> cmd = new ArrayList<>();
        cmd.add(ProcessHandle.current().info().command().orElse(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        for (String a : jvm) {
            // The module path and main module are given again below.
            if (!a.startsWith("--module-path") && !a.startsWith("-Djdk.module.main")) {
                cmd.add(a);
            }
        }
        cmd.add("--add-modules=" + MODULE);
        cmd.add("-D" + LAUNCHED + "=" + (forward ? "forward" : "direct"));
        cmd.add("-D" + STDERR_TERMINAL + "=" + Terminal.isStderrTerminal());
        String modulePath = System.getProperty("jdk.module.path"), classPath = System.getProperty("java.class.path", "");
        if (!classPath.isEmpty()) {
            cmd.addAll(List.of("-cp", classPath));
        }
        if (modulePath != null && SimdLauncher.class.getModule().isNamed()) {
            cmd.addAll(List.of("--module-path", modulePath, "--module", SimdLauncher.class.getModule().getName() + "/" + Main.class.getName()));
        } else {
            cmd.add(Main.class.getName());
        }
        cmd.addAll(Arrays.asList(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectInput(ProcessBuilder.Redirect.INHERIT)
                .redirectOutput(ProcessBuilder.Redirect.INHERIT).redirectError(ProcessBuilder.Redirect.PIPE);
        // Their contents are among this JVM's options, which the child gets: not twice, and no second "Picked up" note.
        Map<String, String> env = pb.environment();
        env.remove("JDK_JAVA_OPTIONS");
        env.remove("JAVA_TOOL_OPTIONS");
        Process child;
        try {
            child = pb.start();
        } catch (IOException e) {
            return -1;                                    // no second JVM: the scalar kernel here
        }
        Thread pump = new Thread(() -> copyStderr(child.getErrorStream(), new FileOutputStream(FileDescriptor.err)), "strahl-stderr");
        pump.start();
        for (String name : new String[] {"INT", "TERM"}) {
            handle(name, forward ? () -> forward(child, name.equals("INT") ? "USR1" : "URG") : () -> { });
        }
        int code;
        while (true) {
            try {
                code = child.waitFor();
                pump.join(2000);                          // the last bytes; a grandchild holding the pipe does not keep us
                break;
            } catch (InterruptedException e) {
                // only signals wake us, and those are forwarded: keep waiting
            }
        }
        if (jvm.stream().anyMatch(a -> a.contains("FlightRecord"))) {
            dropRecordings();
        }
        // A child ended by a forwarded SIGINT before it could handle it ended as by that signal (SIGURG is ignored until then).
        return code == SIGUSR1_EXIT ? Interrupts.SIGINT_EXIT : code;
    }

    /**
     * Closes this JVM's flight recordings without writing them: the child, which got the same
     * {@code -XX:StartFlightRecording}, has written its recording (the one of the work) to that
     * file, and this JVM's, written when it ends (also on halt), would replace it.
     */
    private static void dropRecordings() {
        try {
            Class<?> recorder = Class.forName("jdk.jfr.FlightRecorder");
            if ((Boolean) recorder.getMethod("isInitialized").invoke(null)) {
                Object flightRecorder = recorder.getMethod("getFlightRecorder").invoke(null);
                for (Object recording : (List<?>) recorder.getMethod("getRecordings").invoke(flightRecorder)) {
                    Class.forName("jdk.jfr.Recording").getMethod("close").invoke(recording);
                }
            }
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            // no flight recorder to quiet
        }
    }

    /** Whether the arguments ask for the scalar kernel ({@code --simd off} or {@code --simd=off}). */
    static boolean simdOff(String[] args) {
        for (int i = 0; i < args.length; i++) {
            if (args[i].equalsIgnoreCase("--simd=off") || args[i].equals("--simd") && i + 1 < args.length && args[i + 1].equalsIgnoreCase("off")) {
                return true;
            }
        }
        return false;
    }

    /**
     * In a JVM this launcher started with forwarding: SIGINT and SIGTERM (which the terminal's
     * process group also delivers here) are ignored; SIGUSR1 and SIGURG mean them, and until a
     * command installs its own handlers ({@link Interrupts}) end the JVM as those would (exit code
     * 130 or 143, shutdown hooks run). The JVM exits when its launcher is gone.
     */
    static void setUpChild() {
        String mode = System.getProperty(LAUNCHED);
        if (mode == null) {
            return;
        }
        ProcessHandle.current().parent().ifPresent(p -> p.onExit().thenRun(() -> Runtime.getRuntime().halt(1)));
        if (mode.equals("forward")) {
            handle("INT", null);
            handle("TERM", null);
            handle("USR1", () -> System.exit(Interrupts.SIGINT_EXIT));
            handle("URG", () -> System.exit(Interrupts.SIGTERM_EXIT));
        }
    }

    /** The signal a handler for SIGINT or SIGTERM ({@code name} "INT" or "TERM") listens to in this JVM. */
    static String osSignal(String name) {
        if (!"forward".equals(System.getProperty(LAUNCHED))) {
            return name;
        }
        return name.equals("INT") ? "USR1" : name.equals("TERM") ? "URG" : name;
    }

    private static void forward(Process child, String signal) {
        try {
            new ProcessBuilder("kill", "-" + signal, Long.toString(child.pid())).inheritIO().start();
        } catch (IOException e) {
            child.destroy();                              // no kill command: SIGTERM, which at least ends it
        }
    }

    /**
     * Installs {@code action} for the signal ({@code sun.misc.Signal}, reflectively as in
     * {@link Interrupts}); a null action ignores it. Where that is not possible (e.g. {@code -Xrs}),
     * nothing is installed.
     */
    private static void handle(String name, Runnable action) {
        try {
            Class<?> signalClass = Class.forName("sun.misc.Signal");
            Class<?> handlerClass = Class.forName("sun.misc.SignalHandler");
            Method handle = signalClass.getMethod("handle", signalClass, handlerClass);
            Object handler = action == null ? handlerClass.getField("SIG_IGN").get(null)
                    : Proxy.newProxyInstance(handlerClass.getClassLoader(), new Class<?>[] {handlerClass}, (proxy, method, a) -> switch (method.getName()) {
                        case "handle" -> {
                            action.run();
                            yield null;
                        }
                        case "hashCode" -> System.identityHashCode(proxy);
                        case "equals" -> proxy == a[0];
                        default -> "strahl SIG" + name + " launcher handler";
                    });
            handle.invoke(null, signalClass.getConstructor(String.class).newInstance(name), handler);
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            // the JVM keeps its own handling of this signal
        }
    }

    /** Copies a child's stderr to {@code out} as it comes, without the incubating module's warning line. */
    static void copyStderr(InputStream in, OutputStream out) {
        byte[] warning = (WARNING + System.lineSeparator()).getBytes(StandardCharsets.UTF_8);
        byte[] buf = new byte[8192];
        int matched = 0;                                  // bytes of the warning seen so far, held back
        boolean first = true;
        try {
            for (int n; (n = in.read(buf)) > 0; ) {
                int from = 0;
                if (first) {
                    while (from < n && matched < warning.length && buf[from] == warning[matched]) {
                        from++;
                        matched++;
                    }
                    if (matched == warning.length) {
                        first = false;                    // dropped
                    } else if (from < n) {
                        out.write(warning, 0, matched);   // not the warning after all: what was held back, then the rest
                        first = false;
                    }
                }
                if (!first) {
                    out.write(buf, from, n - from);
                    out.flush();
                }
            }
            if (first) {
                out.write(warning, 0, matched);
            }
            out.flush();
        } catch (IOException e) {
            // our stderr is gone: nothing to copy to
        }
    }
}
