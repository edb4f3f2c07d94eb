package dev.strahl.io.gltf;

import static dev.strahl.io.gltf.GltfWriter.map;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;

/**
 * Structure-aware fuzzing inputs for the glTF reader: assets built from the format's grammar, every
 * part right or hostile: accessors (counts, offsets, component types, types, strides, sparse parts,
 * missing views: zeros), buffer views past their buffer, indices past the vertex count, primitive
 * modes, node hierarchies with cycles, shared children and bad matrices, scenes, materials with
 * textures whose images are embedded (valid, corrupt, bad base64) or missing, samplers, cameras,
 * required extensions; as {@code .gltf} with a data: URI buffer or as {@code .glb} with its chunks
 * right or not. {@link GltfFuzzSeeds} gives the mutated real files.
 */
public final class GltfFuzzInputs {
    private static final long[] HOSTILE = {0, 1, -1, 2, 3, 4, 7, 255, 256, 65535, 65536, Integer.MAX_VALUE, 1L << 31, 1L << 32,
        (1L << 53) + 1, 100_000_000, -2147483648L};
    private static final Object[] ODD_NUMBERS = {0.5, -0.0, 1e308, -1e308, 1e-320, "1", true, null, List.of(), Map.of()};

    private static final byte[] PNG = redOverGreen();

    private GltfFuzzInputs() {}

