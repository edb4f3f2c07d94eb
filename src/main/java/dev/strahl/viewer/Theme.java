package dev.strahl.viewer;

import com.formdev.flatlaf.FlatDarkLaf;
import com.formdev.flatlaf.FlatLightLaf;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * The look and feel: FlatLaf, light or dark. {@code system} (the default) follows the desktop's
 * setting where it can be read: the {@code GTK_THEME} variable, GNOME's {@code color-scheme} or
 * theme name (through {@code gsettings}), KDE's colour scheme in {@code ~/.config/kdeglobals},
 * macOS's {@code AppleInterfaceStyle} and Windows' {@code AppsUseLightTheme}; light when none
 * says dark. The choice is made once, at start-up.
 */
public enum Theme {
    SYSTEM, LIGHT, DARK;

    /** Longest wait for a helper program that reads the desktop setting. */
    private static final long PROBE_MILLIS = 800;

    /** The theme named {@code system}, {@code light} or {@code dark} (any case). */
    public static Theme parse(String name) {
        try {
            return valueOf(name.trim().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("unknown theme '" + name + "': use system, light or dark");
        }
    }

    /** Installs the look and feel; returns whether it is dark. Call before creating any component. */
    boolean install() {
        boolean dark = this == DARK || (this == SYSTEM && systemPrefersDark(System.getenv()));
        if (dark) {
            FlatDarkLaf.setup();
        } else {
            FlatLightLaf.setup();
        }
        return dark;
    }

    static boolean systemPrefersDark(Map<String, String> env) {
        String os = System.getProperty("os.name", "").toLowerCase(Locale.ROOT);
        if (os.contains("mac")) {
            return probe(List.of("defaults", "read", "-g", "AppleInterfaceStyle")).toLowerCase(Locale.ROOT).contains("dark");
        }
        if (os.contains("win")) {
            String out = probe(List.of("reg", "query", "HKCU\\Software\\Microsoft\\Windows\\CurrentVersion\\Themes\\Personalize",
                    "/v", "AppsUseLightTheme"));
            return out.matches("(?s).*AppsUseLightTheme\\s+REG_DWORD\\s+0x0+\\b.*");
        }
        String gtk = env.get("GTK_THEME");
        if (gtk != null && !gtk.isBlank()) {
            return isDarkName(gtk);
        }
        String scheme = probe(List.of("gsettings", "get", "org.gnome.desktop.interface", "color-scheme"));
        if (!scheme.isBlank()) {
            return scheme.contains("prefer-dark") || (!scheme.contains("prefer-light")
                    && isDarkName(probe(List.of("gsettings", "get", "org.gnome.desktop.interface", "gtk-theme"))));
        }
        return isDarkKdeScheme(Path.of(System.getProperty("user.home", ""), ".config", "kdeglobals"));
    }

    /** Whether a GTK theme name ("Adwaita:dark", "Yaru-dark", "Breeze-Dark") is a dark variant. */
    static boolean isDarkName(String themeName) {
        return themeName.toLowerCase(Locale.ROOT).matches("(?s).*(^|[^a-z])dark([^a-z]|$).*");
    }

    private static boolean isDarkKdeScheme(Path kdeglobals) {
        try {
            for (String line : Files.readAllLines(kdeglobals, StandardCharsets.UTF_8)) {
                if (line.startsWith("ColorScheme=")) {
                    return isDarkName(line.substring("ColorScheme=".length())) || line.toLowerCase(Locale.ROOT).contains("dark");
                }
            }
        } catch (IOException | RuntimeException e) {
            // no KDE settings: not dark
        }
        return false;
    }

    /** The output of a short helper program, or "" if it is missing, fails or takes too long. */
    private static String probe(List<String> command) {
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            p.getOutputStream().close();
            if (!p.waitFor(PROBE_MILLIS, TimeUnit.MILLISECONDS)) {
                p.destroyForcibly();
                return "";
            }
            try (InputStream in = p.getInputStream()) {
                return p.exitValue() == 0 ? new String(in.readAllBytes(), StandardCharsets.UTF_8) : "";
            }
        } catch (IOException e) {
            return "";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "";
        }
    }
}
