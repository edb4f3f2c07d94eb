package dev.strahl.scene;

import dev.strahl.codec.Printable;
import java.nio.file.Path;

/**
 * A scene input that cannot be used: a file that is missing, unreadable or malformed. The
 * message starts with the file and, where known, the line ({@code file:line: what is wrong}),
 * so that a command-line tool can print it as the one line a user needs. Whatever a reader quotes
 * from a file, the message stays one printable line: control characters are escaped
 * ({@code \n}, {@code \x1b}).
 */
public final class SceneException extends Exception {
    private final transient Path file;
    /** The line of the error, from 1, or 0 for the whole file. */
    private final int line;

    /**
     * An error at a line of a file.
     *
     * @param file    the file
     * @param line    the line, from 1
     * @param message what is wrong, without the file and line
     */
    public SceneException(Path file, int line, String message) {
        super(Printable.line(file + ":" + line + ": " + message));
        this.file = file;
        this.line = line;
    }

    /**
     * An error about a whole file.
     *
     * @param file    the file
     * @param message what is wrong, without the file
     */
    public SceneException(Path file, String message) {
        super(Printable.line(file + ": " + message));
        this.file = file;
        this.line = 0;
    }

    /**
     * An error about a whole file, caused by another exception (an I/O error).
     *
     * @param file    the file
     * @param message what is wrong, without the file
     * @param cause   the underlying exception
     */
    public SceneException(Path file, String message, Throwable cause) {
        super(Printable.line(file + ": " + message), cause);
        this.file = file;
        this.line = 0;
    }

    /**
     * The file the error is about.
     *
     * @return the file (not kept when the exception is serialised)
     */
    public Path file() {
        return file;
    }

    /**
     * The line of the error.
     *
     * @return the line, from 1, or 0 when the error concerns the whole file
     */
    public int line() {
        return line;
    }
}