    private static byte[] redOverGreen() {
        try {
            return GltfMaterialsTest.redOverGreen();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    /** {@code .gltf} JSON with its buffer as a data: URI. */
    public static Arbitrary<byte[]> randomGltf() {
        return Arbitraries.longs().map(seed -> random(new SplittableRandom(seed), false));
    }

    /** {@code .glb} files. */
    public static Arbitrary<byte[]> randomGlb() {
        return Arbitraries.longs().map(seed -> random(new SplittableRandom(seed), true));
    }

    private static Object number(SplittableRandom r, long right) {
        int k = r.nextInt(16);
        return k == 0 ? HOSTILE[r.nextInt(HOSTILE.length)] : k == 1 ? ODD_NUMBERS[r.nextInt(ODD_NUMBERS.length)] : (Object) right;
    }

    private static boolean rarely(SplittableRandom r) {
        return r.nextInt(8) == 0;
    }

    static byte[] random(SplittableRandom r, boolean glb) {
        GltfWriter w = new GltfWriter();
        int vertices = r.nextInt(1, 9);
        float[] positions = new float[3 * vertices];
        for (int i = 0; i < positions.length; i++) {
            positions[i] = rarely(r) ? new float[] {Float.NaN, Float.POSITIVE_INFINITY, 3e38f, -0f}[r.nextInt(4)] : (float) r.nextGaussian();
        }
        int position = accessor(w, r, "VEC3", 5126, positions, vertices);
        Map<String, Object> attributes = map("POSITION", number(r, position));
        if (r.nextBoolean()) {
            float[] normals = new float[3 * vertices];
            java.util.Arrays.fill(normals, 0.5f);
            attributes.put("NORMAL", accessor(w, r, "VEC3", 5126, normals, vertices));
        }
        if (r.nextBoolean()) {
            float[] uvs = new float[2 * vertices];
            attributes.put("TEXCOORD_" + (rarely(r) ? 1 : 0), accessor(w, r, "VEC2", rarely(r) ? 5123 : 5126, uvs, vertices));
        }
        Map<String, Object> primitive = map("attributes", attributes, "mode", number(r, rarely(r) ? r.nextInt(8) : 4));
        if (r.nextBoolean()) {
            int n = 3 * r.nextInt(0, 5);
            int[] idx = new int[n];
            for (int i = 0; i < n; i++) {
                idx[i] = rarely(r) ? (int) HOSTILE[r.nextInt(HOSTILE.length)] : r.nextInt(vertices + (rarely(r) ? 3 : 0));
            }
            int type = new int[] {5121, 5123, 5125, 5126, 5122}[r.nextInt(rarely(r) ? 5 : 3)];
            primitive.put("indices", w.add("accessors", map("bufferView", w.view(GltfWriter.pack(type == 5126 ? 5125 : type, idx), null),
                    "componentType", type, "count", number(r, Math.max(1, n)), "type", rarely(r) ? "VEC2" : "SCALAR")));
        }
        if (r.nextBoolean()) {
            primitive.put("material", number(r, material(w, r)));
        }
        w.add("meshes", map("primitives", rarely(r) ? List.of() : List.of(primitive)));
        nodes(w, r);
        if (rarely(r)) {
            w.add("cameras", map("type", rarely(r) ? "fisheye" : "perspective", "perspective", map("yfov", number(r, 1),
                    "aspectRatio", number(r, 1))));
            w.add("nodes", map("camera", number(r, 0)));
        }
        if (rarely(r)) {
            w.root.put("extensionsRequired", List.of(rarely(r) ? "KHR_draco_mesh_compression" : "KHR_texture_transform"));
        }
        return glb ? glb(w, r) : gltf(w, r);
    }

    /** An accessor over new data, each property right or not; sometimes no view (zeros) or a sparse part. */
    private static int accessor(GltfWriter w, SplittableRandom r, String type, int componentType, float[] values, int count) {
        ByteBuffer b = ByteBuffer.allocate(4 * values.length).order(ByteOrder.LITTLE_ENDIAN);
        for (float f : values) {
            b.putFloat(f);
        }
        byte[] data = rarely(r) ? java.util.Arrays.copyOf(b.array(), r.nextInt(b.capacity() + 8)) : b.array();
        Integer stride = rarely(r) ? new int[] {0, 4, 8, 12, 13, 252, 256}[r.nextInt(7)] : null;
        Map<String, Object> a = map("componentType", number(r, componentType), "count", number(r, count), "type",
                rarely(r) ? new String[] {"SCALAR", "VEC4", "MAT4", "vec3", ""}[r.nextInt(5)] : type);
        if (!rarely(r)) {
            a.put("bufferView", number(r, w.view(data, stride)));
        }
        if (rarely(r)) {
            a.put("byteOffset", number(r, 4));
        }
        if (rarely(r)) {
            a.put("normalized", r.nextBoolean());
        }
        if (rarely(r)) {
            int k = r.nextInt(1, 3);
            a.put("sparse", map("count", number(r, k), "indices", map("bufferView", w.view(GltfWriter.pack(5121, 0, r.nextInt(count + 2)),
                    null), "componentType", number(r, 5121)), "values", map("bufferView", w.view(new byte[12 * k], null))));
        }
        return w.add("accessors", a);
    }

    /** A material whose base colour reads an image: embedded and valid, corrupt, bad base64, in a buffer view, or missing. */
    private static int material(GltfWriter w, SplittableRandom r) {
        byte[] png = PNG;
        Map<String, Object> image = switch (r.nextInt(6)) {
            case 0 -> map("uri", "data:image/png;base64," + Base64.getEncoder().encodeToString(png));
            case 1 -> map("uri", "data:image/png;base64," + Base64.getEncoder().encodeToString(corrupt(png, r)));
            case 2 -> map("uri", "data:image/png;base64,iVBORw0K!GgoAAAA");
            case 3 -> map("uri", rarely(r) ? "https://example.com/x.png" : "missing-" + r.nextInt(3) + ".png");
            default -> map("bufferView", number(r, w.view(rarely(r) ? corrupt(png, r) : png, null)), "mimeType", "image/png");
        };
        int source = w.add("images", image);
        Map<String, Object> texture = map("source", number(r, source));
        if (rarely(r)) {
            texture.put("sampler", w.add("samplers", map("wrapS", number(r, 33071), "wrapT", number(r, 10497))));
        }
        int t = w.add("textures", texture);
        Map<String, Object> info = map("index", number(r, t));
        if (rarely(r)) {
            info.put("extensions", map("KHR_texture_transform", map("scale", java.util.Arrays.asList(number(r, 2), 2), "rotation", number(r, 1))));
        }
        return w.add("materials", map("name", rarely(r) ? "\u0007\u001b[31m" : "m", "pbrMetallicRoughness", map("baseColorTexture", info,
                "baseColorFactor", java.util.Arrays.asList(1, 1, 1, number(r, 1))), "alphaMode", rarely(r) ? "MASK" : "OPAQUE"));
    }

    private static byte[] corrupt(byte[] b, SplittableRandom r) {
        byte[] c = java.util.Arrays.copyOf(b, r.nextBoolean() ? b.length : r.nextInt(b.length));
        for (int i = 0; i < 1 + r.nextInt(8) && c.length > 0; i++) {
            c[r.nextInt(c.length)] = (byte) r.nextInt(256);
        }
        return c;
    }

    /** Nodes: the mesh's, maybe under parents, with cycles, shared children, bad matrices and scenes that name them. */
    private static void nodes(GltfWriter w, SplittableRandom r) {
        int n = r.nextInt(1, 6);
        for (int i = 0; i < n; i++) {
            Map<String, Object> node = map();
            if (i == n - 1 || rarely(r)) {
                node.put("mesh", number(r, 0));
            }
            if (i < n - 1) {
                List<Object> children = new ArrayList<>(java.util.Arrays.asList(number(r, i + 1)));
                if (rarely(r)) {
                    children.add(r.nextInt(n));             // a cycle, or a second parent
                }
                node.put("children", children);
            }
            switch (r.nextInt(6)) {
                case 0 -> node.put("matrix", java.util.Arrays.asList(1, 0, 0, 0, 0, number(r, 1), 0, 0, 0, 0, 1, 0, 0, 0, 0, 1));
                case 1 -> node.put("rotation", java.util.Arrays.asList(number(r, 0), 0, 0, number(r, 1)));
                case 2 -> node.put("scale", java.util.Arrays.asList(number(r, 2), 1, rarely(r) ? -1 : 1));
                case 3 -> node.put("translation", java.util.Arrays.asList(0, number(r, 1), 0));
                default -> { }
            }
            w.add("nodes", node);
        }
        if (!rarely(r)) {
            w.add("scenes", map("nodes", java.util.Arrays.asList(number(r, 0))));
            if (r.nextBoolean()) {
                w.root.put("scene", number(r, 0));
            }
        }
    }

    private static byte[] gltf(GltfWriter w, SplittableRandom r) {
        byte[] bin = w.binary();
        String base64 = Base64.getEncoder().encodeToString(bin);
        if (rarely(r) && !base64.isEmpty()) {
            base64 = base64.substring(0, r.nextInt(base64.length())) + (r.nextBoolean() ? "*" : "");
        }
        w.root.put("buffers", java.util.Arrays.asList(map("byteLength", number(r, Math.max(1, bin.length)), "uri",
                rarely(r) ? "missing.bin" : "data:application/octet-stream;base64," + base64)));
        return GltfWriter.json(w.root).getBytes(StandardCharsets.UTF_8);
    }

    private static byte[] glb(GltfWriter w, SplittableRandom r) {
        byte[] b = w.glb();
        ByteBuffer le = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
        switch (r.nextInt(10)) {
            case 0 -> le.putInt(8, (int) HOSTILE[r.nextInt(HOSTILE.length)]);           // total length
            case 1 -> le.putInt(12, (int) HOSTILE[r.nextInt(HOSTILE.length)]);          // JSON chunk length
            case 2 -> le.putInt(4, r.nextInt(4));                                        // version
            case 3 -> b = java.util.Arrays.copyOf(b, r.nextInt(b.length));              // cut
            default -> { }
        }
        return b;
    }
}
