package dev.strahl.cli;

import static dev.strahl.io.gltf.GltfWriter.map;

import dev.strahl.io.gltf.GltfWriter;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Hostile glTF assets, {@code .gltf} (external and embedded buffers and images) and {@code .glb}:
 * each a main file and the files beside it, with the fragments its one-line error must hold (the
 * element at fault: {@code nodes[0]}, {@code accessors[0]}, {@code chunk 12}; the size a bomb claims).
 * Also the assets that use an image file as their texture, three ways.
 */
final class HostileGltf {
    /** An asset: the files to write (the first is the one rendered) and what the error line must say. */
    record Asset(String name, Map<String, byte[]> files, List<String> fragments) {
        String main() {
            return files.keySet().iterator().next();
        }

        @Override
        public String toString() {
            return name;
        }
    }

    private HostileGltf() {}

    /** A textured triangle: its material's base colour reads images[0], which {@code image} describes. */
    static GltfWriter triangle(Map<String, Object> image) {
        GltfWriter w = new GltfWriter();
        int mesh = w.mesh(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 2}, 0);
        w.add("materials", map("name", "m", "pbrMetallicRoughness", map("baseColorTexture", map("index", 0))));
        w.add("textures", map("source", 0));
        if (image != null) {
            w.add("images", image);
        }
        w.rootNode(map("mesh", mesh));
        return w;
    }

    static GltfWriter plain() {
        GltfWriter w = new GltfWriter();
        w.rootNode(map("mesh", w.mesh(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 2}, null)));
        return w;
    }

    @SuppressWarnings("unchecked")
    static Map<String, Object> element(GltfWriter w, String array, int index) {
        return (Map<String, Object>) w.list(array).get(index);
    }

    static byte[] text(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    static Asset asset(String name, Map<String, byte[]> files, String... fragments) {
        return new Asset(name, files, List.of(fragments));
    }

    static Map<String, byte[]> files(Object... nameBytes) {
        Map<String, byte[]> m = new LinkedHashMap<>();
        for (int i = 0; i < nameBytes.length; i += 2) {
            m.put((String) nameBytes[i], nameBytes[i + 1] instanceof String s ? text(s) : (byte[]) nameBytes[i + 1]);
        }
        return m;
    }

    /** A .gltf with its buffer as a data: URI (edits to the JSON go through {@code w}). */
    static String embedded(GltfWriter w) {
        return GltfWriter.json(withBuffer(w, "data:application/octet-stream;base64," + Base64.getEncoder().encodeToString(w.binary())));
    }

    /** JSON text with ESC and BEL written as JSON escapes of those control characters. */
    static String escapes(String json) {
        return json.replace("ESC", "\\u001b").replace("BEL", "\\u0007");
    }

    static Map<String, Object> withBuffer(GltfWriter w, String uri) {
        w.root.put("buffers", new ArrayList<>(List.of(map("byteLength", w.binary().length, "uri", uri))));
        return w.root;
    }

    static List<Asset> all() {
        List<Asset> out = new ArrayList<>();
        out.add(asset("malformed.gltf", files("t.gltf", "{\"asset\": {\"version\": \"2.0\"}, \u001b[31m\u0007 }"), "malformed JSON"));
        GltfWriter w = plain();
        String json = GltfWriter.json(withBuffer(w, "gone.bin"));
        out.add(asset("missing-bin.gltf", files("t.gltf", json), "buffer file not found", "gone.bin"));
        w = plain();
        out.add(asset("bad-base64.gltf", files("t.gltf", GltfWriter.json(withBuffer(w, "data:application/octet-stream;base64,AAAA!!*"))),
                "buffers[0].uri", "base64"));
        w = plain();
        element(w, "bufferViews", 0).put("byteLength", 4000);
        out.add(asset("view-past-buffer.gltf", files("t.gltf", embedded(w)), "bufferViews[0]", "past the end of buffer 0"));
        w = plain();
        element(w, "accessors", 0).put("count", 4);
        out.add(asset("accessor-past-view.gltf", files("t.gltf", embedded(w)), "accessors[0]", "past the end of bufferView 0"));
        w = new GltfWriter();
        w.rootNode(map("mesh", w.mesh(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 7}, null)));
        out.add(asset("index-past-vertices.gltf", files("t.gltf", embedded(w)), "accessors[1]", "index 7", "past the vertex count 3"));
        w = plain();
        w.add("nodes", map("children", List.of(0)));
        element(w, "nodes", 0).put("children", List.of(1));
        out.add(asset("cycle.gltf", files("t.gltf", embedded(w)), "nodes[0]", "reached twice"));
        w = plain();
        element(w, "accessors", 0).put("count", 2147483648L);
        out.add(asset("accessor-2-31.gltf", files("t.gltf", embedded(w)), "accessors[0].count", "2147483648"));
        w = plain();
        Map<String, Object> zeros = element(w, "accessors", 0);
        zeros.remove("bufferView");
        zeros.put("count", 500_000_000);
        out.add(asset("accessor-zeros-bomb.gltf", files("t.gltf", embedded(w)), "accessors[0]", "500000000"));
        w = plain();
        out.add(asset("absolute-url.gltf", files("t.gltf", GltfWriter.json(withBuffer(w, "https://example.com/t.bin"))),
                "only relative file URIs"));
        w = plain();
        out.add(asset("uri-with-escapes.gltf", files("t.gltf", escapes(GltfWriter.json(withBuffer(w, "ESC[2JBELx.bin")))),
                "buffer file not found", "\\x1b[2J\\x07x.bin"));
        w = plain();
        w.root.put("asset", map("version", "3.0ESC"));
        out.add(asset("version-3.gltf", files("t.gltf", escapes(embedded(w))), "glTF version '3.0\\x1b' is not supported"));
        out.add(asset("bad-base64-image.gltf", files("t.gltf", embedded(triangle(map("uri", "data:image/png;base64,iVBOR*w0")))),
                "images[0].uri", "base64"));
        out.addAll(glb());
        return out;
    }

    static List<Asset> glb() {
        List<Asset> out = new ArrayList<>();
        byte[] ok = plain().glb();
        out.add(asset("wrong-magic.glb", files("t.glb", new byte[] {'g', 'l', 'T', 'X', 2, 0, 0, 0, 0x1b, '[', '3', '1', 'm', 7, 0, 0}),
                "not a GLB file", "glTX"));
        out.add(asset("json.glb", files("t.glb", "{\"asset\": {\"version\": \"2.0\"}}"), "not a GLB file"));
        out.add(asset("empty.glb", files("t.glb", new byte[0]), "not a GLB file"));
        out.add(asset("truncated.glb", files("t.glb", Arrays.copyOf(ok, ok.length - 9)), "truncated GLB"));
        byte[] past = ok.clone();
        int jsonLength = ByteBuffer.wrap(ok).order(ByteOrder.LITTLE_ENDIAN).getInt(12);
        ByteBuffer.wrap(past).order(ByteOrder.LITTLE_ENDIAN).putInt(20 + jsonLength, 1 << 20);
        out.add(asset("chunk-past-end.glb", files("t.glb", past), "GLB chunk 1", "runs past the end"));
        byte[] binFirst = ok.clone();
        ByteBuffer.wrap(binFirst).order(ByteOrder.LITTLE_ENDIAN).putInt(16, 0x004E4942);
        out.add(asset("bin-first.glb", files("t.glb", binFirst), "the first chunk must be JSON"));
        byte[] version = ok.clone();
        ByteBuffer.wrap(version).order(ByteOrder.LITTLE_ENDIAN).putInt(4, 1);
        out.add(asset("version-1.glb", files("t.glb", version), "GLB version 1"));
        out.add(asset("chunk-12.glb", files("t.glb", chunk12(ok)), "GLB chunk 12"));
        return out;
    }

    /** A GLB with ten empty chunks of an unknown type after its BIN chunk, then a twelfth whose length runs past the end. */
    static byte[] chunk12(byte[] ok) {
        ByteBuffer b = ByteBuffer.allocate(ok.length + 11 * 8).order(ByteOrder.LITTLE_ENDIAN);
        b.put(ok);
        for (int i = 0; i < 10; i++) {
            b.putInt(0).putInt(0x5458450a);              // "\nEXT": skipped
        }
        b.putInt(4096).putInt(0x5458450a);
        b.putInt(8, b.capacity());
        return b.array();
    }

    /** The three ways a glTF asset references an image: a file beside it, a data: URI, a GLB buffer view. */
    enum ImageUse { FILE, DATA_URI, GLB_VIEW }

    /** An asset whose texture is {@code image} (named {@code name}), referenced as {@code use} says. */
    static Map<String, byte[]> textured(String name, byte[] image, ImageUse use) {
        switch (use) {
            case FILE: {
                GltfWriter w = triangle(map("uri", name));
                return files("t.gltf", embedded(w), name, image);
            }
            case DATA_URI: {
                GltfWriter w = triangle(map("uri", "data:image/png;base64," + Base64.getEncoder().encodeToString(image)));
                return files("t.gltf", embedded(w));
            }
            default: {
                GltfWriter w = triangle(null);
                w.add("images", map("bufferView", w.view(image, null), "mimeType", "image/png"));
                return files("t.glb", w.glb());
            }
        }
    }
}
