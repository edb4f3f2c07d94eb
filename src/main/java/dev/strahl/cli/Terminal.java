package dev.strahl.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** Whether standard error is a terminal, so that a progress bar is only drawn where a person sees it. */
final class Terminal {
    private Terminal() {}

    /**
     * On Linux, standard error is a terminal when file descriptor 2 points to a tty device. Elsewhere
     * Java 17 offers only {@link System#console()}, which asks about stdin and stdout instead. In a
     * JVM started by {@link SimdLauncher}, the launcher's answer for its own stderr.
     */
    static boolean isStderrTerminal() {
        String launcher = System.getProperty(SimdLauncher.STDERR_TERMINAL);
        if (launcher != null) {
            return Boolean.parseBoolean(launcher);        // stderr reaches the terminal through the launcher's pipe
        }
        Path fd2 = Path.of("/proc/self/fd/2");
        if (Files.exists(fd2)) {
            try {
                String target = Files.readSymbolicLink(fd2).toString();
                return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty");
            } catch (IOException | UnsupportedOperationException | SecurityException e) {
                return false;
            }
        }
        return System.console() != null;
    }
}
