package dev.strahl.io.ply;

import dev.strahl.io.text.FastDecimal;
import dev.strahl.io.text.LineCursor;
import dev.strahl.scene.SceneException;
import dev.strahl.io.ply.PlyHeader.Element;
import dev.strahl.io.ply.PlyHeader.Property;
import dev.strahl.io.ply.PlyHeader.Type;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * The body of an ASCII PLY file: one element instance per line, values separated by spaces or
 * tabs, read as tokens straight from the byte buffer (no String per value unless a number needs
 * the slow parser). A line with too few or too many values, a value that does not fit its type
 * and a file that ends early are errors at that line.
 */
final class PlyAscii {
    private static final int MAX_TOKEN = 256;

    private final PlyReader reader;
    private final PlyInput in;
    private final ByteBuffer buf;
    private final byte[] bytes;
    /** Line of the last byte looked at (1 + the newlines passed). */
    private int line;
    private int tokenStart;
    private int tokenEnd;
    private int tokenLine;
    /** Line of the current element instance, whose values must all be on it. */
    private int instanceLine;
    private String instanceElement;
    private long instanceIndex;
    /** A token read ahead that belongs to the next instance. */
    private boolean pending;

    PlyAscii(PlyReader reader, int headerLines) {
        this.reader = reader;
        this.in = reader.in;
        this.buf = in.buf;
        this.bytes = buf.array();
        this.line = headerLines + 1;
    }

    void read(PlyHeader header, PlyLayout layout) throws IOException, SceneException {
        for (Element e : header.elements) {
            if (e == layout.vertices) {
                vertices(layout);
            } else if (e == layout.faces) {
                faces(layout);
            } else {
                skip(e);
            }
        }
        if (pending || token()) {
            reader.asciiLine = tokenLine;
            if (tokenLine == instanceLine) {
                throw reader.error(instanceElement, instanceIndex, "more values on the line than the header declares");
            }
            reader.warn("line " + tokenLine + ": data after the last element ignored");
        }
    }

    private void vertices(PlyLayout layout) throws IOException, SceneException {
        Element e = layout.vertices;
        List<Property> props = e.properties();
        double[] values = new double[props.size()];
        int[] n = layout.normals != null ? layout.normals : new int[] {layout.x, layout.x, layout.x};
        for (int v = 0; v < (int) e.count(); v++) {
            begin(e, v);
            for (int k = 0; k < values.length; k++) {
                Property p = props.get(k);
                if (p.isList()) {
                    long count = listLength(e, v, p);
                    for (long i = 0; i < count; i++) {
                        value(e, v, p, p.type());
                    }
                } else {
                    values[k] = value(e, v, p, p.type());
                }
            }
            reader.vertex(v, values[layout.x], values[layout.y], values[layout.z], values[n[0]], values[n[1]], values[n[2]]);
        }
    }

    private void faces(PlyLayout layout) throws IOException, SceneException {
        Element e = layout.faces;
        List<Property> props = e.properties();
        for (int f = 0; f < (int) e.count(); f++) {
            begin(e, f);
            for (int k = 0; k < props.size(); k++) {
                Property p = props.get(k);
                if (!p.isList()) {
                    value(e, f, p, p.type());
                    continue;
                }
                long count = listLength(e, f, p);
                if (k != layout.indexList || !reader.polygon(f, count)) {
                    for (long i = 0; i < count; i++) {
                        value(e, f, p, p.type());
                    }
                    continue;
                }
                int first = reader.index(f, integer(e, f, p, p.type()));
                int prev = reader.index(f, integer(e, f, p, p.type()));
                for (long i = 2; i < count; i++) {
                    int cur = reader.index(f, integer(e, f, p, p.type()));
                    reader.triangle(first, prev, cur);
                    prev = cur;
                }
            }
        }
    }

    private void skip(Element e) throws IOException, SceneException {
        if (e.properties().isEmpty()) {
            return;                                   // instances without values take no text
        }
        for (long i = 0; i < e.count(); i++) {
            begin(e, i);
            for (Property p : e.properties()) {
                long count = p.isList() ? listLength(e, i, p) : 1;
                for (long j = 0; j < count; j++) {
                    value(e, i, p, p.type());
                }
            }
        }
    }

    // ---- one value at a time ---------------------------------------------------------------------

    /** Starts instance {@code index}: it must begin on a new line. */
    private void begin(Element e, long index) throws IOException, SceneException {
        if (!pending && !token()) {
            reader.asciiLine = line;
            throw reader.truncated(e.name(), index);
        }
        pending = true;
        reader.asciiLine = tokenLine;
        if (tokenLine == instanceLine) {
            throw reader.error(instanceElement, instanceIndex, "more values on the line than the header declares");
        }
        instanceLine = tokenLine;
        instanceElement = e.name();
        instanceIndex = index;
    }

