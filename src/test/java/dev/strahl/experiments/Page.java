package dev.strahl.experiments;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Writes docs/experiments.md from its template (docs/experiments/page.md.in) and the measured
 * figures (docs/experiments/figures.txt): every {@code {key}} becomes the figure's value,
 * {@code {key.percent}} its value in per cent. Numbers are shown with three significant digits,
 * large ones with an SI prefix (1.23 M). A key without a figure (the bunny's, when its mesh is
 * missing) is written as "(not measured)", with a warning.
 */
final class Page {
    private static final Pattern KEY = Pattern.compile("\\{([a-z0-9_.]+)}");

    private Page() {}

    static Map<String, String> read(Path figures) throws IOException {
        Map<String, String> m = new LinkedHashMap<>();
        if (Files.isRegularFile(figures)) {
            for (String line : Files.readAllLines(figures)) {
                int eq = line.indexOf(" = ");
                if (eq > 0) {
                    m.put(line.substring(0, eq), line.substring(eq + 3));
                }
            }
        }
        return m;
    }

    static void write(Path template, Map<String, String> figures, Path page) throws IOException {
        String text = Files.readString(template);
        Matcher m = KEY.matcher(text);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            m.appendReplacement(out, Matcher.quoteReplacement(value(m.group(1), figures)));
        }
        m.appendTail(out);
        String header = "<!-- Written by docs/experiments/run.sh from docs/experiments/page.md.in and figures.txt: edit those, not this file. -->\n";
        Files.writeString(page, header + out);
    }

    private static String value(String key, Map<String, String> figures) {
        boolean percent = key.endsWith(".percent");
        String k = percent ? key.substring(0, key.length() - ".percent".length()) : key;
        String v = figures.get(k);
        if (v == null) {             // e.g. the bunny's figures when its mesh is not there
            System.err.println("experiments: warning: no figure " + k + " (the page says 'not measured')");
            return "(not measured)";
        }
        double d;
        try {
            d = Double.parseDouble(v);
        } catch (NumberFormatException e) {
            return v;
        }
        return format(percent ? 100 * d : d);
    }

    static String format(double d) {
        double a = Math.abs(d);
        if (a >= 1e5) {
            List<String> prefixes = List.of("k", "M", "G", "T");
            int p = -1;
            while (a >= 1e3 && p < prefixes.size() - 1) {
                a /= 1e3;
                d /= 1e3;
                p++;
            }
            return sig(d) + " " + prefixes.get(p);
        }
        if (d == Math.rint(d) && a < 1e5) {
            return String.valueOf((long) d);
        }
        return sig(d);
    }

    private static String sig(double d) {
        return new java.math.BigDecimal(d).round(new java.math.MathContext(3)).stripTrailingZeros().toPlainString();
    }

    static String locale(double d) {
        return String.format(Locale.ROOT, "%.3g", d);
    }
}
