package dev.strahl.io.text;

import java.nio.file.Path;

/**
 * The exception a reader throws for what is wrong in its input, made where this package finds it
 * ({@link TextLines}, {@link LineCursor}): the scene readers pass
 * {@code InputErrors.of(SceneException::new, SceneException::new)}, so this package, below the
 * scene model, names no exception of it. Every message starts with the file ({@code file: ...} or
 * {@code file:line: ...}).
 *
 * @param <E> the reader's exception
 */
public interface InputErrors<E extends Exception> {

    /** An error at line {@code line} (from 1) of {@code file}. */
    E at(Path file, int line, String message);

    /** An error about {@code file} as a whole, with the exception behind it, or null. */
    E about(Path file, String message, Throwable cause);

    /** Makes a line's error. */
    @FunctionalInterface
    interface AtLine<E extends Exception> {
        E make(Path file, int line, String message);
    }

    /** Makes a file's error. */
    @FunctionalInterface
    interface AboutFile<E extends Exception> {
        E make(Path file, String message, Throwable cause);
    }

    /** The errors made by these two constructors (of one exception class, as a rule). */
    static <E extends Exception> InputErrors<E> of(AtLine<E> atLine, AboutFile<E> aboutFile) {
        return new InputErrors<>() {
            @Override
            public E at(Path file, int line, String message) {
                return atLine.make(file, line, message);
            }

            @Override
            public E about(Path file, String message, Throwable cause) {
                return aboutFile.make(file, message, cause);
            }
        };
    }
}
