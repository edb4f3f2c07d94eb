package dev.strahl.io.text;

import dev.strahl.codec.Printable;
import java.nio.file.Path;

/**
 * A hand-written tokeniser over one line (no regex, no split): whitespace-separated tokens
 * up to a {@code #} comment, addressed by {@link #start}/{@link #stop} without copying. Its
 * errors are the reader's ({@link InputErrors}).
 *
 * @param <E> the exception the reader throws
 */
public final class LineCursor<E extends Exception> {
    private static final int QUOTE_MAX = 40;

    private final Path file;
    private final InputErrors<E> errors;
    public String line = "";
    public int lineNumber;
    public int start;
    public int stop;
    private int pos;
    private int end;

    public LineCursor(Path file, InputErrors<E> errors) {
        this.file = file;
        this.errors = errors;
    }

    public void reset(String line, int lineNumber) {
        this.line = line;
        this.lineNumber = lineNumber;
        int hash = line.indexOf('#');
        end = hash < 0 ? line.length() : hash;
        pos = 0;
        start = stop = 0;
    }

    /** Moves to the next token; false at the end of the line (or at a comment). */
    public boolean next() {
        while (pos < end && isSpace(line.charAt(pos))) {
            pos++;
        }
        if (pos >= end) {
            return false;
        }
        start = pos;
        while (pos < end && !isSpace(line.charAt(pos))) {
            pos++;
        }
        stop = pos;
        return true;
    }

    public String token() {
        return line.substring(start, stop);
    }

    /** Everything after the current token up to the comment, without surrounding whitespace. */
    public String rest() {
        int s = pos;
        while (s < end && isSpace(line.charAt(s))) {
            s++;
        }
        int e = end;
        while (e > s && isSpace(line.charAt(e - 1))) {
            e--;
        }
        pos = end;
        return line.substring(s, e);
    }

    /** The current token as a number; {@code keyword} names the statement in the message. */
    public double number(String keyword) throws E {
        double value = FastDecimal.parse(line, start, stop);
        if (!Double.isNaN(value)) {
            return value;
        }
        try {
            return Double.parseDouble(token());
        } catch (NumberFormatException e) {
            throw error("bad number " + quote(token()) + " in " + quote(keyword));
        }
    }

    public E error(String message) {
        return errors.at(file, lineNumber, message);
    }

    static boolean isSpace(char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\u000B';
    }

    /** {@code 's'}, shortened if long, for messages about arbitrary input. */
    public static String quote(String s) {
        return "'" + abbreviate(s) + "'";
    }

    /** At most {@code QUOTE_MAX} characters of {@code s}, invisible ones (control characters of a binary file) escaped. */
    public static String abbreviate(String s) {
        return Printable.line(s.length() <= QUOTE_MAX ? s : s.substring(0, QUOTE_MAX)) + (s.length() <= QUOTE_MAX ? "" : "...");
    }
}
