package dev.strahl.cli;

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
        int filled = (int) Math.round(fraction * WIDTH);
        double rate = seconds > 0 ? samples / seconds : 0;
        String eta = fraction > 0 && fraction < 1 ? formatDuration(seconds * (1 - fraction) / fraction) : "--:--";
        out.print(String.format(Locale.ROOT, "\r[%s%s] %3d%%  %s samples/s  elapsed %s  ETA %s ",
                "#".repeat(filled), "-".repeat(WIDTH - filled), (int) (fraction * 100), si(rate), formatDuration(seconds), eta));
        out.flush();
    }

    void finish() {
        out.print("\r" + " ".repeat(WIDTH + 70) + "\r");
        out.flush();
    }

    static String formatDuration(double seconds) {
        long s = Math.round(seconds);
        return s >= 3600 ? String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60)
                : String.format(Locale.ROOT, "%d:%02d", s / 60, s % 60);
    }

    /** 1234567 → "1.23 M". */
    static String si(double v) {
        if (v >= 1e9) {
            return String.format(Locale.ROOT, "%.2f G", v / 1e9);
        }
        if (v >= 1e6) {
            return String.format(Locale.ROOT, "%.2f M", v / 1e6);
        }
        if (v >= 1e3) {
            return String.format(Locale.ROOT, "%.2f k", v / 1e3);
        }
        return String.format(Locale.ROOT, "%.0f", v);
    }
}
