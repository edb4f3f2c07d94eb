package dev.strahl.io.gltf;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Writes small glTF assets for the tests: the JSON as nested maps and lists (tests change any
 * property), one binary buffer that accessors and images append to, and the three ways to store
 * it: a {@code .glb}, a {@code .gltf} with a {@code .bin} beside it, or a {@code .gltf} with a
 * {@code data:} URI.
 */
public final class GltfWriter {
    public final Map<String, Object> root = new LinkedHashMap<>();
    private final ByteArrayOutputStream bin = new ByteArrayOutputStream();

    public GltfWriter() {
        root.put("asset", map("version", "2.0", "generator", "strahl tests"));
    }

    /** A map from alternating keys and values. */
    public static Map<String, Object> map(Object... kv) {
        Map<String, Object> m = new LinkedHashMap<>();
        for (int i = 0; i < kv.length; i += 2) {
            m.put((String) kv[i], kv[i + 1]);
        }
        return m;
    }

    @SuppressWarnings("unchecked")
    public List<Object> list(String key) {
        return (List<Object>) root.computeIfAbsent(key, k -> new ArrayList<>());
    }

    /** Appends {@code value} to the top-level array {@code key}; returns its index. */
    public int add(String key, Object value) {
        List<Object> l = list(key);
        l.add(value);
        return l.size() - 1;
    }

    /** Appends bytes (4-aligned) to the buffer as a new buffer view; returns the view's index. */
    public int view(byte[] bytes, Integer stride) {
        while (bin.size() % 4 != 0) {
            bin.write(0);
        }
        Map<String, Object> v = map("buffer", 0, "byteOffset", bin.size(), "byteLength", bytes.length);
        if (stride != null) {
            v.put("byteStride", stride);
        }
        bin.writeBytes(bytes);
        return add("bufferViews", v);
    }

    /** A FLOAT accessor of {@code type} (VEC3…) over new tightly packed data. */
    public int floats(String type, float... values) {
        ByteBuffer b = ByteBuffer.allocate(4 * values.length).order(ByteOrder.LITTLE_ENDIAN);
        for (float f : values) {
            b.putFloat(f);
        }
        int n = components(type);
        return add("accessors", map("bufferView", view(b.array(), null), "componentType", 5126, "count", values.length / n, "type", type));
    }

    /** An index accessor of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT. */
    public int indices(int componentType, int... values) {
        return add("accessors", map("bufferView", view(pack(componentType, values), null), "componentType", componentType,
                "count", values.length, "type", "SCALAR"));
    }

    /** Integers packed little-endian as {@code componentType} (5120…5125). */
    public static byte[] pack(int componentType, int... values) {
        int size = componentType <= 5121 ? 1 : componentType <= 5123 ? 2 : 4;
        ByteBuffer b = ByteBuffer.allocate(size * values.length).order(ByteOrder.LITTLE_ENDIAN);
        for (int v : values) {
            if (size == 1) {
                b.put((byte) v);
            } else if (size == 2) {
                b.putShort((short) v);
            } else {
                b.putInt(v);
            }
        }
        return b.array();
    }

    static int components(String type) {
        return type.equals("SCALAR") ? 1 : type.charAt(3) - '0';
    }

    /** A mesh of one TRIANGLES primitive; returns the mesh index. */
    public int mesh(float[] positions, int[] indices, Integer material) {
        Map<String, Object> prim = map("attributes", map("POSITION", floats("VEC3", positions)));
        if (indices != null) {
            prim.put("indices", indices(5125, indices));
        }
        if (material != null) {
            prim.put("material", material);
        }
        return add("meshes", map("primitives", new ArrayList<>(List.of(prim))));
    }

    /** A node with a mesh, in the default scene's roots. */
    public int rootNode(Map<String, Object> node) {
        int index = add("nodes", node);
        if (!root.containsKey("scenes")) {
            add("scenes", map("nodes", new ArrayList<>()));
            root.put("scene", 0);
        }
        @SuppressWarnings("unchecked")
        List<Object> roots = (List<Object>) ((Map<String, Object>) list("scenes").get(0)).get("nodes");
        roots.add(index);
        return index;
    }

    public byte[] binary() {
        return bin.toByteArray();
    }

    private void declareBuffer(String uri) {
        if (bin.size() > 0) {
            Map<String, Object> b = map("byteLength", bin.size());
            if (uri != null) {
                b.put("uri", uri);
            }
            root.put("buffers", new ArrayList<>(List.of(b)));
        }
    }

    /** A {@code .gltf} whose buffer is a {@code data:} URI. */
    public Path writeEmbedded(Path file) throws IOException {
        declareBuffer("data:application/octet-stream;base64," + Base64.getEncoder().encodeToString(binary()));
        Files.writeString(file, json(root));
        return file;
    }

    /** A {@code .gltf} with its buffer in a {@code .bin} file beside it. */
    public Path writeSeparate(Path file, String binName) throws IOException {
        declareBuffer(binName);
        Files.write(file.resolveSibling(binName), binary());
        Files.writeString(file, json(root));
        return file;
    }

    /** A {@code .glb}. */
    public Path writeGlb(Path file) throws IOException {
        Files.write(file, glb());
        return file;
    }

    public byte[] glb() {
        declareBuffer(null);
        byte[] json = json(root).getBytes(StandardCharsets.UTF_8);
        int jsonPadded = (json.length + 3) & ~3;
        byte[] data = binary();
        int binPadded = (data.length + 3) & ~3;
        int total = 12 + 8 + jsonPadded + (data.length > 0 ? 8 + binPadded : 0);
        ByteBuffer b = ByteBuffer.allocate(total).order(ByteOrder.LITTLE_ENDIAN);
        b.putInt(0x46546C67).putInt(2).putInt(total);
        b.putInt(jsonPadded).putInt(0x4E4F534A).put(json);
        for (int i = json.length; i < jsonPadded; i++) {
            b.put((byte) ' ');
        }
        if (data.length > 0) {
            b.putInt(binPadded).putInt(0x004E4942).put(data);
        }
        return b.array();
    }

    /** Minimal JSON for maps, lists, numbers, strings and booleans. */
    public static String json(Object o) {
        StringBuilder s = new StringBuilder();
        write(o, s);
        return s.toString();
    }

    private static void write(Object o, StringBuilder s) {
        if (o instanceof Map<?, ?> m) {
            s.append('{');
            boolean first = true;
            for (var e : m.entrySet()) {
                s.append(first ? "" : ",").append('"').append(e.getKey()).append("\":");
                write(e.getValue(), s);
                first = false;
            }
            s.append('}');
        } else if (o instanceof List<?> l) {
            s.append('[');
            for (int i = 0; i < l.size(); i++) {
                s.append(i == 0 ? "" : ",");
                write(l.get(i), s);
            }
            s.append(']');
        } else if (o instanceof double[] d) {
            List<Object> l = new ArrayList<>();
            for (double v : d) {
                l.add(v);
            }
            write(l, s);
        } else if (o instanceof String str) {
            s.append('"').append(str.replace("\\", "\\\\").replace("\"", "\\\"")).append('"');
        } else if (o instanceof Float f) {
            s.append(Float.toString(f));
        } else {
            s.append(o);
        }
    }
}
