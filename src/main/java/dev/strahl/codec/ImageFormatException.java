package dev.strahl.codec;

import java.io.IOException;
import java.nio.file.Path;

/**
 * An image file that cannot be read: not of its format, truncated, corrupt, of a kind strahl does
 * not read, or too large for the heap. The message is one line that starts with the file name and,
 * where it helps, the place in the file ({@code "sky.exr: chunk 3 (byte 1234): ..."}), ready to be
 * shown to a user as it is (docs/reliability.md). Every image reader of strahl throws this, and
 * only this, for a bad file; other {@link IOException}s mean the file could not be read at all
 * (missing, a directory, no permission).
 */
public final class ImageFormatException extends IOException {
    private static final long serialVersionUID = 1L;

    /**
     * @param file    the file being read
     * @param message what is wrong and where, without the file name
     */
    public ImageFormatException(Path file, String message) {
        super(Printable.line(file + ": " + message));
    }

    /**
     * For a text line of a file (a header line): the message starts {@code "file:line: "}, as
     * the scene readers' do.
     *
     * @param file    the file being read
     * @param line    the line, from 1
     * @param message what is wrong, without the file name and line
     */
    public ImageFormatException(Path file, int line, String message) {
        super(Printable.line(file + ":" + line + ": " + message));
    }

    /**
     * A file's text (a magic word, a header token or name) as it may be quoted in a message: at most
     * {@link Printable#QUOTE_LENGTH} characters, anything but printable ASCII escaped, so that binary
     * garbage cannot break the one-line message ({@link Printable#text}).
     */
    public static String printable(String s) {
        return Printable.text(s);
    }

    /**
     * @param file    the file being read
     * @param message what is wrong and where, without the file name
     * @param cause   the decoder's own exception, kept for {@code --debug}
     */
    public ImageFormatException(Path file, String message, Throwable cause) {
        super(Printable.line(file + ": " + message), cause);
    }
}
