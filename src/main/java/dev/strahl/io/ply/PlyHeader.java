package dev.strahl.io.ply;

import dev.strahl.io.text.LineCursor;
import dev.strahl.scene.SceneException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * The header of a PLY file (Turk 1994; the format as documented with the Stanford 3D Scanning
 * Repository): the format line, then {@code element NAME COUNT} lines each followed by its
 * {@code property TYPE NAME} or {@code property list COUNT_TYPE ITEM_TYPE NAME} lines, with
 * {@code comment} and {@code obj_info} lines anywhere, up to {@code end_header}. Lines end with
 * LF or CR LF. Every problem is a {@link SceneException} at the header line that shows it.
 */
public final class PlyHeader {

    /** How the body is stored. */
    public enum Format {
        ASCII("ascii"), BINARY_LITTLE_ENDIAN("binary_little_endian"), BINARY_BIG_ENDIAN("binary_big_endian");

        final String keyword;

        Format(String keyword) {
            this.keyword = keyword;
        }
    }

    /** The scalar types of PLY, under both their old and their sized names. */
    public enum Type {
        CHAR(1, true, "char", "int8"), UCHAR(1, true, "uchar", "uint8"), SHORT(2, true, "short", "int16"),
        USHORT(2, true, "ushort", "uint16"), INT(4, true, "int", "int32"), UINT(4, true, "uint", "uint32"),
        FLOAT(4, false, "float", "float32"), DOUBLE(8, false, "double", "float64");

        final int size;
        final boolean integer;
        final String name;
        final String sizedName;

        Type(int size, boolean integer, String name, String sizedName) {
            this.size = size;
            this.integer = integer;
            this.name = name;
            this.sizedName = sizedName;
        }

        static Type of(String word) {
            for (Type t : values()) {
                if (t.name.equals(word) || t.sizedName.equals(word)) {
                    return t;
                }
            }
            return null;
        }

        /** The smallest and largest value of an integer type. */
        long min() {
            return switch (this) {
                case CHAR -> Byte.MIN_VALUE;
                case SHORT -> Short.MIN_VALUE;
                case INT -> Integer.MIN_VALUE;
                default -> 0;
            };
        }

        long max() {
            return switch (this) {
                case CHAR -> Byte.MAX_VALUE;
                case UCHAR -> 0xFF;
                case SHORT -> Short.MAX_VALUE;
                case USHORT -> 0xFFFF;
                case INT -> Integer.MAX_VALUE;
                default -> 0xFFFF_FFFFL;
            };
        }
    }

    /**
     * One property of an element: a scalar of {@code type}, or (when {@code countType} is not
     * null) a list of {@code type} values preceded by its length.
     */
    record Property(String name, Type type, Type countType, int line) {
        boolean isList() {
            return countType != null;
        }
    }

    /** One element declaration: {@code count} instances, each holding the properties in order. */
    record Element(String name, long count, List<Property> properties, int line) {
        /** Bytes per instance in a binary body, or -1 if it holds a list (and so varies). */
        int binarySize() {
            int size = 0;
            for (Property p : properties) {
                if (p.isList()) {
                    return -1;
                }
                size += p.type.size;
            }
            return size;
        }

        /** The fewest bytes one instance can take in the given format. */
        long minimumBytes(Format format) {
            long size = 0;
            for (Property p : properties) {
                size += format == Format.ASCII ? 2 : (p.isList() ? p.countType.size : p.type.size);
            }
            return size;
        }

        int indexOf(String property) {
            for (int i = 0; i < properties.size(); i++) {
                if (properties.get(i).name.equals(property)) {
                    return i;
                }
            }
            return -1;
        }
    }

    final Format format;
    final List<Element> elements;
    /** The number of header lines, so that an ASCII body starts on line {@code lines + 1}. */
    final int lines;

    private PlyHeader(Format format, List<Element> elements, int lines) {
        this.format = format;
        this.elements = List.copyOf(elements);
        this.lines = lines;
    }

