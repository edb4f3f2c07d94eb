package dev.strahl.io.text;

import java.io.BufferedInputStream;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The lines of a text file, with the checks both OBJ and MTL need: a file that is not text (NUL
 * bytes near the start) or cannot be read is the reader's error ({@link InputErrors}) at the line
 * where that shows. A leading byte order mark is dropped.
 *
 * <p><b>Encodings.</b> A file is read as UTF-8; {@link #open} refuses it at the first byte
 * sequence that is not UTF-8. Old exporters write names and comments in Latin-1 or Windows-1252, so the
 * readers then read the whole file again as Latin-1 ({@link #read}: every byte one character,
 * with one note), where a NUL byte or another control character (binary content) on any line is
 * still refused at that line. Names that must match across files ({@code usemtl} and
 * {@code newmtl}) are compared by their bytes, whatever each file's encoding: {@link #byteKey}.
 *
 * @param <E> the exception the reader throws
 */
public final class TextLines<E extends Exception> implements AutoCloseable {
    private static final int HEAD = 1024;

    private final Path file;
    private final InputErrors<E> errors;
    private final String kind;
    private final boolean continuation;
    private final BufferedReader reader;
    private final boolean latin1;
    private boolean signalNotUtf8;         // read(): throw NotUtf8 instead of refusing the file
    private int physicalLine;
    private int lineNumber;

    private TextLines(Path file, InputErrors<E> errors, String kind, boolean continuation, BufferedReader reader, boolean latin1) {
        this.file = file;
        this.errors = errors;
        this.kind = kind;
        this.continuation = continuation;
        this.reader = reader;
        this.latin1 = latin1;
    }

    /** What a reader does with the lines of one file. */
    @FunctionalInterface
    public interface Parse<T, E extends Exception> {
        /** Reads the file from {@code lines}, appending its warnings to {@code warnings}. */
        T apply(TextLines<E> lines, List<String> warnings) throws E;
    }

    /**
     * Reads {@code file} with {@code parse}: as UTF-8, or, if it is not UTF-8, once more from the
     * start as Latin-1 with the note "FILE: not UTF-8 (first at line N): read as Latin-1" before
     * the warnings of that reading (those of the failed UTF-8 reading are dropped).
     */
    public static <T, E extends Exception> T read(Path file, InputErrors<E> errors, String kind, boolean continuation, List<String> warnings,
                                                  Parse<T, E> parse) throws E {
        List<String> utf8Warnings = new ArrayList<>();
        int line;
        try (TextLines<E> lines = open(file, errors, kind, continuation, false)) {
            lines.signalNotUtf8 = true;
            T result = parse.apply(lines, utf8Warnings);
            warnings.addAll(utf8Warnings);
            return result;
        } catch (NotUtf8 e) {
            if (e.source.file != file) {
                throw e;                   // not this file's (a file it includes reads its own)
            }
            line = e.line;
        }
        warnings.add(file + ": not UTF-8 (first at line " + line + "): read as Latin-1");
        try (TextLines<E> lines = open(file, errors, kind, continuation, true)) {
            return parse.apply(lines, warnings);
        }
    }

    /**
     * The signal from a file read by {@link #read} as UTF-8 that is not: unchecked, so that it
     * passes through the parser to {@link #read}, which catches it and never lets it out.
     */
    private static final class NotUtf8 extends RuntimeException {
        private static final long serialVersionUID = 1L;
        final transient TextLines<?> source;
        final int line;

        NotUtf8(TextLines<?> source, int line) {
            super(null, null, false, false);
            this.source = source;
            this.line = line;
        }
    }

    /**
     * Opens {@code file}; {@code kind} ("OBJ", "MTL") is used in messages, {@code continuation}
     * joins a line ending in a backslash with the next one.
     */
    public static <E extends Exception> TextLines<E> open(Path file, InputErrors<E> errors, String kind, boolean continuation) throws E {
        return open(file, errors, kind, continuation, false);
    }

    /** As {@link #open(Path, InputErrors, String, boolean)}, as Latin-1 (one character per byte) if {@code latin1}. */
    private static <E extends Exception> TextLines<E> open(Path file, InputErrors<E> errors, String kind, boolean continuation, boolean latin1)
            throws E {
        if (Files.isDirectory(file)) {
            throw errors.about(file, "is a directory, not an " + kind + " file", null);
        }
        InputStream in;
        try {
            dev.strahl.files.FileReads.note(file);
            in = Files.newInputStream(file);
        } catch (NoSuchFileException e) {
            throw errors.about(file, "file not found", e);
        } catch (AccessDeniedException e) {
            throw errors.about(file, "cannot read: permission denied", e);
        } catch (IOException | SecurityException e) {
            throw errors.about(file, "cannot read: " + describe(e), e);
        }
        try {
            var buffered = new BufferedInputStream(in, 1 << 16);
            buffered.mark(HEAD);
            byte[] head = buffered.readNBytes(HEAD);
            buffered.reset();
            for (int i = 0, line = 1; i < head.length; i++) {
                if (head[i] == '\n') {
                    line++;
                } else if (head[i] == 0) {
                    closeQuietly(in);
                    throw notText(errors, file, kind, line, "NUL byte");
                }
            }
            CharsetDecoder decoder = (latin1 ? StandardCharsets.ISO_8859_1 : StandardCharsets.UTF_8).newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT);
            var reader = new BufferedReader(new InputStreamReader(buffered, decoder), 1 << 16);
            return new TextLines<>(file, errors, kind, continuation, reader, latin1);
        } catch (IOException e) {
            closeQuietly(in);
            throw errors.about(file, "cannot read: " + describe(e), e);
        }
    }

    /** The next logical line, or null at the end of the file. */
    public String next() throws E {
        String line = readPhysical();
        if (line == null) {
            return null;
        }
        lineNumber = physicalLine;
        if (physicalLine == 1 && line.startsWith("\uFEFF")) {
            line = line.substring(1);
        }
        if (!continuation || !endsWithBackslash(line)) {
            return line;
        }
        var joined = new StringBuilder(line);
        while (endsWithBackslash(joined)) {
            trimEnd(joined);
            joined.setLength(joined.length() - 1);
            String more = readPhysical();
            if (more == null) {
                break;
            }
            joined.append(' ').append(more);
        }
        return joined.toString();
    }

    /** Whether this file is read as Latin-1 (it is not UTF-8). */
    public boolean isLatin1() {
        return latin1;
    }

    /**
     * A string made of the bytes {@code text} (read from this file) had in the file, one
     * character per byte: equal keys mean equal bytes, whichever encoding each file was read in.
     */
    public String byteKey(String text) {
        if (latin1) {
            return text;
        }
        for (int i = 0; i < text.length(); i++) {
            if (text.charAt(i) >= 0x80) {
                return new String(text.getBytes(StandardCharsets.UTF_8), StandardCharsets.ISO_8859_1);
            }
        }
        return text;                      // ASCII: the same bytes in both
    }

    /** The line number (from 1) of the first physical line of the last logical line. */
    public int lineNumber() {
        return lineNumber;
    }

    @Override
    public void close() {
        closeQuietly(reader);
    }

    private String readPhysical() throws E {
        try {
            String line = reader.readLine();
            if (line != null) {
                physicalLine++;
                if (latin1) {
                    checkText(line);
                }
            }
            return line;
        } catch (CharacterCodingException e) {
            int line = lineOfInvalidUtf8(file, physicalLine + 1);
            if (signalNotUtf8) {
                throw new NotUtf8(this, line);
            }
            throw notText(errors, file, kind, line, "invalid UTF-8");
        } catch (IOException e) {
            throw errors.about(file, "cannot read after line " + physicalLine + ": " + describe(e), e);
        }
    }

    /**
     * A file that is not UTF-8 is only read as Latin-1 if it is text: no NUL and no control
     * character other than tab, vertical tab, form feed and the DOS end-of-file mark (Ctrl-Z).
     */
    private void checkText(String line) throws E {
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (c < 0x20 && c != '\t' && c != 0x0B && c != '\f' && c != 0x1A) {
                throw notText(errors, file, kind, physicalLine, c == 0 ? "NUL byte" : "binary content");
            }
        }
    }

    /** A backslash as the last visible character of a line that holds no comment. */
    private static boolean endsWithBackslash(CharSequence s) {
        int i = s.length() - 1;
        while (i >= 0 && LineCursor.isSpace(s.charAt(i))) {
            i--;
        }
        if (i < 0 || s.charAt(i) != '\\') {
            return false;
        }
        for (int j = 0; j < i; j++) {
            if (s.charAt(j) == '#') {
                return false;
            }
        }
        return true;
    }

    private static void trimEnd(StringBuilder s) {
        int n = s.length();
        while (n > 0 && LineCursor.isSpace(s.charAt(n - 1))) {
            n--;
        }
        s.setLength(n);
    }

    private static <E extends Exception> E notText(InputErrors<E> errors, Path file, String kind, int line, String why) {
        return errors.at(file, line, "not a text " + kind + " file (" + why + ")");
    }

    /**
     * The line of the first byte sequence that is not UTF-8. The decoder behind the reader works
     * ahead in blocks and cannot say where it failed, so this pass over the bytes (only taken
     * on the error path) finds it; {@code fallback} if it finds nothing.
     */
    public static int lineOfInvalidUtf8(Path file, int fallback) {
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file), 1 << 16)) {
            int line = 1;
            int need = 0;
            int lo = 0x80;
            int hi = 0xBF;
            for (int b; (b = in.read()) >= 0; ) {
                if (need > 0) {
                    if (b < lo || b > hi) {
                        return line;
                    }
                    need--;
                    lo = 0x80;
                    hi = 0xBF;
                } else if (b < 0x80) {
                    line += b == '\n' ? 1 : 0;
                } else if (b >= 0xC2 && b <= 0xDF) {
                    need = 1;
                } else if (b >= 0xE0 && b <= 0xEF) {
                    need = 2;               // no overlong forms (E0) and no surrogates (ED)
                    lo = b == 0xE0 ? 0xA0 : 0x80;
                    hi = b == 0xED ? 0x9F : 0xBF;
                } else if (b >= 0xF0 && b <= 0xF4) {
                    need = 3;               // no overlong forms (F0) and nothing above U+10FFFF (F4)
                    lo = b == 0xF0 ? 0x90 : 0x80;
                    hi = b == 0xF4 ? 0x8F : 0xBF;
                } else {
                    return line;
                }
            }
            return need > 0 ? line : fallback;
        } catch (IOException | SecurityException e) {
            return fallback;
        }
    }

    private static void closeQuietly(AutoCloseable c) {
        try {
            c.close();
        } catch (Exception ignored) {
            // nothing was written; a failing close cannot lose data
        }
    }

    /** "NoSuchFileException: path" style: the exception type says most, its message the rest. */
    static String describe(Exception e) {
        String name = e.getClass().getSimpleName();
        String message = e.getMessage();
        return message == null || message.isBlank() ? name : name + ": " + message;
    }

    /** The one-line error for a file that cannot be read. */
    public static <E extends Exception> E cannotRead(InputErrors<E> errors, Path file, IOException e) {
        if (e instanceof NoSuchFileException) {
            return errors.about(file, "file not found", null);
        }
        if (e instanceof AccessDeniedException) {
            return errors.about(file, "permission denied", null);
        }
        return errors.about(file, "cannot read: " + e.getMessage(), e);
    }
}
