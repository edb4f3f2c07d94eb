package dev.strahl.files;

import java.nio.file.Path;
import java.util.Set;
import java.util.concurrent.Callable;

/**
 * Which files a scene is made of: every reader notes the file it opens ({@link #note}), and a
 * cluster render, which must ship the scene file with every mesh, material library and image it
 * references, records them while the scene loads ({@link #recording}). One thread-local set, so
 * that scenes loading at the same time on other threads do not mix.
 */
public final class FileReads {
    private static final ThreadLocal<Set<Path>> RECORDING = new ThreadLocal<>();

    private FileReads() {}

    /**
     * Notes that {@code file} is read (by the current thread); costs nothing unless recording.
     *
     * @param file the file opened
     */
    public static void note(Path file) {
        Set<Path> into = RECORDING.get();
        if (into != null) {
            into.add(file.toAbsolutePath().normalize());
        }
    }

    /** @return whether the current thread records the files it reads (for a cluster render) */
    public static boolean isRecording() {
        return RECORDING.get() != null;
    }

    /**
     * Runs {@code load} and adds every file it reads on this thread to {@code into}.
     *
     * @param into receives the absolute, normalised paths
     * @param load what reads the files
     * @param <T>  what it returns
     * @return what {@code load} returned
     * @throws Exception what {@code load} threw
     */
    public static <T> T recording(Set<Path> into, Callable<T> load) throws Exception {
        Set<Path> outer = RECORDING.get();
        RECORDING.set(into);
        try {
            return load.call();
        } finally {
            if (outer != null) {
                outer.addAll(into);
            }
            RECORDING.set(outer);
        }
    }
}
