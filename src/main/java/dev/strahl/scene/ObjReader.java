package dev.strahl.scene;

import dev.strahl.geometry.TriangleMesh;
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
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Reads a Wavefront OBJ file (and the MTL files it names) into one {@link ObjModel}.
 *
 * <p>Understood: {@code v x y z [w]} (w and any further numbers, such as vertex colours, are
 * checked and ignored), {@code vn} (normalised on read; a zero-length one means "no normal"),
 * {@code vt} (checked, unused), {@code f} with the index forms {@code v}, {@code v/t},
 * {@code v//n}, {@code v/t/n} and negative (relative) indices, {@code usemtl}, {@code mtllib}.
 * Polygons are fan-triangulated as (v0, vi, vi+1), keeping the file's winding, which decides the
 * geometric normal (DESIGN.md §3). A line ending in a backslash continues on the next line.
 * {@code g}, {@code o}, {@code s} and other grouping statements are accepted and have no effect;
 * lines, points, free-form geometry and unknown statements give one warning per keyword.
 *
 * <p>Output vertices are the distinct (position, normal) pairs that faces use, in order of first
 * use, so that OBJ normals become per-vertex normals of the mesh and unused vertices disappear.
 *
 * <p>Every problem with the input is a {@link SceneException} whose message starts with
 * {@code file:line:}; no other exception escapes for any file content.
 */
final class ObjReader {

    private static final int VERTEX_NONE = -1;
    /**
     * Largest accepted |coordinate| of a position: products of four coordinates (squared lengths
     * of edge cross products) then stay far inside the double range.
     */
    static final double MAX_COORDINATE = 1e18;

    private final Path obj;
    private final TextLines lines;
    private final LineCursor cur;
    private final List<String> warnings = new ArrayList<>();
    private final Set<String> warnedKeywords = new HashSet<>();

    // OBJ data as read: positions and normals as float triples, texture coordinates only counted
    private float[] v = new float[3 * 1024];
    private int vCount;
    private float[] vn = new float[3 * 64];
    private int vnCount;
    private int vtCount;

    // Output vertices: the OBJ position and normal index (or VERTEX_NONE) of each distinct pair
    private final LongIntMap vertexIds = new LongIntMap();
    private int[] outPosition = new int[1024];
    private int[] outNormal = new int[1024];
    private int outCount;
    private boolean anyNormal;

    private int[] tri = new int[3 * 1024];
    private int[] triSlot = new int[1024];
    private int triCount;
    private int[] face = new int[16];
    private int degenerateCount;
    private int firstDegenerateLine;

    // Material slots: one per distinct usemtl name, slot 0 = "no usemtl yet"
    private final List<String> slotNames = new ArrayList<>(List.of(""));
    private final List<Integer> slotLines = new ArrayList<>(List.of(0));
    private final Map<String, Integer> slotByName = new HashMap<>();
    private final List<Integer> usedSlots = new ArrayList<>();
    private boolean[] slotUsed = new boolean[8];
    private int slot;

    private final Map<String, MtlMaterial> library = new HashMap<>();
    private final Set<Path> loadedLibraries = new HashSet<>();
    private boolean libraryMissing;

    private ObjReader(Path obj, TextLines lines) {
        this.obj = obj;
        this.lines = lines;
        this.cur = new LineCursor(obj);
    }

    /** Reads {@code obj}; material libraries are resolved relative to its directory. */
    static ObjModel read(Path obj) throws SceneException {
        try (TextLines lines = TextLines.open(obj, "OBJ", true)) {
            return new ObjReader(obj, lines).parse();
        }
    }

    private ObjModel parse() throws SceneException {
        for (String line; (line = lines.next()) != null; ) {
            cur.reset(line, lines.lineNumber());
            if (cur.next()) {
                statement();
            }
        }
        return build();
    }

    private void statement() throws SceneException {
        int length = cur.stop - cur.start;
        char c0 = cur.line.charAt(cur.start);
        char c1 = length == 2 ? cur.line.charAt(cur.start + 1) : 0;
        // The three statements that make up nearly all of a big file are recognised without a String
        if (length == 1 && c0 == 'v') {
            vertex();
        } else if (length == 1 && c0 == 'f') {
            face();
        } else if (length == 2 && c0 == 'v' && c1 == 'n') {
            normal();
        } else if (length == 2 && c0 == 'v' && c1 == 't') {
            texcoord();
        } else {
            String keyword = cur.token();
            switch (keyword) {
                case "usemtl" -> useMaterial(cur.rest());
                case "mtllib" -> materialLibraries(cur.rest());
                case "g", "o", "s", "mg", "lod", "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj" -> { }
                case "l" -> warnOnce(keyword, "line element 'l' is not rendered");
                case "p" -> warnOnce(keyword, "point element 'p' is not rendered");
                case "vp", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv",
                        "sp", "end", "con", "ctech", "stech" ->
                        warnOnce(keyword, "free-form statement '" + keyword + "' is not supported");
                default -> warnOnce(keyword, "unknown statement " + LineCursor.quote(keyword));
            }
        }
    }

    private void warnOnce(String keyword, String what) {
        if (warnedKeywords.add(keyword)) {
            warnings.add(obj + ": " + what + " (line " + cur.lineNumber + "): ignored");
        }
    }

    // ---- vertex data ---------------------------------------------------------------------

    private void vertex() throws SceneException {
        double x = position(0);
        double y = position(1);
        double z = position(2);
        while (cur.next()) {
            cur.number("v"); // w, or r g b of the vertex-colour extension: checked, not used
        }
        if (vCount * 3 + 3 > v.length) {
            v = grow(v, vCount * 3 + 3);
        }
        v[vCount * 3] = (float) x;
        v[vCount * 3 + 1] = (float) y;
        v[vCount * 3 + 2] = (float) z;
        vCount++;
    }

    private void normal() throws SceneException {
        double x = coordinate("vn", "3 numbers (x y z)", 0);
        double y = coordinate("vn", "3 numbers (x y z)", 1);
        double z = coordinate("vn", "3 numbers (x y z)", 2);
        while (cur.next()) {
            cur.number("vn");
        }
        // Scale by the largest component first so that the squared length cannot overflow
        double m = Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
        if (m > 0) {
            x /= m;
            y /= m;
            z /= m;
            double length = Math.sqrt(x * x + y * y + z * z);
            x /= length;
            y /= length;
            z /= length;
        } else {
            x = y = z = Double.NaN; // a zero vector names no direction: the vertex gets no normal
        }
        if (vnCount * 3 + 3 > vn.length) {
            vn = grow(vn, vnCount * 3 + 3);
        }
        vn[vnCount * 3] = (float) x;
        vn[vnCount * 3 + 1] = (float) y;
        vn[vnCount * 3 + 2] = (float) z;
        vnCount++;
    }

    private void texcoord() throws SceneException {
        coordinate("vt", "at least 1 number (u [v [w]])", 0);
        while (cur.next()) {
            checkFinite(cur.number("vt"), "vt");
        }
        vtCount++;
    }

    private double position(int index) throws SceneException {
        double value = coordinate("v", "3 numbers (x y z)", index);
        if (Math.abs(value) > MAX_COORDINATE) {
            throw cur.error("coordinate " + LineCursor.quote(cur.token()) + " in 'v' is too large (the limit is 1e18 in magnitude)");
        }
        return value;
    }

    /** The next number of a v/vn/vt line, which must exist, be finite and fit a float. */
    private double coordinate(String keyword, String expected, int index) throws SceneException {
        if (!cur.next()) {
            throw cur.error("'" + keyword + "' needs " + expected + ", got " + index);
        }
        return checkFinite(cur.number(keyword), keyword);
    }

    private double checkFinite(double value, String keyword) throws SceneException {
        if (!Double.isFinite(value)) {
            throw cur.error("coordinate " + LineCursor.quote(cur.token()) + " in '" + keyword + "' is not finite");
        }
        if (Math.abs(value) > Float.MAX_VALUE) {
            throw cur.error("coordinate " + LineCursor.quote(cur.token()) + " in '" + keyword + "' is too large for a float");
        }
        return value;
    }

    // ---- faces ---------------------------------------------------------------------------

    private void face() throws SceneException {
        int n = 0;
        while (cur.next()) {
            if (n == face.length) {
                face = grow(face, n + 1);
            }
            face[n++] = faceVertex();
        }
        if (n < 3) {
            throw cur.error("face with " + n + (n == 1 ? " vertex" : " vertices") + " (needs at least 3)");
        }
        if (!slotUsed[slot]) {
            slotUsed[slot] = true;
            usedSlots.add(slot);
        }
        int newCount = triCount + n - 2;
        if ((long) newCount * 3 > Integer.MAX_VALUE - 16) {
            throw cur.error("too many triangles for one mesh");
        }
        if (newCount * 3 > tri.length) {
            String tooMany = HeapBudget.tooMany(newCount);
            if (tooMany != null) {
                throw cur.error(tooMany);
            }
            tri = grow(tri, newCount * 3);
        }
        if (newCount > triSlot.length) {
            triSlot = grow(triSlot, newCount);
        }
        // Fan (v0, vi, vi+1): keeps the winding of the polygon, hence its geometric normal
        for (int i = 1; i + 1 < n; i++) {
            if (isDegenerate(face[0], face[i], face[i + 1])) {
                if (degenerateCount++ == 0) {
                    firstDegenerateLine = cur.lineNumber;
                }
                continue;
            }
            tri[triCount * 3] = face[0];
            tri[triCount * 3 + 1] = face[i];
            tri[triCount * 3 + 2] = face[i + 1];
            triSlot[triCount] = slot;
            triCount++;
        }
    }

    /**
     * Whether the triangle of three output vertices has zero area: cross(v1 − v0, v2 − v0) = 0
     * with the float positions subtracted in double, the test the geometry uses.
     */
    private boolean isDegenerate(int a, int b, int c) {
        int pa = 3 * outPosition[a], pb = 3 * outPosition[b], pc = 3 * outPosition[c];
        double e1x = (double) v[pb] - v[pa], e1y = (double) v[pb + 1] - v[pa + 1], e1z = (double) v[pb + 2] - v[pa + 2];
        double e2x = (double) v[pc] - v[pa], e2y = (double) v[pc + 1] - v[pa + 1], e2z = (double) v[pc + 2] - v[pa + 2];
        double cx = e1y * e2z - e1z * e2y, cy = e1z * e2x - e1x * e2z, cz = e1x * e2y - e1y * e2x;
        return cx * cx + cy * cy + cz * cz == 0;
    }

    /** Parses the current token as v, v/t, v//n or v/t/n and returns the output vertex. */
    private int faceVertex() throws SceneException {
        String s = cur.line;
        int start = cur.start;
        int stop = cur.stop;
        int slash1 = indexOf(s, '/', start, stop);
        int slash2 = slash1 < 0 ? -1 : indexOf(s, '/', slash1 + 1, stop);
        int vEnd = slash1 < 0 ? stop : slash1;
        if (vEnd == start || (slash2 >= 0 && indexOf(s, '/', slash2 + 1, stop) >= 0)) {
            throw cur.error("bad face vertex " + LineCursor.quote(cur.token()) + ": expected v, v/t, v//n or v/t/n");
        }
        int p = index(start, vEnd, vCount, "vertex", "vertex", "vertices");
        if (slash1 >= 0) {
            int tEnd = slash2 < 0 ? stop : slash2;
            if (tEnd > slash1 + 1) {
                index(slash1 + 1, tEnd, vtCount, "texture", "texture coordinate", "texture coordinates");
            }
        }
        int nrm = VERTEX_NONE;
        if (slash2 >= 0 && stop > slash2 + 1) {
            nrm = index(slash2 + 1, stop, vnCount, "normal", "normal", "normals");
        }
        long key = ((long) p << 32) | (nrm + 1L);
        int id = vertexIds.putIfAbsent(key, outCount);
        if (id >= 0) {
            return id;
        }
        if (outCount == outPosition.length) {
            outPosition = grow(outPosition, outCount + 1);
            outNormal = grow(outNormal, outCount + 1);
        }
        outPosition[outCount] = p;
        outNormal[outCount] = nrm;
        anyNormal |= nrm != VERTEX_NONE;
        return outCount++;
    }

    /**
     * A 1-based (or, if negative, relative to the end) OBJ index in {@code [from, to)} of the line,
     * checked against the {@code count} elements defined so far; returns it 0-based.
     */
    private int index(int from, int to, int count, String what, String one, String many) throws SceneException {
        String s = cur.line;
        int i = from;
        boolean negative = s.charAt(i) == '-';
        if (negative || s.charAt(i) == '+') {
            i++;
        }
        if (i == to) {
            throw cur.error("bad " + what + " index " + LineCursor.quote(s.substring(from, to)) + " in 'f'");
        }
        long value = 0;
        for (; i < to; i++) {
            char c = s.charAt(i);
            if (c < '0' || c > '9') {
                throw cur.error("bad " + what + " index " + LineCursor.quote(s.substring(from, to)) + " in 'f'");
            }
            value = Math.min(value * 10 + (c - '0'), 1L << 40); // saturates far above any count
        }
        if (value == 0) {
            throw cur.error(what + " index " + LineCursor.quote(s.substring(from, to)) + " is invalid (OBJ indices start at 1)");
        }
        if (value > count) {
            throw cur.error(what + " index " + LineCursor.abbreviate(s.substring(from, to)) + " out of range (" + count + " "
                    + (count == 1 ? one : many) + " defined so far)");
        }
        return (int) (negative ? count - value : value - 1);
    }

    private static int indexOf(String s, char c, int from, int to) {
        int i = s.indexOf(c, from);
        return i >= 0 && i < to ? i : -1;
    }

    // ---- materials -----------------------------------------------------------------------

    private void useMaterial(String name) {
        Integer existing = slotByName.get(name);
        if (existing != null) {
            slot = existing;
            return;
        }
        slot = slotNames.size();
        slotNames.add(name);
        slotLines.add(cur.lineNumber);
        slotByName.put(name, slot);
        if (slot == slotUsed.length) {
            slotUsed = Arrays.copyOf(slotUsed, slot * 2);
        }
    }

    /**
     * {@code mtllib a.mtl b.mtl ...}; a name containing spaces is taken whole when the
     * space-separated parts are not all existing files but the whole rest of the line is one.
     */
    private void materialLibraries(String rest) throws SceneException {
        if (rest.isEmpty()) {
            warnings.add(obj + ": mtllib without a file name (line " + cur.lineNumber + "): ignored");
            return;
        }
        List<String> names = new ArrayList<>();
        LineCursor split = new LineCursor(obj);
        split.reset(rest, cur.lineNumber);
        while (split.next()) {
            names.add(split.token());
        }
        if (names.size() > 1 && !names.stream().allMatch(this::isLibraryFile) && isLibraryFile(rest)) {
            names = List.of(rest);
        }
        for (String name : names) {
            loadLibrary(name);
        }
    }

    private boolean isLibraryFile(String name) {
        try {
            return Files.isRegularFile(obj.resolveSibling(name));
        } catch (InvalidPathException | SecurityException e) {
            return false;
        }
    }

    private void loadLibrary(String name) throws SceneException {
        String where = obj + ": material library " + LineCursor.quote(name) + " (line " + cur.lineNumber + ")";
        String consequence = ": its materials are replaced by the default grey diffuse";
        Path path;
        try {
            path = obj.resolveSibling(name);
        } catch (InvalidPathException e) {
            warnings.add(where + " is not a valid file name" + consequence);
            libraryMissing = true;
            return;
        }
        if (!loadedLibraries.add(path.toAbsolutePath().normalize())) {
            return;
        }
        if (!Files.isRegularFile(path)) {
            warnings.add(where + " not found at " + path + consequence);
            libraryMissing = true;
            return;
        }
        if (!Files.isReadable(path)) {
            warnings.add(where + " is not readable" + consequence);
            libraryMissing = true;
            return;
        }
        // A library that exists but is malformed is an error, reported at its own file:line
        for (MtlMaterial m : MtlReader.read(path, warnings).values()) {
            if (library.putIfAbsent(m.name(), m) != null) {
                warnings.add(path + ": material '" + m.name() + "' is already defined by an earlier material library: "
                        + "keeping the first definition");
            }
        }
    }

    // ---- result --------------------------------------------------------------------------

    private ObjModel build() throws SceneException {
        if (triCount == 0) {
            throw new SceneException(obj, degenerateCount == 0 ? "no faces: the file holds no geometry"
                    : "no geometry: all " + degenerateCount + " triangles have zero area");
        }
        String tooMany = HeapBudget.tooMany(triCount);
        if (tooMany != null) {
            throw new SceneException(obj, tooMany.replace(" so far", ""));
        }
        if (degenerateCount > 0) {
            warnings.add(obj + ": skipped " + degenerateCount + " degenerate triangle" + (degenerateCount == 1 ? "" : "s")
                    + " (zero area), the first at line " + firstDegenerateLine);
        }
        MtlMaterial fallback = MtlMaterial.defaultMaterial();
        List<MtlMaterial> materials = new ArrayList<>();
        Map<MtlMaterial, Integer> materialIndex = new IdentityHashMap<>();
        int[] slotMaterial = new int[slotNames.size()];
        for (int s : usedSlots) {
            MtlMaterial m = s == 0 ? fallback : library.get(slotNames.get(s));
            if (m == null) {
                m = fallback;
                // After a missing library its warning already explains every unknown name
                if (!libraryMissing) {
                    warnings.add(obj + ": unknown material " + LineCursor.quote(slotNames.get(s)) + " (line "
                            + slotLines.get(s) + "): using the default grey diffuse");
                }
            }
            slotMaterial[s] = materialIndex.computeIfAbsent(m, k -> {
                materials.add(k);
                return materials.size() - 1;
            });
        }
        int[] triangleMaterial = new int[triCount];
        for (int t = 0; t < triCount; t++) {
            triangleMaterial[t] = slotMaterial[triSlot[t]];
        }

        float[] positions = new float[outCount * 3];
        float[] normals = anyNormal ? new float[outCount * 3] : null;
        for (int i = 0; i < outCount; i++) {
            System.arraycopy(v, outPosition[i] * 3, positions, i * 3, 3);
            if (normals == null) {
                continue;
            }
            if (outNormal[i] == VERTEX_NONE) {
                Arrays.fill(normals, i * 3, i * 3 + 3, Float.NaN);
            } else {
                System.arraycopy(vn, outNormal[i] * 3, normals, i * 3, 3);
            }
        }
        var mesh = new TriangleMesh(positions, Arrays.copyOf(tri, triCount * 3), normals);
        return new ObjModel(mesh, triangleMaterial, materials, warnings);
    }

    // ---- helpers -------------------------------------------------------------------------

    private static int newCapacity(int length, int needed) {
        long grown = Math.max((long) needed, length + (length >> 1) + 16L);
        return (int) Math.min(grown, Integer.MAX_VALUE - 16);
    }

    private static int[] grow(int[] a, int needed) {
        return Arrays.copyOf(a, newCapacity(a.length, needed));
    }

    private static float[] grow(float[] a, int needed) {
        return Arrays.copyOf(a, newCapacity(a.length, needed));
    }

    /**
     * The lines of a UTF-8 text file, with the checks both OBJ and MTL need: a file that is not
     * text (NUL bytes near the start, invalid UTF-8 anywhere) or cannot be read is a
     * {@link SceneException} at the line where that shows. A leading byte order mark is dropped.
     */
    static final class TextLines implements AutoCloseable {
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
        static TextLines open(Path file, String kind, boolean continuation) throws SceneException {
            if (Files.isDirectory(file)) {
                throw new SceneException(file, "is a directory, not an " + kind + " file");
            }
            InputStream in;
            try {
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
        String next() throws SceneException {
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
        int lineNumber() {
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
        static int lineOfInvalidUtf8(Path file, int fallback) {
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
    }

    /**
     * A hand-written tokeniser over one line (no regex, no split): whitespace-separated tokens
     * up to a {@code #} comment, addressed by {@link #start}/{@link #stop} without copying.
     */
    static final class LineCursor {
        private static final int QUOTE_MAX = 40;
        private static final double[] POW10 = {
            1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
            1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22
        };

        private final Path file;
        String line = "";
        int lineNumber;
        int start;
        int stop;
        private int pos;
        private int end;

        LineCursor(Path file) {
            this.file = file;
        }

        void reset(String line, int lineNumber) {
            this.line = line;
            this.lineNumber = lineNumber;
            int hash = line.indexOf('#');
            end = hash < 0 ? line.length() : hash;
            pos = 0;
            start = stop = 0;
        }

        /** Moves to the next token; false at the end of the line (or at a comment). */
        boolean next() {
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

        String token() {
            return line.substring(start, stop);
        }

        /** Everything after the current token up to the comment, without surrounding whitespace. */
        String rest() {
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
        double number(String keyword) throws SceneException {
            double value = parseDecimal(line, start, stop);
            if (!Double.isNaN(value)) {
                return value;
            }
            try {
                return Double.parseDouble(token());
            } catch (NumberFormatException e) {
                throw error("bad number " + quote(token()) + " in " + quote(keyword));
            }
        }

        SceneException error(String message) {
            return new SceneException(file, lineNumber, message);
        }

        static boolean isSpace(char c) {
            return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\u000B';
        }

        /** {@code 's'}, shortened if long, for messages about arbitrary input. */
        static String quote(String s) {
            return "'" + abbreviate(s) + "'";
        }

        static String abbreviate(String s) {
            return s.length() <= QUOTE_MAX ? s : s.substring(0, QUOTE_MAX) + "...";
        }

        /**
         * Fast path for plain decimals ([+-]digits[.digits], at most 15 significant digits and 22
         * decimals): the digits as an exact integer divided by an exact power of ten is one
         * correctly rounded IEEE operation, so the result equals {@link Double#parseDouble}
         * (Clinger 1990). Returns NaN for anything else, which the caller hands to parseDouble.
         */
        static double parseDecimal(String s, int from, int to) {
            int i = from;
            boolean negative = false;
            if (i < to && (s.charAt(i) == '-' || s.charAt(i) == '+')) {
                negative = s.charAt(i) == '-';
                i++;
            }
            long mantissa = 0;
            int significant = 0;
            int decimals = 0;
            boolean dot = false;
            boolean digit = false;
            for (; i < to; i++) {
                char c = s.charAt(i);
                if (c >= '0' && c <= '9') {
                    digit = true;
                    decimals += dot ? 1 : 0;
                    if (mantissa == 0 && c == '0') {
                        continue;
                    }
                    if (++significant > 15) {
                        return Double.NaN;
                    }
                    mantissa = mantissa * 10 + (c - '0');
                } else if (c == '.' && !dot) {
                    dot = true;
                } else {
                    return Double.NaN;
                }
            }
            if (!digit || decimals >= POW10.length) {
                return Double.NaN;
            }
            double value = mantissa / POW10[decimals];
            return negative ? -value : value;
        }
    }

    /** Open-addressing map from non-negative long keys to int values, without boxing. */
    static final class LongIntMap {
        private static final long EMPTY = -1;

        private long[] keys;
        private int[] values;
        private int size;
        private int shift;

        LongIntMap() {
            allocate(10);
        }

        /** The value stored for {@code key}; if there is none, stores {@code value} and returns -1. */
        int putIfAbsent(long key, int value) {
            int mask = keys.length - 1;
            for (int i = slot(key); ; i = (i + 1) & mask) {
                long k = keys[i];
                if (k == key) {
                    return values[i];
                }
                if (k == EMPTY) {
                    keys[i] = key;
                    values[i] = value;
                    if (++size > keys.length >> 1) {
                        rehash();
                    }
                    return -1;
                }
            }
        }

        private int slot(long key) {
            return (int) ((key * 0x9E3779B97F4A7C15L) >>> shift); // Fibonacci hashing
        }

        private void allocate(int bits) {
            keys = new long[1 << bits];
            values = new int[1 << bits];
            Arrays.fill(keys, EMPTY);
            shift = 64 - bits;
        }

        private void rehash() {
            long[] oldKeys = keys;
            int[] oldValues = values;
            allocate(65 - shift);
            int mask = keys.length - 1;
            for (int j = 0; j < oldKeys.length; j++) {
                if (oldKeys[j] != EMPTY) {
                    int i = slot(oldKeys[j]);
                    while (keys[i] != EMPTY) {
                        i = (i + 1) & mask;
                    }
                    keys[i] = oldKeys[j];
                    values[i] = oldValues[j];
                }
            }
        }
    }
}
