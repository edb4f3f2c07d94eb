package dev.strahl.bench;

import dev.strahl.io.text.NumberText;
import java.io.PrintStream;

/** The progress line of {@code strahl bench}: redrawn in place on a terminal, one line per step elsewhere. */
public final class BenchProgress {
    private final PrintStream out;
    private final boolean terminal;
    private final long start = System.nanoTime();
    private int width;

    public BenchProgress(PrintStream out, boolean terminal) {
        this.out = out;
        this.terminal = terminal;
    }

    public void step(String what) {
        String line = String.format(java.util.Locale.ROOT, "bench %s  %s", NumberText.duration((System.nanoTime() - start) * 1e-9), what);
        if (terminal) {
            out.print("\r" + line + " ".repeat(Math.max(0, width - line.length())));
            width = line.length();
        } else {
            out.println(line);
        }
        out.flush();
    }

    public void done() {
        if (terminal && width > 0) {
            out.print("\r" + " ".repeat(width) + "\r");
            out.flush();
            width = 0;
        }
    }
}
