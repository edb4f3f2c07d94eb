package dev.strahl.io.text;

import dev.strahl.scene.SceneException;
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

/**
 * The lines of a UTF-8 text file, with the checks both OBJ and MTL need: a file that is not
 * text (NUL bytes near the start, invalid UTF-8 anywhere) or cannot be read is a
 * {@link SceneException} at the line where that shows. A leading byte order mark is dropped.
 */
public final class TextLines implements AutoCloseable {
    private static final int HEAD = 1024;

    private final Path file;
    private final String kind;
    private final boolean continuation;
    private final BufferedReader reader;
    private int physicalLine;
    private int lineNumber;

    private TextLines(Path file, String kind, boolean continuation, BufferedReader reader) {
        this.file = file;
        this.kind = kind;
        this.continuation = continuation;
        this.reader = reader;
    }

    /**
     * Opens {@code file}; {@code kind} ("OBJ", "MTL") is used in messages, {@code continuation}
     * joins a line ending in a backslash with the next one.
     */
    public static TextLines open(Path file, String kind, boolean continuation) throws SceneException {
        if (Files.isDirectory(file)) {
            throw new SceneException(file, "is a directory, not an " + kind + " file");
        }
        InputStream in;
        try {
            dev.strahl.io.image.FileReads.note(file);
            in = Files.newInputStream(file);
        } catch (NoSuchFileException e) {
            throw new SceneException(file, "file not found", e);
        } catch (AccessDeniedException e) {
            throw new SceneException(file, "cannot read: permission denied", e);
        } catch (IOException | SecurityException e) {
            throw new SceneException(file, "cannot read: " + describe(e), e);
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
                    throw notText(file, kind, line, "NUL byte");
                }
            }
            CharsetDecoder utf8 = StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT);
            var reader = new BufferedReader(new InputStreamReader(buffered, utf8), 1 << 16);
            return new TextLines(file, kind, continuation, reader);
        } catch (IOException e) {
            closeQuietly(in);
            throw new SceneException(file, "cannot read: " + describe(e), e);
        } catch (SceneException e) {
            closeQuietly(in);
            throw e;
        }
    }

    /** The next logical line, or null at the end of the file. */
    public String next() throws SceneException {
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

    /** The line number (from 1) of the first physical line of the last logical line. */
    public int lineNumber() {
        return lineNumber;
    }

    @Override
    public void close() {
        closeQuietly(reader);
    }

    private String readPhysical() throws SceneException {
        try {
            String line = reader.readLine();
            if (line != null) {
                physicalLine++;
            }
            return line;
        } catch (CharacterCodingException e) {
            throw notText(file, kind, lineOfInvalidUtf8(file, physicalLine + 1), "invalid UTF-8");
        } catch (IOException e) {
            throw new SceneException(file, "cannot read after line " + physicalLine + ": " + describe(e), e);
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

    private static SceneException notText(Path file, String kind, int line, String why) {
        return new SceneException(file, line, "not a text " + kind + " file (" + why + ")");
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
    public static SceneException cannotRead(Path file, IOException e) {
        if (e instanceof NoSuchFileException) {
            return new SceneException(file, "file not found");
        }
        if (e instanceof AccessDeniedException) {
            return new SceneException(file, "permission denied");
        }
        return new SceneException(file, "cannot read: " + e.getMessage(), e);
    }
}
