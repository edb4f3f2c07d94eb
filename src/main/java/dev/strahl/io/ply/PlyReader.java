package dev.strahl.io.ply;

import dev.strahl.io.text.InputErrors;
import dev.strahl.io.text.TextLines;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.io.ply.PlyHeader.Element;
import dev.strahl.io.ply.PlyHeader.Format;
import dev.strahl.io.ply.PlyHeader.Property;
import dev.strahl.io.ply.PlyHeader.Type;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Reads a PLY mesh (ASCII, binary little endian or binary big endian) into a {@link TriangleMesh}.
 *
 * <p>Used: the {@code vertex} element's {@code x y z} (any scalar type) and, if all three are
 * there, {@code nx ny nz} (normalised on read; a zero or non-finite normal means "no normal" for
 * that vertex); the {@code face} element's list {@code vertex_indices} (or {@code vertex_index}),
 * with integer count and index types of any size. Polygons are fan-triangulated (v0, vi, vi+1),
 * keeping the file's winding. Every other property and element is skipped by its declared type.
 *
 * <p>The file is read through one {@value #BUFFER}-byte buffer straight into the flat arrays of
 * the mesh: no object per vertex or face. Errors are {@link SceneException}s naming the header
 * line, the body line (ASCII) or the element, its index and the byte offset (binary): truncated
 * files, indices out of range, non-finite coordinates and malformed values are all refused.
 */
public final class PlyReader {
    /** This reader's errors, as io.text makes them. */
    static final InputErrors<SceneException> ERRORS = InputErrors.of(SceneException::new, SceneException::new);
    /** Buffer size; also the most a header may take. */
    static final int BUFFER = 1 << 20;
    private static final int MAX_ARRAY = Integer.MAX_VALUE - 8;

    /** The mesh and the remarks for the user (faces skipped, normals missing). */
    public record PlyModel(TriangleMesh mesh, List<String> warnings) {}

    final Path file;
    final PlyInput in;
    private final ByteBuffer buf;
    /** The body line of the value being read in an ASCII file; 0 in a binary one. */
    int asciiLine;

    private final int vertexCount;
    private final float[] positions;
    private final float[] normals;
    private int[] indices;
    private int indexCount;
    private long shortFaces;
    private int missingNormals;
    private final List<String> warnings = new ArrayList<>();

    private PlyReader(Path file, PlyInput in, PlyLayout layout) {
        this.file = file;
        this.in = in;
        this.buf = in.buf;
        this.vertexCount = (int) layout.vertices.count();
        this.positions = new float[3 * vertexCount];
        this.normals = layout.normals != null ? new float[3 * vertexCount] : null;
        this.indices = new int[layout.initialIndexCapacity()];
    }

    /** Reads the mesh in {@code file}. */
    public static PlyModel read(Path file) throws SceneException {
        if (Files.isDirectory(file)) {
            throw new SceneException(file, "is a directory, not a PLY file");
        }
        dev.strahl.files.FileReads.note(file);
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            PlyInput in = new PlyInput(channel, BUFFER);
            in.fill(BUFFER);
            PlyHeader header = PlyHeader.parse(file, in.buf);
            PlyLayout layout = PlyLayout.of(file, header, in.fileSize() - in.offset());
            return new PlyReader(file, in, layout).body(header, layout);
        } catch (IOException e) {
            throw TextLines.cannotRead(ERRORS, file, e);
        }
    }

    private PlyModel body(PlyHeader header, PlyLayout layout) throws IOException, SceneException {
        if (header.format == Format.ASCII) {
            new PlyAscii(this, header.lines).read(header, layout);
        } else {
            buf.order(header.format == Format.BINARY_BIG_ENDIAN ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN);
            for (Element e : header.elements) {
                if (e == layout.vertices) {
                    binaryVertices(layout);
                } else if (e == layout.faces) {
                    binaryFaces(layout);
                } else {
                    skipBinary(e);
                }
            }
            if (in.request(1)) {
                warnings.add(file + ": " + (in.fileSize() - in.offset()) + " bytes after the last element ignored");
            }
        }
        return model();
    }

    /** Adds a remark for the user. */
    void warn(String message) {
        warnings.add(file + ": " + message);
    }

    private PlyModel model() throws SceneException {
        if (shortFaces > 0) {
            warn("skipped " + shortFaces + " face" + (shortFaces == 1 ? "" : "s") + " with fewer than 3 vertices");
        }
        if (missingNormals > 0) {
            warn(missingNormals + " vertex normal" + (missingNormals == 1 ? " is" : "s are")
                    + " zero or not finite; those vertices are shaded with the face normal");
        }
        if (indexCount == 0) {
            throw new SceneException(file, "the mesh has no triangles");
        }
        int[] tri = indexCount == indices.length ? indices : Arrays.copyOf(indices, indexCount);
        indices = null;
        return new PlyModel(new TriangleMesh(positions, tri, normals), List.copyOf(warnings));
    }

    // ---- storing what was read (shared by both encodings) ---------------------------------------

    /** Stores vertex v: a position that is not a finite float is an error; a normal without length means none. */
    void vertex(int v, double x, double y, double z, double nx, double ny, double nz) throws SceneException {
        float fx = (float) x, fy = (float) y, fz = (float) z;
        if (!Float.isFinite(fx) || !Float.isFinite(fy) || !Float.isFinite(fz)) {
            throw error("vertex", v, "position (" + x + ", " + y + ", " + z + ") is not a finite float");
        }
        int o = 3 * v;
        positions[o] = fx;
        positions[o + 1] = fy;
        positions[o + 2] = fz;
        if (normals != null) {
            double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (len > 0 && Double.isFinite(len)) {
                normals[o] = (float) (nx / len);
                normals[o + 1] = (float) (ny / len);
                normals[o + 2] = (float) (nz / len);
            } else {
                normals[o] = normals[o + 1] = normals[o + 2] = Float.NaN;
                missingNormals++;
            }
        }
    }

    /** Checks a vertex index of face f. */
    int index(int f, long value) throws SceneException {
        if (value < 0 || value >= vertexCount) {
            throw error("face", f, "vertex index " + value + " is out of range (the file has " + vertexCount + " vertices)");
        }
        return (int) value;
    }

    /** Makes room for the triangles of a polygon of {@code n} vertices; false (and counted) if it has fewer than 3. */
    boolean polygon(int f, long n) throws SceneException {
        if (n < 3) {
            shortFaces++;
            return false;
        }
        long needed = indexCount + 3 * (n - 2);
        if (needed > indices.length) {
            // every index takes at least one byte: a list longer than the rest of the file is not grown into
            long left;
            try {
                left = in.fileSize() - in.offset();
            } catch (IOException e) {
                throw TextLines.cannotRead(ERRORS, file, e);
            }
            if (n > left) {
                throw truncated("face", f);
            }
            if (needed > MAX_ARRAY) {
                throw error("face", f, "too many triangles for one mesh (more than " + MAX_ARRAY / 3 + ")");
            }
            indices = Arrays.copyOf(indices, (int) Math.min(MAX_ARRAY, Math.max(needed, indices.length + (indices.length >> 1) + 16)));
        }
        return true;
    }

    void triangle(int a, int b, int c) {
        indices[indexCount] = a;
        indices[indexCount + 1] = b;
        indices[indexCount + 2] = c;
        indexCount += 3;
    }

    /** An error about instance {@code index} of an element, at the current body line (ASCII) or byte offset (binary). */
    SceneException error(String element, long index, String message) {
        return asciiLine > 0
                ? new SceneException(file, asciiLine, "element '" + element + "' " + index + ": " + message)
                : new SceneException(file, "element '" + element + "' " + index + " (byte " + in.offset() + "): " + message);
    }

    SceneException truncated(String element, long index) {
        return error(element, index, "the file ends here: it is truncated or its header promises more than it holds");
    }

    private void need(int n, String element, long index) throws IOException, SceneException {
        if (!in.request(n)) {
            throw truncated(element, index);
        }
    }

    // ---- binary bodies -------------------------------------------------------------------------

    private void binaryVertices(PlyLayout layout) throws IOException, SceneException {
        Element e = layout.vertices;
        List<Property> props = e.properties();
        int stride = e.binarySize();
        int[] offset = new int[props.size()];
        for (int k = 1; k < offset.length; k++) {
            offset[k] = stride < 0 ? 0 : offset[k - 1] + props.get(k - 1).type().size;
        }
        Type tx = props.get(layout.x).type(), ty = props.get(layout.y).type(), tz = props.get(layout.z).type();
        int ox = offset[layout.x], oy = offset[layout.y], oz = offset[layout.z];
        boolean withNormals = layout.normals != null;
        int[] nIdx = withNormals ? layout.normals : new int[] {0, 0, 0};
        Type tnx = props.get(nIdx[0]).type(), tny = props.get(nIdx[1]).type(), tnz = props.get(nIdx[2]).type();
        int onx = offset[nIdx[0]], ony = offset[nIdx[1]], onz = offset[nIdx[2]];
        double[] values = new double[props.size()];
        for (int v = 0; v < vertexCount; v++) {
            if (stride >= 0) {
                need(stride, "vertex", v);
                int base = buf.position();
                double nx = 0, ny = 0, nz = 0;
                if (withNormals) {
                    nx = value(tnx, base + onx);
                    ny = value(tny, base + ony);
                    nz = value(tnz, base + onz);
                }
                vertex(v, value(tx, base + ox), value(ty, base + oy), value(tz, base + oz), nx, ny, nz);
                buf.position(base + stride);
            } else {
                for (int k = 0; k < values.length; k++) {
                    Property p = props.get(k);
                    if (p.isList()) {
                        skip(listLength(p, "vertex", v) * p.type().size, "vertex", v);
                    } else {
                        need(p.type().size, "vertex", v);
                        values[k] = value(p.type(), buf.position());
                        buf.position(buf.position() + p.type().size);
                    }
                }
                vertex(v, values[layout.x], values[layout.y], values[layout.z],
                        values[nIdx[0]], values[nIdx[1]], values[nIdx[2]]);
            }
        }
    }

    private void binaryFaces(PlyLayout layout) throws IOException, SceneException {
        Element e = layout.faces;
        List<Property> props = e.properties();
        long count = e.count();
        for (long f = 0; f < count; f++) {
            int face = (int) f;
            for (int k = 0; k < props.size(); k++) {
                Property p = props.get(k);
                if (k != layout.indexList) {
                    if (p.isList()) {
                        skip(listLength(p, "face", f) * p.type().size, "face", f);
                    } else {
                        skip(p.type().size, "face", f);
                    }
                    continue;
                }
                long n = listLength(p, "face", f);
                Type t = p.type();
                int size = t.size;
                if (!polygon(face, n)) {
                    skip(n * size, "face", f);
                    continue;
                }
                need(2 * size, "face", f);
                int first = index(face, (long) value(t, buf.position()));
                int prev = index(face, (long) value(t, buf.position() + size));
                buf.position(buf.position() + 2 * size);
                for (long i = 2; i < n; i++) {
                    need(size, "face", f);
                    int cur = index(face, (long) value(t, buf.position()));
                    buf.position(buf.position() + size);
                    triangle(first, prev, cur);
                    prev = cur;
                }
            }
        }
    }

    private void skipBinary(Element e) throws IOException, SceneException {
        int size = e.binarySize();
        for (long i = 0; i < e.count(); i++) {
            if (size >= 0) {
                skip(size, e.name(), i);
                continue;
            }
            for (Property p : e.properties()) {
                skip(p.isList() ? listLength(p, e.name(), i) * p.type().size : p.type().size, e.name(), i);
            }
        }
    }

    /** Reads the length of a list; a negative one is an error. */
    private long listLength(Property p, String element, long index) throws IOException, SceneException {
        need(p.countType().size, element, index);
        long n = (long) value(p.countType(), buf.position());
        buf.position(buf.position() + p.countType().size);
        if (n < 0) {
            throw error(element, index, "list '" + p.name() + "' has a negative length " + n);
        }
        return n;
    }

    private void skip(long bytes, String element, long index) throws IOException, SceneException {
        while (bytes > 0) {
            if (!in.request(1)) {
                throw truncated(element, index);
            }
            int step = (int) Math.min(bytes, buf.remaining());
            buf.position(buf.position() + step);
            bytes -= step;
        }
    }

    /** The value of type t at buffer index {@code at}, in the buffer's byte order (exact in a double). */
    private double value(Type t, int at) {
        return switch (t) {
            case CHAR -> buf.get(at);
            case UCHAR -> buf.get(at) & 0xFF;
            case SHORT -> buf.getShort(at);
            case USHORT -> buf.getShort(at) & 0xFFFF;
            case INT -> buf.getInt(at);
            case UINT -> buf.getInt(at) & 0xFFFF_FFFFL;
            case FLOAT -> buf.getFloat(at);
            case DOUBLE -> buf.getDouble(at);
        };
    }
}
