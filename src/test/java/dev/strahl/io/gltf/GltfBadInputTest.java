package dev.strahl.io.gltf;

import static dev.strahl.io.gltf.GltfWriter.map;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.io.SceneLoader;
import dev.strahl.scene.SceneException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Bad glTF input: one line naming the file and the JSON path (or the place in the GLB), a {@link SceneException}. */
class GltfBadInputTest {
    @TempDir
    Path dir;

    private String refused(String name, byte[] bytes) throws Exception {
        Path file = dir.resolve(name);
        Files.write(file, bytes);
        return refused(file);
    }

    private static String refused(Path file) {
        Throwable t = org.assertj.core.api.Assertions.catchThrowable(() -> SceneLoader.load(file));
        assertThat(t).isInstanceOf(SceneException.class);
        String message = t.getMessage();
        assertThat(message).startsWith(file + ": ").doesNotContain("\n");
        return message.substring(file.toString().length() + 2);
    }

    @Test
    void truncatedGlb() throws Exception {
        byte[] glb = GltfReaderTest.quad().glb();
        assertThat(refused("t.glb", Arrays.copyOf(glb, glb.length - 10))).startsWith("truncated GLB: the header says " + glb.length + " bytes");
        assertThat(refused("h.glb", Arrays.copyOf(glb, 8))).startsWith("truncated GLB: 8 bytes");
    }

    @Test
    void chunkLengthPastTheEnd() throws Exception {
        byte[] glb = GltfReaderTest.quad().glb();
        ByteBuffer.wrap(glb).order(ByteOrder.LITTLE_ENDIAN).putInt(12, 1 << 20);
        assertThat(refused("c.glb", glb)).startsWith("GLB chunk 0 ('JSON', 1048576 bytes at byte 20) runs past the end of the file");
    }

    @Test
    void accessorPastItsBufferView() throws Exception {
        GltfWriter w = GltfReaderTest.quad();
        @SuppressWarnings("unchecked")
        Map<String, Object> positions = (Map<String, Object>) w.list("accessors").get(0);
        positions.put("count", 5);
        assertThat(refused("a.glb", w.glb())).isEqualTo("accessors[0]: byteOffset + count x stride past the end of bufferView 0: count 5 of 12-byte elements 12 bytes apart"
                + " from byte 0 end at byte 60, the view has 48");
    }

    @Test
    void bufferViewPastItsBuffer() throws Exception {
        GltfWriter w = GltfReaderTest.quad();
        @SuppressWarnings("unchecked")
        Map<String, Object> view = (Map<String, Object>) w.list("bufferViews").get(1);
        view.put("byteLength", 4000);
        assertThat(refused("v.glb", w.glb())).startsWith("bufferViews[1]: byteOffset + byteLength = 4048 past the end of buffer 0");
    }

    @Test
    void indexPastTheVertexCount() throws Exception {
        GltfWriter w = new GltfWriter();
        w.rootNode(map("mesh", w.mesh(GltfReaderTest.TRIANGLE, new int[] {0, 1, 3}, null)));
        assertThat(refused("i.glb", w.glb())).isEqualTo("accessors[1]: index 3 at element 2 is past the vertex count 3");
    }

    @Test
    void missingBinFile() throws Exception {
        Path file = GltfReaderTest.quad().writeSeparate(dir.resolve("m.gltf"), "m.bin");
        Files.delete(dir.resolve("m.bin"));
        assertThat(refused(file)).isEqualTo("buffer file not found: " + dir.toAbsolutePath().resolve("m.bin"));
    }

    @Test
    void nanPosition() throws Exception {
        GltfWriter w = new GltfWriter();
        w.rootNode(map("mesh", w.mesh(new float[] {0, 0, 0, Float.NaN, 0, 0, 0, 1, 0}, null, null)));
        assertThat(refused("n.glb", w.glb())).isEqualTo("accessors[0]: POSITION of vertex 1 is not finite (NaN)");
    }

    @Test
    void malformedJson() throws Exception {
        assertThat(refused("j.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"nodes\": [,]}".getBytes(StandardCharsets.UTF_8)))
                .startsWith("malformed JSON: line 2, column");
        assertThat(refused("e.gltf", new byte[0])).isEqualTo("empty glTF JSON");
    }

    @Test
    void unsupportedRequiredExtensionsAreNamed() throws Exception {
        for (String ext : List.of("KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_texture_basisu", "EXT_texture_webp")) {
            GltfWriter w = GltfReaderTest.quad();
            w.root.put("extensionsRequired", List.of("KHR_materials_ior", ext));
            assertThat(refused("x.glb", w.glb())).startsWith("extensionsRequired[1]: required extension " + ext + " is not supported (");
        }
    }

    @Test
    void wrongTypesAndIndicesNameTheirPath() throws Exception {
        GltfWriter w = GltfReaderTest.quad();
        w.rootNode(map("mesh", 7));
        assertThat(refused("r.glb", w.glb())).isEqualTo("nodes[1].mesh: index 7 out of range (1 element)");
        GltfWriter v = GltfReaderTest.quad();
        v.root.put("asset", map("version", 2));
        assertThat(refused("s.glb", v.glb())).isEqualTo("asset.version: must be a string, got a number");
        GltfWriter c = GltfReaderTest.quad();
        c.add("nodes", map("children", List.of(1)));
        c.rootNode(map("children", List.of(1)));
        assertThat(refused("cycle.glb", c.glb())).isEqualTo("nodes[1]: is reached twice in the node hierarchy (a cycle, or more than one parent)");
        GltfWriter m = GltfReaderTest.quad();
        m.add("materials", map("pbrMetallicRoughness", map("metallicFactor", 2)));
        @SuppressWarnings("unchecked")
        Map<String, Object> prim = (Map<String, Object>) ((List<Object>) ((Map<String, Object>) m.list("meshes").get(0)).get("primitives")).get(0);
        prim.put("material", 0);
        assertThat(refused("mat.glb", m.glb())).isEqualTo("materials[0].pbrMetallicRoughness.metallicFactor: must lie in [0, 1], got 2");
    }

    @Test
    void aGlbWithoutBinChunkButABufferWithoutUri() throws Exception {
        GltfWriter w = GltfReaderTest.quad();
        byte[] glb = w.glb();
        // keep the JSON chunk (which declares a buffer without uri) and drop the BIN chunk
        int jsonLength = ByteBuffer.wrap(glb).order(ByteOrder.LITTLE_ENDIAN).getInt(12);
        byte[] cut = Arrays.copyOf(glb, 20 + jsonLength);
        ByteBuffer.wrap(cut).order(ByteOrder.LITTLE_ENDIAN).putInt(8, cut.length);
        assertThat(refused("nobin.glb", cut)).isEqualTo("buffers[0]: has no uri and the file has no GLB BIN chunk");
    }

    @Test
    void anAbsoluteUrlIsRefused() throws Exception {
        GltfWriter w = GltfReaderTest.quad();
        Path file = w.writeSeparate(dir.resolve("u.gltf"), "u.bin");
        Files.writeString(file, Files.readString(file).replace("\"uri\":\"u.bin\"", "\"uri\":\"https://example.com/u.bin\""));
        assertThatThrownBy(() -> SceneLoader.load(file)).isInstanceOf(SceneException.class)
                .hasMessage(file + ": buffers[0].uri: only relative file URIs and data: URIs are supported, got https://example.com/u.bin");
    }
}