    /**
     * Parses the header at the start of {@code buf} (positioned at the file's first byte) and
     * leaves the buffer positioned at the first byte of the body.
     */
    static PlyHeader parse(Path file, ByteBuffer buf) throws SceneException {
        Format format = null;
        List<Element> elements = new ArrayList<>();
        Set<String> elementNames = new HashSet<>();
        List<Property> properties = null;
        Set<String> propertyNames = null;
        String elementName = null;
        long elementCount = 0;
        int elementLine = 0;
        int line = 0;
        while (true) {
            String text = nextLine(buf);
            line++;
            if (text == null) {
                if (line == 1) {
                    throw new SceneException(file, 1, "not a PLY file (empty)");
                }
                throw new SceneException(file, line, "the header has no 'end_header' line within its first "
                        + buf.capacity() / 1024 + " KiB");
            }
            if (line == 1) {
                if (!text.equals("ply")) {
                    throw new SceneException(file, 1, "not a PLY file (the first line must be 'ply')");
                }
                continue;
            }
            String[] w = words(text);
            if (w.length == 0) {
                throw new SceneException(file, line, "empty line in the PLY header");
            }
            switch (w[0]) {
                case "comment", "obj_info" -> { }
                case "format" -> {
                    if (format != null) {
                        throw new SceneException(file, line, "a second 'format' line");
                    }
                    format = format(file, line, w);
                }
                case "element" -> {
                    if (w.length != 3) {
                        throw new SceneException(file, line, "expected 'element NAME COUNT'");
                    }
                    if (!elementNames.add(w[1])) {
                        throw new SceneException(file, line, "element '" + w[1] + "' is declared twice");
                    }
                    if (elementName != null) {
                        elements.add(new Element(elementName, elementCount, properties, elementLine));
                    }
                    elementName = w[1];
                    elementCount = count(file, line, w[2], w[1]);
                    elementLine = line;
                    properties = new ArrayList<>();
                    propertyNames = new HashSet<>();
                }
                case "property" -> {
                    if (elementName == null) {
                        throw new SceneException(file, line, "'property' before any 'element'");
                    }
                    Property p = property(file, line, w);
                    if (!propertyNames.add(p.name)) {
                        throw new SceneException(file, line, "property '" + p.name + "' of element '" + elementName + "' is declared twice");
                    }
                    properties.add(p);
                }
                case "end_header" -> {
                    if (w.length != 1) {
                        throw new SceneException(file, line, "unexpected words after 'end_header'");
                    }
                    if (format == null) {
                        throw new SceneException(file, line, "the header has no 'format' line");
                    }
                    if (elementName != null) {
                        elements.add(new Element(elementName, elementCount, properties, elementLine));
                    }
                    return new PlyHeader(format, elements, line);
                }
                default -> throw new SceneException(file, line, "unknown PLY header keyword " + LineCursor.quote(w[0])
                        + " (expected format, element, property, comment, obj_info or end_header)");
            }
        }
    }

    /** The element of that name, or null. */
    Element element(String name) {
        for (Element e : elements) {
            if (e.name.equals(name)) {
                return e;
            }
        }
        return null;
    }

    private static Format format(Path file, int line, String[] w) throws SceneException {
        if (w.length != 3) {
            throw new SceneException(file, line, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
        }
        Format format = null;
        for (Format f : Format.values()) {
            if (f.keyword.equals(w[1])) {
                format = f;
            }
        }
        if (format == null) {
            throw new SceneException(file, line, "unknown PLY format " + LineCursor.quote(w[1])
                    + " (expected ascii, binary_little_endian or binary_big_endian)");
        }
        if (!w[2].equals("1.0")) {
            throw new SceneException(file, line, "unsupported PLY version " + LineCursor.quote(w[2]) + " (expected 1.0)");
        }
        return format;
    }

    private static long count(Path file, int line, String word, String element) throws SceneException {
        try {
            long n = Long.parseLong(word);
            if (n >= 0) {
                return n;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new SceneException(file, line, "bad count " + LineCursor.quote(word) + " for element '" + element
                + "' (expected a whole number >= 0)");
    }

    private static Property property(Path file, int line, String[] w) throws SceneException {
        if (w.length >= 2 && w[1].equals("list")) {
            if (w.length != 5) {
                throw new SceneException(file, line, "expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
            }
            Type count = type(file, line, w[2]);
            if (!count.integer) {
                throw new SceneException(file, line, "the count type of list '" + w[4] + "' must be an integer type, got " + w[2]);
            }
            return new Property(w[4], type(file, line, w[3]), count, line);
        }
        if (w.length != 3) {
            throw new SceneException(file, line, "expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME'");
        }
        return new Property(w[2], type(file, line, w[1]), null, line);
    }

    private static Type type(Path file, int line, String word) throws SceneException {
        Type t = Type.of(word);
        if (t == null) {
            throw new SceneException(file, line, "unknown PLY type " + LineCursor.quote(word)
                    + " (expected char, uchar, short, ushort, int, uint, float, double or int8 ... float64)");
        }
        return t;
    }

    private static String[] words(String text) {
        String trimmed = text.strip();
        if (trimmed.isEmpty()) {
            return new String[0];
        }
        return trimmed.split("[ \t]+");
    }

    /**
     * The next header line without its LF or CR LF, or null if the buffer holds no further LF.
     * Bytes are read as ISO-8859-1, so that a comment in any encoding cannot fail.
     */
    private static String nextLine(ByteBuffer buf) {
        int start = buf.position();
        for (int i = start; i < buf.limit(); i++) {
            if (buf.get(i) == '\n') {
                int end = i > start && buf.get(i - 1) == '\r' ? i - 1 : i;
                byte[] bytes = new byte[end - start];
                buf.get(start, bytes);
                buf.position(i + 1);
                return new String(bytes, StandardCharsets.ISO_8859_1);
            }
        }
        return null;
    }
}
