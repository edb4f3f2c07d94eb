package dev.strahl.io.gltf;

import dev.strahl.codec.ImageLimits;
import dev.strahl.scene.SceneException;
import java.nio.ByteBuffer;
import java.util.List;

/**
 * Reads glTF accessors into flat arrays: every component type (BYTE, UNSIGNED_BYTE, SHORT,
 * UNSIGNED_SHORT, UNSIGNED_INT, FLOAT), normalised integers mapped to [0, 1] or [−1, 1] as the
 * specification's §3.11 says, interleaved views ({@code byteStride}), and sparse accessors
 * (substitutions over the view's data, or over zeros without one). {@code min}/{@code max} are
 * not read. Every offset is checked against its buffer view before a byte is read.
 */
final class Accessors {
    static final int BYTE = 5120;
    static final int UNSIGNED_BYTE = 5121;
    static final int SHORT = 5122;
    static final int UNSIGNED_SHORT = 5123;
    static final int UNSIGNED_INT = 5125;
    static final int FLOAT = 5126;

    private final GltfDocument doc;

    Accessors(GltfDocument doc) {
        this.doc = doc;
    }

    /** The accessor at {@code indexNode} as floats, {@code components} per element (its type must match). */
    float[] floats(GltfJson indexNode, int components, String what) throws SceneException {
        GltfJson a = doc.element("accessors", indexNode);
        int n = components(a);
        if (n != components) {
            throw a.error(what + " must be of type " + typeName(components) + ", got " + a.require("type").quoted());
        }
        int type = componentType(a);
        if (type == UNSIGNED_INT && a.bool("normalized", false)) {
            throw a.error("normalized UNSIGNED_INT is not allowed");
        }
        if (type != FLOAT && !a.bool("normalized", false) && !what.equals("TEXCOORD_0")) {
            doc.noteOnce("integer " + what + " accessors read as plain numbers (not normalised)");
        }
        double[] v = read(a, n, type, a.bool("normalized", false));
        float[] out = new float[v.length];
        for (int i = 0; i < v.length; i++) {
            out[i] = (float) v[i];
        }
        return out;
    }

    /** An index accessor (SCALAR, UNSIGNED_BYTE/SHORT/INT) as ints; each index is checked below {@code vertexCount}. */
    int[] indices(GltfJson indexNode, int vertexCount) throws SceneException {
        GltfJson a = doc.element("accessors", indexNode);
        if (components(a) != 1) {
            throw a.error("indices must be of type SCALAR, got " + a.require("type").quoted());
        }
        int type = componentType(a);
        if (type != UNSIGNED_BYTE && type != UNSIGNED_SHORT && type != UNSIGNED_INT) {
            throw a.get("componentType").error("indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, got " + type);
        }
        double[] v = read(a, 1, type, false);
        int[] out = new int[v.length];
        for (int i = 0; i < v.length; i++) {
            if (v[i] >= vertexCount) {
                throw a.error("index " + (long) v[i] + " at element " + i + " is past the vertex count " + vertexCount);
            }
            out[i] = (int) v[i];
        }
        return out;
    }

    /** The number of elements of the accessor at {@code indexNode}. */
    int count(GltfJson indexNode) throws SceneException {
        return doc.element("accessors", indexNode).require("count").integer(1, Integer.MAX_VALUE);
    }

    private double[] read(GltfJson a, int n, int type, boolean normalized) throws SceneException {
        int count = a.require("count").integer(1, Integer.MAX_VALUE);
        int size = size(type);
        int element = n * size;
        ByteBuffer data = null;
        int view = -1;
        int stride = element;
        long offset = 0;
        if (a.has("bufferView")) {           // the view must hold every element before a value is allocated
            view = a.get("bufferView").index(doc.root.array("bufferViews").size());
            data = doc.bufferView(view);
            stride = doc.byteStride(view);
            if (stride == 0) {
                stride = element;
            } else if (stride < element) {
                throw a.error("byteStride " + stride + " of bufferView " + view + " is smaller than an element (" + element + " bytes)");
            }
            offset = a.integer("byteOffset", 0, 0, Integer.MAX_VALUE);
            if (offset % size != 0) {
                throw a.error("byteOffset " + offset + " is not a multiple of the component size " + size);
            }
            long end = offset + (long) (count - 1) * stride + element;
            if (end > data.capacity()) {
                throw a.error("byteOffset + count x stride past the end of bufferView " + view + ": count " + count + " of " + element
                        + "-byte elements " + stride + " bytes apart from byte " + offset + " end at byte " + end + ", the view has "
                        + data.capacity());
            }
        }
        checkHeap(a, count, n);
        double[] out = new double[count * n];
        if (data != null) {
            for (int i = 0; i < count; i++) {
                int base = (int) (offset + (long) i * stride);
                for (int c = 0; c < n; c++) {
                    out[i * n + c] = component(data, base + c * size, type, normalized);
                }
            }
        }
        if (a.has("sparse")) {
            sparse(a, a.get("sparse"), count, n, type, normalized, out);
        }
        return out;
    }

