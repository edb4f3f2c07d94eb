package dev.strahl.codec;

/**
 * How a message quotes what a file holds: a hostile file's text or bytes must never reach a user's
 * terminal as they are (control characters, escape sequences, a line break that splits the one
 * line, megabytes of a data URI). Printable ASCII is kept; everything else is escaped as
 * {@code \n}, {@code \t}, {@code \xNN} or &#92;uNNNN; and a quote stops after a few characters.
 */
public final class Printable {
    /** The characters of a file's text that a message quotes at most. */
    public static final int QUOTE_LENGTH = 32;
    /** A whole message longer than this is cut (a message, not a file, so this is generous). */
    static final int LINE_LENGTH = 2000;

    private Printable() {
    }

    /**
     * A file's text as a message may quote it: at most {@link #QUOTE_LENGTH} characters, printable
     * ASCII as it is, anything else escaped; "..." where it was cut.
     *
     * @param s text from a file
     * @return the escaped text, without quotes around it
     */
    public static String text(CharSequence s) {
        return text(s, QUOTE_LENGTH);
    }

    /**
     * @param s   text from a file
     * @param max the characters of {@code s} to keep
     * @return the first {@code max} characters, escaped, and "..." if {@code s} is longer
     */
    public static String text(CharSequence s, int max) {
        StringBuilder sb = new StringBuilder();
        int n = Math.min(s.length(), max);
        for (int i = 0; i < n; i++) {
            escape(sb, s.charAt(i));
        }
        return s.length() > max ? sb.append("...").toString() : sb.toString();
    }

    /** {@link #text(CharSequence)} in single quotes: {@code 'abc\x01'}. */
    public static String quote(CharSequence s) {
        return "'" + text(s) + "'";
    }

    /**
     * Raw bytes of a file as a message may quote them: printable ASCII as it is, other bytes as
     * {@code \xNN}, at most {@code n} of them (and "..." if the file has more there).
     *
     * @param b      the bytes
     * @param offset where the quote starts
     * @param n      how many bytes to quote at most
     * @return the quote, without quotes around it
     */
    public static String bytes(byte[] b, int offset, int n) {
        StringBuilder sb = new StringBuilder();
        int end = (int) Math.min(b.length, (long) offset + n);
        for (int i = offset; i < end; i++) {
            int c = b[i] & 0xff;
            if (c >= 0x20 && c < 0x7f && c != '\\') {
                sb.append((char) c);
            } else {
                sb.append(String.format("\\x%02x", c));
            }
        }
        return end < b.length ? sb.append("...").toString() : sb.toString();
    }

    /**
     * A file name for a message: printable characters kept (a name in any script stays readable),
     * invisible ones escaped, at most 300 characters. For names that come from a file's content
     * (a glTF URI), where a hostile file could put anything.
     *
     * @param path the path
     * @return its printable form
     */
    public static String path(Object path) {
        String s = String.valueOf(path);
        return s.length() > 300 ? line(s.substring(0, 300)) + "..." : line(s);
    }

    /**
     * A message made safe to print as one line, whatever it quotes: control characters, line and
     * paragraph separators and invisible format characters escaped, other (printable) characters
     * kept, so that file names in any script stay readable; cut at {@value #LINE_LENGTH} characters.
     * The last line of defence of the command line: readers quote with {@link #text} already.
     *
     * @param message a message, possibly null
     * @return the line
     */
    public static String line(String message) {
        if (message == null) {
            return "null";
        }
        StringBuilder sb = new StringBuilder();
        int n = Math.min(message.length(), LINE_LENGTH);
        for (int i = 0; i < n; i++) {
            char c = message.charAt(i);
            int type = Character.getType(c);
            boolean invisible = type == Character.CONTROL || type == Character.FORMAT || type == Character.LINE_SEPARATOR
                    || type == Character.PARAGRAPH_SEPARATOR || type == Character.PRIVATE_USE || type == Character.UNASSIGNED
                    || type == Character.SURROGATE && !validSurrogate(message, i);
            if (invisible) {
                escape(sb, c);
            } else {
                sb.append(c);
            }
        }
        return message.length() > LINE_LENGTH ? sb.append("...").toString() : sb.toString();
    }

    private static boolean validSurrogate(String s, int i) {
        char c = s.charAt(i);
        return Character.isHighSurrogate(c) ? i + 1 < s.length() && Character.isLowSurrogate(s.charAt(i + 1))
                : i > 0 && Character.isHighSurrogate(s.charAt(i - 1));
    }

    private static void escape(StringBuilder sb, char c) {
        if (c >= 0x20 && c < 0x7f && c != '\\') {
            sb.append(c);
        } else if (c == '\\') {
            sb.append("\\\\");
        } else if (c == '\n') {
            sb.append("\\n");
        } else if (c == '\r') {
            sb.append("\\r");
        } else if (c == '\t') {
            sb.append("\\t");
        } else if (c < 0x100) {
            sb.append(String.format("\\x%02x", (int) c));
        } else {
            sb.append(String.format("\\u%04x", (int) c));
        }
    }
}