    /** Reads the next token of the current instance, which must be on the instance's line. */
    private void next(Element e, long index, Property p) throws IOException, SceneException {
        if (pending) {
            pending = false;
            return;
        }
        if (!token()) {
            reader.asciiLine = line;
            throw reader.truncated(e.name(), index);
        }
        if (tokenLine != instanceLine) {
            reader.asciiLine = instanceLine;
            throw reader.error(e.name(), index, "the line ends before property '" + p.name() + "'");
        }
    }

    private long listLength(Element e, long index, Property p) throws IOException, SceneException {
        long n = integer(e, index, p, p.countType());
        if (n < 0) {
            throw reader.error(e.name(), index, "list '" + p.name() + "' has a negative length " + n);
        }
        return n;
    }

    private double value(Element e, long index, Property p, Type t) throws IOException, SceneException {
        if (t.integer) {
            return integer(e, index, p, t);
        }
        next(e, index, p);
        double d = FastDecimal.parse(bytes, tokenStart, tokenEnd);
        if (Double.isNaN(d)) {
            d = slowDecimal(e, index, p, t);
        }
        return t == Type.FLOAT ? (float) d : d;
    }

    private long integer(Element e, long index, Property p, Type t) throws IOException, SceneException {
        next(e, index, p);
        int i = tokenStart;
        boolean negative = bytes[i] == '-';
        if (negative || bytes[i] == '+') {
            i++;
        }
        long v = 0;
        if (i == tokenEnd || tokenEnd - i > 18) {
            throw bad(e, index, p, t);
        }
        for (; i < tokenEnd; i++) {
            int d = bytes[i] - '0';
            if (d < 0 || d > 9) {
                throw bad(e, index, p, t);
            }
            v = 10 * v + d;
        }
        v = negative ? -v : v;
        if (v < t.min() || v > t.max()) {
            throw reader.error(e.name(), index, "value " + v + " of property '" + p.name() + "' does not fit its type " + t.name);
        }
        return v;
    }

    /** Numbers the fast path does not take: exponents, long mantissas, nan and inf. */
    private double slowDecimal(Element e, long index, Property p, Type t) throws SceneException {
        String s = new String(bytes, tokenStart, tokenEnd - tokenStart, StandardCharsets.ISO_8859_1);
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (!(c >= '0' && c <= '9' || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E')) {
                return switch (s.toLowerCase(java.util.Locale.ROOT)) {
                    case "nan", "+nan", "-nan" -> Double.NaN;
                    case "inf", "+inf", "infinity", "+infinity" -> Double.POSITIVE_INFINITY;
                    case "-inf", "-infinity" -> Double.NEGATIVE_INFINITY;
                    default -> throw bad(e, index, p, t);
                };
            }
        }
        try {
            return Double.parseDouble(s);
        } catch (NumberFormatException x) {
            throw bad(e, index, p, t);
        }
    }

    private SceneException bad(Element e, long index, Property p, Type t) {
        String s = new String(bytes, tokenStart, tokenEnd - tokenStart, StandardCharsets.ISO_8859_1);
        return reader.error(e.name(), index, "bad value " + LineCursor.quote(s) + " for property '" + p.name()
                + "' of type " + t.name);
    }

    /**
     * Finds the next whitespace-separated token in the file and sets {@link #tokenStart},
     * {@link #tokenEnd} (indices into the buffer) and {@link #tokenLine}; false at the end.
     */
    private boolean token() throws IOException, SceneException {
        int p = buf.position();
        while (true) {
            if (p == buf.limit()) {
                buf.position(p);
                if (!in.fill(1)) {
                    return false;
                }
                p = buf.position();
            }
            byte b = bytes[p];
            if (b == '\n') {
                line++;
            } else if (!isSpace(b)) {
                break;
            }
            p++;
        }
        int start = p;
        while (true) {
            if (p == buf.limit()) {
                int length = p - start;
                buf.position(start);
                boolean more = in.fill(length + 1);
                start = buf.position();
                p = start + length;
                if (!more) {
                    break;
                }
            }
            if (isSpace(bytes[p]) || bytes[p] == '\n') {
                break;
            }
            if (++p - start > MAX_TOKEN) {
                reader.asciiLine = line;
                throw new SceneException(reader.file, line, "a value longer than " + MAX_TOKEN + " characters");
            }
        }
        tokenStart = start;
        tokenEnd = p;
        tokenLine = line;
        buf.position(p);
        return true;
    }

    private static boolean isSpace(byte b) {
        return b == ' ' || b == '\t' || b == '\r' || b == '\f' || b == 0x0B;
    }
}
