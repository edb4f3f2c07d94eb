package dev.strahl.cli;

import dev.strahl.files.AtomicFile;
import java.io.PrintWriter;
import java.lang.reflect.Constructor;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * What Ctrl-C (SIGINT) and SIGTERM do during {@code strahl render}: the first asks the render to
 * stop, so that the image rendered so far (and a checkpoint) is written; a second one exits at
 * once. Files are written atomically, so even then no truncated file is left behind.
 *
 * <p>The handlers are installed with {@code sun.misc.Signal} (module jdk.unsupported, present in
 * every JDK and reachable from the class path, so with {@code java -jar}), called reflectively so
 * that the build needs no internal API. Where that is not possible (for example under
 * {@code java -Xrs}), a shutdown hook does the first part: it stops the render and waits for the
 * image to be written before the JVM exits.
 */
final class Interrupts implements AutoCloseable {
    /** Exit code after an interruption: 128 + the signal number, as shells report it. */
    static final int SIGINT_EXIT = 130;
    static final int SIGTERM_EXIT = 143;
    private static final long HOOK_WAIT_SECONDS = 120;

    private final PrintWriter err;
    private final AtomicInteger signals = new AtomicInteger();
    private final List<Runnable> uninstall = new ArrayList<>();
    private final CountDownLatch written = new CountDownLatch(1);
    private volatile Runnable stop;
    private volatile int exitCode;

    private volatile String stopping = "stopping";

    private Interrupts(PrintWriter err) {
        this.err = err;
    }

    /** Installs the handlers for SIGINT and SIGTERM until {@link #close()}. */
    static Interrupts install(PrintWriter err) {
        Interrupts irq = new Interrupts(err);
        if (!irq.installSignalHandlers()) {
            irq.installShutdownHook();
        }
        return irq;
    }

    /**
     * What the first signal does: ask the render to stop. A signal that came before this is set
     * (while the scene was loading) has already ended the program, since nothing was rendered.
     */
    void onFirstSignal(Runnable stopRender) {
        onFirstSignal(stopRender, "stopping and writing the image rendered so far");
    }

    /** As {@link #onFirstSignal(Runnable)}, saying what stopping means ("leaving the cluster"). */
    void onFirstSignal(Runnable stop, String stopping) {
        this.stopping = stopping;
        this.stop = stop;
    }

    /** Whether a signal asked the render to stop. */
    boolean interrupted() {
        return exitCode != 0;                  // set before the render is told to stop, so never 0 once it has stopped
    }

    /** {@link #SIGINT_EXIT} or {@link #SIGTERM_EXIT} after a signal, else 0. */
    int exitCode() {
        return exitCode;
    }

    /** Called once the image (and checkpoint) of an interrupted render has been written. */
    void written() {
        written.countDown();
    }

    @Override
    public void close() {
        written.countDown();
        for (Runnable r : uninstall) {
            r.run();
        }
        uninstall.clear();
    }

    /** Runs on the JVM's signal thread. */
    void signal(String name, int code) {
        if (signals.incrementAndGet() > 1 || stop == null) {
            err.println("strahl: " + name + (stop == null ? ": nothing rendered yet, exiting" : " again: exiting at once"));
            err.flush();
            AtomicFile.abandonWritesInProgress();
            Runtime.getRuntime().halt(exitCode != 0 ? exitCode : code);
        }
        exitCode = code;
        err.println("strahl: " + name + ": " + stopping + " (again to exit at once)");
        err.flush();
        stop.run();
    }

    private boolean installSignalHandlers() {
        try {
            Class<?> signalClass = Class.forName("sun.misc.Signal");
            Class<?> handlerClass = Class.forName("sun.misc.SignalHandler");
            Constructor<?> newSignal = signalClass.getConstructor(String.class);
            Method handle = signalClass.getMethod("handle", signalClass, handlerClass);
            List<Runnable> restore = new ArrayList<>();
            for (String name : new String[] {"INT", "TERM"}) {
                // Under the launcher these arrive as SIGUSR1 and SIGURG (SimdLauncher); messages and codes stay those of INT and TERM.
                Object signal = newSignal.newInstance(SimdLauncher.osSignal(name));
                int code = name.equals("INT") ? SIGINT_EXIT : SIGTERM_EXIT;
                Object handler = Proxy.newProxyInstance(handlerClass.getClassLoader(), new Class<?>[] {handlerClass},
                        (proxy, method, args) -> switch (method.getName()) {
                            case "handle" -> {
                                signal("SIG" + name, code);
                                yield null;
                            }
                            case "hashCode" -> System.identityHashCode(proxy);
                            case "equals" -> proxy == args[0];
                            default -> "strahl SIG" + name + " handler";
                        });
                Object previous = handle.invoke(null, signal, handler);
                restore.add(() -> {
                    try {
                        handle.invoke(null, signal, previous);
                    } catch (ReflectiveOperationException | RuntimeException e) {
                        // the JVM is ending or the handler cannot be put back: nothing to lose
                    }
                });
            }
            uninstall.addAll(restore);
            return true;
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            return false;          // e.g. -Xrs (IllegalArgumentException inside), or no jdk.unsupported
        }
    }

    private void installShutdownHook() {
        Thread hook = new Thread(() -> {
            if (stop == null || written.getCount() == 0) {
                return;
            }
            exitCode = SIGINT_EXIT;
            signals.incrementAndGet();
            stop.run();
            try {
                written.await(HOOK_WAIT_SECONDS, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "strahl-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        uninstall.add(() -> {
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException e) {
                // already shutting down
            }
        });
    }
}
