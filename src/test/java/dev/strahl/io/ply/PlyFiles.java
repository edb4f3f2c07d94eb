package dev.strahl.io.ply;

import dev.strahl.io.ply.PlyHeader.Format;
import dev.strahl.io.ply.PlyHeader.Type;
import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Writes PLY files for tests, independently of the reader: elements with typed scalar and list
 * properties, in any of the three encodings, so that the same content can be compared across them.
 */
public final class PlyFiles {

    /** A property: a scalar when {@code countType} is null, else a list. */
    public record Prop(String name, Type type, Type countType) {
        public static Prop scalar(String name, Type type) {
            return new Prop(name, type, null);
        }

        public static Prop list(String name, Type countType, Type type) {
            return new Prop(name, type, countType);
        }
    }

    /** An element: its properties and, per instance, per property, the values (one for a scalar). */
    public static final class Elem {
        final String name;
        final List<Prop> props;
        final List<double[][]> rows = new ArrayList<>();

        Elem(String name, Prop... props) {
            this.name = name;
            this.props = List.of(props);
        }

        Elem row(double[]... values) {
            if (values.length != props.size()) {
                throw new IllegalArgumentException("one value array per property");
            }
            rows.add(values);
            return this;
        }
    }

    private PlyFiles() {}

    public static byte[] write(Format format, List<Elem> elements) {
        return write(format, elements, List.of("comment written by PlyFiles", "obj_info a test mesh"));
    }

    /** The file: header (with the given comment/obj_info lines after the format line), then the body. */
    public static byte[] write(Format format, List<Elem> elements, List<String> extraHeaderLines) {
        StringBuilder h = new StringBuilder("ply\nformat ").append(format.keyword).append(" 1.0\n");
        for (String line : extraHeaderLines) {
            h.append(line).append('\n');
        }
        for (Elem e : elements) {
            h.append("element ").append(e.name).append(' ').append(e.rows.size()).append('\n');
            for (Prop p : e.props) {
                h.append(p.countType == null ? "property " + p.type.name + " " + p.name
                        : "property list " + p.countType.name + " " + p.type.name + " " + p.name).append('\n');
            }
        }
        h.append("end_header\n");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(h.toString().getBytes(StandardCharsets.US_ASCII));
        for (Elem e : elements) {
            for (double[][] row : e.rows) {
                if (format == Format.ASCII) {
                    out.writeBytes(asciiRow(e, row).getBytes(StandardCharsets.US_ASCII));
                } else {
                    out.writeBytes(binaryRow(e, row, format == Format.BINARY_BIG_ENDIAN ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN));
                }
            }
        }
        return out.toByteArray();
    }

    private static String asciiRow(Elem e, double[][] row) {
        List<String> words = new ArrayList<>();
        for (int k = 0; k < row.length; k++) {
            Prop p = e.props.get(k);
            if (p.countType != null) {
                words.add(Long.toString(row[k].length));
            }
            for (double v : row[k]) {
                words.add(p.type.integer ? Long.toString((long) v) : Double.toString(v));
            }
        }
        return String.join(" ", words) + "\n";
    }

    private static byte[] binaryRow(Elem e, double[][] row, ByteOrder order) {
        ByteBuffer b = ByteBuffer.allocate(1 << 16).order(order);
        for (int k = 0; k < row.length; k++) {
            Prop p = e.props.get(k);
            if (p.countType != null) {
                put(b, p.countType, row[k].length);
            }
            for (double v : row[k]) {
                put(b, p.type, v);
            }
        }
        byte[] bytes = new byte[b.position()];
        b.flip().get(bytes);
        return bytes;
    }

    static void put(ByteBuffer b, Type t, double v) {
        switch (t) {
            case CHAR, UCHAR -> b.put((byte) (long) v);
            case SHORT, USHORT -> b.putShort((short) (long) v);
            case INT, UINT -> b.putInt((int) (long) v);
            case FLOAT -> b.putFloat((float) v);
            case DOUBLE -> b.putDouble(v);
        }
    }

    /**
     * A random mesh as PLY elements: {@code vertices} vertices (float positions in [-1, 1], with
     * normals if asked, and an extra {@code confidence} property), faces of 3 to 6 vertices.
     */
    public static List<Elem> randomMesh(long seed, int vertices, int faces, Type coordinate, Type count, Type index, boolean withNormals) {
        SplittableRandom rnd = new SplittableRandom(seed);
        List<Prop> vp = new ArrayList<>(List.of(Prop.scalar("x", coordinate), Prop.scalar("y", coordinate), Prop.scalar("z", coordinate)));
        if (withNormals) {
            vp.addAll(List.of(Prop.scalar("nx", Type.FLOAT), Prop.scalar("ny", Type.FLOAT), Prop.scalar("nz", Type.FLOAT)));
        }
        vp.add(Prop.scalar("confidence", Type.FLOAT));
        Elem v = new Elem("vertex", vp.toArray(new Prop[0]));
        for (int i = 0; i < vertices; i++) {
            double[][] row = new double[vp.size()][];
            for (int k = 0; k < row.length; k++) {
                row[k] = new double[] {(float) rnd.nextDouble(-1, 1)};
            }
            v.row(row);
        }
        Elem f = new Elem("face", Prop.list("vertex_indices", count, index), Prop.scalar("flags", Type.INT));
        for (int i = 0; i < faces; i++) {
            double[] idx = new double[3 + rnd.nextInt(4)];
            for (int k = 0; k < idx.length; k++) {
                idx[k] = rnd.nextInt(vertices);
            }
            f.row(idx, new double[] {rnd.nextInt(1000)});
        }
        return List.of(v, f);
    }
}