    /**
     * An accessor's values are read as doubles and then kept as floats or ints: 12 bytes per value
     * while it is read. An accessor without a buffer view (zeros, or a sparse one over zeros) may
     * claim any count in a few bytes of JSON, so the claim is checked against the heap first.
     */
    private static void checkHeap(GltfJson a, int count, int n) throws SceneException {
        if ((long) count * n > ImageLimits.MAX_ARRAY) {
            throw a.error("count " + count + " of " + n + " components each is more values than one array holds");
        }
        String shortfall = ImageLimits.heapShortfall(12L * count * n);
        if (shortfall != null) {
            throw a.error("count " + count + " (" + n + " components each" + (a.has("bufferView") ? "" : ", no bufferView: zeros") + ") "
                    + shortfall);
        }
    }

    private void sparse(GltfJson a, GltfJson s, int count, int n, int type, boolean normalized, double[] out) throws SceneException {
        int k = s.require("count").integer(1, count);
        GltfJson idx = s.require("indices");
        int idxType = idx.require("componentType").integer(0, Integer.MAX_VALUE);
        if (idxType != UNSIGNED_BYTE && idxType != UNSIGNED_SHORT && idxType != UNSIGNED_INT) {
            throw idx.get("componentType").error("sparse indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, got " + idxType);
        }
        ByteBuffer ib = packed(idx, k, size(idxType));
        GltfJson vals = s.require("values");
        ByteBuffer vb = packed(vals, k, n * size(type));
        long previous = -1;
        for (int j = 0; j < k; j++) {
            long target = (long) component(ib, j * size(idxType), idxType, false);
            if (target >= count) {
                throw idx.error("sparse index " + target + " is past the accessor's count " + count);
            }
            if (target <= previous) {
                throw idx.error("sparse indices must increase strictly, got " + target + " after " + previous);
            }
            previous = target;
            for (int c = 0; c < n; c++) {
                out[(int) target * n + c] = component(vb, (j * n + c) * size(type), type, normalized);
            }
        }
    }

    /** {@code k} tightly packed elements of {@code size} bytes at a sparse part's bufferView and byteOffset. */
    private ByteBuffer packed(GltfJson part, int k, int size) throws SceneException {
        int view = part.require("bufferView").index(doc.root.array("bufferViews").size());
        ByteBuffer data = doc.bufferView(view);
        long offset = part.integer("byteOffset", 0, 0, Integer.MAX_VALUE);
        if (offset + (long) k * size > data.capacity()) {
            throw part.error("byteOffset + count x size past the end of bufferView " + view);
        }
        return data.duplicate().position((int) offset).slice().order(java.nio.ByteOrder.LITTLE_ENDIAN);
    }

    private static double component(ByteBuffer b, int at, int type, boolean normalized) {
        switch (type) {
            case BYTE: {
                int v = b.get(at);
                return normalized ? Math.max(v / 127.0, -1) : v;
            }
            case UNSIGNED_BYTE: {
                int v = b.get(at) & 0xFF;
                return normalized ? v / 255.0 : v;
            }
            case SHORT: {
                int v = b.getShort(at);
                return normalized ? Math.max(v / 32767.0, -1) : v;
            }
            case UNSIGNED_SHORT: {
                int v = b.getShort(at) & 0xFFFF;
                return normalized ? v / 65535.0 : v;
            }
            case UNSIGNED_INT:
                return Integer.toUnsignedLong(b.getInt(at));
            default:
                return b.getFloat(at);
        }
    }

    private static int componentType(GltfJson a) throws SceneException {
        GltfJson t = a.require("componentType");
        int type = t.integer(0, Integer.MAX_VALUE);
        if (type < BYTE || type > FLOAT || type == 5124) {
            throw t.error("unknown componentType " + type);
        }
        return type;
    }

    static int size(int type) {
        return type == BYTE || type == UNSIGNED_BYTE ? 1 : type == SHORT || type == UNSIGNED_SHORT ? 2 : 4;
    }

    private static int components(GltfJson a) throws SceneException {
        GltfJson t = a.require("type");
        switch (t.string()) {
            case "SCALAR":
                return 1;
            case "VEC2":
                return 2;
            case "VEC3":
                return 3;
            case "VEC4":
                return 4;
            case "MAT2":
            case "MAT3":
            case "MAT4":
                throw t.error("matrix accessors are not used by meshes");
            default:
                throw t.error("unknown accessor type " + t.quoted() + " (known: " + String.join(", ", List.of("SCALAR", "VEC2", "VEC3", "VEC4")) + ")");
        }
    }

    private static String typeName(int components) {
        return components == 1 ? "SCALAR" : "VEC" + components;
    }
}
