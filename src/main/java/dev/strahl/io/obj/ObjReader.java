package dev.strahl.io.obj;

import dev.strahl.io.text.InputErrors;
import dev.strahl.io.text.HeapBudget;
import dev.strahl.scene.SceneException;
import dev.strahl.io.text.LineCursor;
import dev.strahl.io.text.TextLines;
import dev.strahl.scene.TriangleMesh;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Reads a Wavefront OBJ file (and the MTL files it names) into one {@link ObjModel}.
 *
 * <p>Understood: {@code v x y z [w]} (w and any further numbers, such as vertex colours, are
 * checked and ignored), {@code vn} (normalised on read; a zero-length one means "no normal"),
 * {@code vt} (u and v; w ignored; (0, 0) is the image's bottom-left corner), {@code f} with the index forms {@code v}, {@code v/t},
 * {@code v//n}, {@code v/t/n} and negative (relative) indices, {@code usemtl}, {@code mtllib}.
 * Polygons are fan-triangulated as (v0, vi, vi+1), keeping the file's winding, which decides the
 * geometric normal (DESIGN.md §3). A line ending in a backslash continues on the next line.
 * {@code g}, {@code o}, {@code s} and other grouping statements are accepted and have no effect;
 * lines, points, free-form geometry and unknown statements give one warning per keyword.
 *
 * <p>Output vertices are the distinct (position, texture coordinate, normal) triples that faces
 * use, in order of first use, so that OBJ normals and texture coordinates become per-vertex data
 * of the mesh and unused vertices disappear.
 *
 * <p>The parts: {@link TextLines} reads the file's lines, {@link LineCursor} splits each into
 * tokens, {@link ObjMaterials} keeps the {@code usemtl} slots and the MTL libraries, and a
 * {@link LongIntMap} finds each (position, normal) pair's output vertex.
 *
 * <p>Every problem with the input is a {@link SceneException} whose message starts with
 * {@code file:line:}; no other exception escapes for any file content.
 */
public final class ObjReader {
    /** This reader's errors, as io.text makes them. */
    static final InputErrors<SceneException> ERRORS = InputErrors.of(SceneException::new, SceneException::new);

    /**
     * Largest accepted |coordinate| of a position: products of four coordinates (squared lengths
     * of edge cross products) then stay far inside the double range.
     */
    static final double MAX_COORDINATE = 1e18;

    private final Path obj;
    private final TextLines<SceneException> lines;
    private final LineCursor<SceneException> cur;
    private final List<String> warnings = new ArrayList<>();
    private final Set<String> warnedKeywords = new HashSet<>();

    // OBJ data as read: positions and normals as float triples, texture coordinates only counted
    private float[] v = new float[3 * 1024];
    private int vCount;
    private float[] vn = new float[3 * 64];
    private int vnCount;
    private float[] vt = new float[2 * 64];
    private int vtCount;

    /** The mesh's vertices: the distinct index triples of the faces. */
    private final ObjVertices vertices = new ObjVertices();

    // Output triangles (output vertex indices) and the material slot of each (see ObjMaterials)
    private int[] tri = new int[3 * 1024];
    private int[] triSlot = new int[1024];
    private int triCount;
    private int[] face = new int[16];
    private int degenerateCount;
    private int firstDegenerateLine;

    private final ObjMaterials materials;

    private ObjReader(Path obj, TextLines<SceneException> lines) {
        this.obj = obj;
        this.lines = lines;
        this.cur = new LineCursor<>(obj, ERRORS);
        this.materials = new ObjMaterials(obj, warnings);
    }

    /** Reads {@code obj}; material libraries are resolved relative to its directory. */
    public static ObjModel read(Path obj) throws SceneException {
        // A file that is not UTF-8 is read again as Latin-1, its note first among the warnings.
        return TextLines.read(obj, ERRORS, "OBJ", true, new ArrayList<>(), (lines, notes) -> {
            ObjReader reader = new ObjReader(obj, lines);
            reader.warnings.addAll(notes);
            return reader.parse();
        });
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
                case "usemtl" -> {
                    String name = cur.rest();
                    materials.use(name, lines.byteKey(name), cur.lineNumber);
                }
                case "mtllib" -> materials.libraries(cur.rest(), cur.lineNumber);
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
        v = putTriple(v, vCount++, x, y, z);
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
        vn = putTriple(vn, vnCount++, x, y, z);
    }

    private void texcoord() throws SceneException {
        double u = coordinate("vt", "at least 1 number (u [v [w]])", 0);
        double vv = 0;
        for (int k = 1; cur.next(); k++) {
            double x = checkFinite(cur.number("vt"), "vt");
            if (k == 1) {
                vv = x;
            }
        }
        if (2 * vtCount + 2 > vt.length) {
            vt = grow(vt, 2 * vtCount + 2);
        }
        vt[2 * vtCount] = (float) u;
        vt[2 * vtCount + 1] = (float) vv;
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
        int slot = materials.faceSlot();
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
        int pa = 3 * vertices.position(a), pb = 3 * vertices.position(b), pc = 3 * vertices.position(c);
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
        int tex = ObjVertices.NONE;
        if (slash1 >= 0) {
            int tEnd = slash2 < 0 ? stop : slash2;
            if (tEnd > slash1 + 1) {
                tex = index(slash1 + 1, tEnd, vtCount, "texture", "texture coordinate", "texture coordinates");
            }
        }
        int nrm = ObjVertices.NONE;
        if (slash2 >= 0 && stop > slash2 + 1) {
            nrm = index(slash2 + 1, stop, vnCount, "normal", "normal", "normals");
        }
        return vertices.vertex(p, tex, nrm);
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
        List<MtlMaterial> used = new ArrayList<>();
        int[] slotMaterial = materials.resolve(used);
        int[] triangleMaterial = new int[triCount];
        for (int t = 0; t < triCount; t++) {
            triangleMaterial[t] = slotMaterial[triSlot[t]];
        }

        var mesh = new TriangleMesh(vertices.positions(v), Arrays.copyOf(tri, triCount * 3), vertices.normals(vn), vertices.uvs(vt));
        return new ObjModel(mesh, triangleMaterial, used, warnings);
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

    /** Stores (x, y, z) as floats at triple {@code index} of {@code a}, grown if needed; returns the array. */
    private static float[] putTriple(float[] a, int index, double x, double y, double z) {
        if (index * 3 + 3 > a.length) {
            a = grow(a, index * 3 + 3);
        }
        a[index * 3] = (float) x;
        a[index * 3 + 1] = (float) y;
        a[index * 3 + 2] = (float) z;
        return a;
    }
}

