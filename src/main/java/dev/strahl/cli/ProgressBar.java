package dev.strahl.cli;

import dev.strahl.io.text.NumberText;
import java.io.PrintStream;
import java.util.Locale;

/** A one-line progress bar with rate and ETA, redrawn in place on a terminal. */
final class ProgressBar {
    private static final int WIDTH = 30;

    private final PrintStream out;

    ProgressBar(PrintStream out) {
        this.out = out;
    }

    void update(double fraction, double seconds, long samples) {
        update(fraction, seconds, samples, "");
    }

    /** With {@code extra} after the figures (a cluster's member count). */
    void update(double fraction, double seconds, long samples, String extra) {
        int filled = (int) Math.round(fraction * WIDTH);
        double rate = seconds > 0 ? samples / seconds : 0;
        String eta = fraction > 0 && fraction < 1 ? NumberText.duration(seconds * (1 - fraction) / fraction) : "--:--";
        out.print(String.format(Locale.ROOT, "\r[%s%s] %3d%%  %s samples/s  elapsed %s  ETA %s ",
                "#".repeat(filled), "-".repeat(WIDTH - filled), (int) (fraction * 100), NumberText.si(rate), NumberText.duration(seconds), eta) + extra);
        out.flush();
    }

    void finish() {
        out.print("\r" + " ".repeat(WIDTH + 70) + "\r");
        out.flush();
    }
}
