package dev.strahl.viewer;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;

/**
 * The last {@value #MAX} scene files opened, newest first, for File → Open Recent. Kept across
 * sessions in {@link java.util.prefs} (the user's preferences: on Linux under ~/.java), as keys
 * {@code recent.0} … {@code recent.7} holding absolute paths. A store that cannot be written (no
 * writable home) only loses the list: opening files never fails because of it.
 */
final class RecentFiles {
    /** How many files the list keeps. */
    static final int MAX = 8;
    private static final String KEY = "recent.";

    private final Preferences node;

    RecentFiles(Preferences node) {
        this.node = node;
    }

    /** The list in the user's preferences, node {@code /dev/strahl/viewer}. */
    static RecentFiles user() {
        return new RecentFiles(Preferences.userRoot().node("dev/strahl/viewer"));
    }

    /** The files, newest first. */
    List<Path> list() {
        List<Path> out = new ArrayList<>();
        for (int i = 0; i < MAX; i++) {
            String p = node.get(KEY + i, null);
            if (p != null && !p.isEmpty()) {
                out.add(Path.of(p));
            }
        }
        return out;
    }

    /** Puts {@code file} (made absolute) first; an older entry of it goes, and the list keeps {@value #MAX}. */
    void add(Path file) {
        Path abs = file.toAbsolutePath().normalize();
        List<Path> files = list();
        files.remove(abs);
        files.add(0, abs);
        store(files);
    }

    /** Takes {@code file} off the list (a recent file that no longer opens). */
    void remove(Path file) {
        List<Path> files = list();
        files.remove(file.toAbsolutePath().normalize());
        store(files);
    }

    /** Empties the list. */
    void clear() {
        store(List.of());
    }

    private void store(List<Path> files) {
        for (int i = 0; i < MAX; i++) {
            if (i < files.size()) {
                node.put(KEY + i, files.get(i).toString());
            } else {
                node.remove(KEY + i);
            }
        }
        try {
            node.flush();
        } catch (BackingStoreException | SecurityException e) {
            // The list lives on in this session; the next one starts without it.
        }
    }
}
