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
        super(file + ": " + message);
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
        super(file + ":" + line + ": " + message);
    }

    /**
     * A file's text (a magic word, a header token or name) as it may be quoted in a message: at most
     * 40 characters, anything but printable ASCII shown as '?', so that binary garbage cannot break
     * the one-line message.
     */
    public static String printable(String s) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < s.length() && i < 40; i++) {
            char c = s.charAt(i);
            sb.append(c >= 0x20 && c < 0x7f ? c : '?');
        }
        return s.length() > 40 ? sb + "..." : sb.toString();
    }

    /**
     * @param file    the file being read
     * @param message what is wrong and where, without the file name
     * @param cause   the decoder's own exception, kept for {@code --debug}
     */
    public ImageFormatException(Path file, String message, Throwable cause) {
        super(file + ": " + message, cause);
    }
}
