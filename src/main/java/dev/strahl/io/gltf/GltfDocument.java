package dev.strahl.io.gltf;

import dev.strahl.codec.Printable;
import dev.strahl.scene.SceneException;
import java.io.IOException;
import java.net.URLDecoder;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * A parsed glTF asset: the JSON tree, its buffers (a GLB's BIN chunk, {@code data:} URIs or
 * external files next to the asset, each read once when first used) and buffer views, and the
 * notes collected while reading. Checks the asset version and the required extensions.
 */
final class GltfDocument {
    /** The extensions read here (the rest are ignored with a note, or refused when required). */
    static final Set<String> SUPPORTED = Set.of("KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_materials_specular",
            "KHR_materials_transmission", "KHR_materials_ior", "KHR_lights_punctual", "EXT_mesh_gpu_instancing");

    final Path file;
    final GltfJson root;
    final List<String> notes = new ArrayList<>();
    private final ByteBuffer glbBin;
    private final ByteBuffer[] buffers;
    private final Set<String> said = new LinkedHashSet<>();

    private GltfDocument(Path file, GltfJson root, ByteBuffer glbBin) throws SceneException {
        this.file = file;
        this.root = root;
        this.glbBin = glbBin;
        root.object();
        this.buffers = new ByteBuffer[root.array("buffers").size()];
    }

    /** Reads a {@code .gltf} or {@code .glb} file (told apart by content) and checks its asset and extensions. */
    static GltfDocument read(Path file) throws SceneException {
        byte[] bytes = readFile(file, file, "glTF file");
        GltfDocument doc;
        if (!GlbContainer.isGlb(bytes) && file.toString().toLowerCase(java.util.Locale.ROOT).endsWith(".glb")) {
            throw new SceneException(file, GlbContainer.wrongMagic(bytes));      // never read a .glb as JSON
        }
        if (GlbContainer.isGlb(bytes)) {
            GlbContainer glb = GlbContainer.read(file, bytes);
            doc = new GltfDocument(file, GltfJson.parse(file, glb.json(), glb.jsonOffset(), glb.jsonLength()), glb.bin());
        } else {
            doc = new GltfDocument(file, GltfJson.parse(file, bytes, 0, bytes.length), null);
        }
        doc.checkAssetAndExtensions();
        return doc;
    }

    private void checkAssetAndExtensions() throws SceneException {
        GltfJson asset = root.require("asset");
        String version = asset.require("version").string();
        if (!version.startsWith("2.")) {
            throw asset.get("version").error("glTF version " + asset.get("version").quoted() + " is not supported (only 2.x)");
        }
        for (GltfJson e : root.array("extensionsRequired")) {
            String name = e.string();
            if (!SUPPORTED.contains(name)) {
                throw e.error("required extension " + Printable.text(name, 64) + " is not supported" + hint(name));
            }
        }
        for (GltfJson e : root.array("extensionsUsed")) {
            String name = e.string();
            if (!SUPPORTED.contains(name)) {
                noteOnce("extension " + Printable.text(name, 64) + " is not supported: ignored");
            }
        }
    }

    private static String hint(String name) {
        switch (name) {
            case "KHR_draco_mesh_compression":
                return " (Draco-compressed meshes; re-export without compression)";
            case "EXT_meshopt_compression":
                return " (meshopt-compressed buffers; re-export without compression)";
            case "KHR_texture_basisu":
                return " (Basis Universal textures; re-export with PNG or JPEG images)";
            case "EXT_texture_webp":
                return " (WebP textures; re-export with PNG or JPEG images)";
            default:
                return "";
        }
    }

    /** Adds a note once (the same remark about many elements is said once). */
    void noteOnce(String note) {
        if (said.add(note)) {
            notes.add(note);
        }
    }

    /** The element {@code index} of the top-level array {@code name}. */
    GltfJson element(String name, GltfJson indexNode) throws SceneException {
        List<GltfJson> list = root.array(name);
        return list.get(indexNode.index(list.size()));
    }

    /** The bytes of buffer view {@code index} ({@code byteOffset}..+{@code byteLength} of its buffer), little-endian. */
    ByteBuffer bufferView(int index) throws SceneException {
        GltfJson view = root.array("bufferViews").get(index);
        GltfJson bufferIndex = view.require("buffer");
        ByteBuffer buffer = buffer(bufferIndex.index(buffers.length));
        long offset = view.integer("byteOffset", 0, 0, Integer.MAX_VALUE);
        long length = view.require("byteLength").integer(1, Integer.MAX_VALUE);
        if (offset + length > buffer.capacity()) {
            throw view.error("byteOffset + byteLength = " + (offset + length) + " past the end of buffer " + (int) bufferIndex.number()
                    + " (" + buffer.capacity() + " bytes)");
        }
        return buffer.duplicate().position((int) offset).limit((int) (offset + length)).slice().order(ByteOrder.LITTLE_ENDIAN);
    }

    /** The byte stride of buffer view {@code index}, or 0 when it has none (tightly packed). */
    int byteStride(int index) throws SceneException {
        return root.array("bufferViews").get(index).integer("byteStride", 0, 4, 252);
    }

    private ByteBuffer buffer(int index) throws SceneException {
        if (buffers[index] == null) {
            GltfJson b = root.array("buffers").get(index);
            long declared = b.require("byteLength").integer(1, Integer.MAX_VALUE);
            byte[] bytes;
            ByteBuffer data;
            if (!b.has("uri")) {
                if (index != 0 || glbBin == null) {
                    throw b.error("has no uri and the file has no GLB BIN chunk");
                }
                data = glbBin;
            } else {
                GltfJson uri = b.get("uri");
                bytes = uri.string().startsWith("data:") ? decodeDataUri(uri) : readFile(resolve(uri), file, "buffer file");
                data = ByteBuffer.wrap(bytes);
            }
            if (data.capacity() < declared) {
                throw b.error("byteLength " + declared + " but the data has " + data.capacity() + " bytes");
            }
            buffers[index] = data.duplicate().limit((int) declared).slice().order(ByteOrder.LITTLE_ENDIAN);
        }
        return buffers[index];
    }

    /** A {@code data:} URI's bytes (base64, or percent-encoded text). */
    static byte[] decodeDataUri(GltfJson uri) throws SceneException {
        String s = uri.string();
        int comma = s.indexOf(',');
        if (comma < 0) {
            throw uri.error("malformed data: URI (no comma) " + uri.quoted());
        }
        String header = s.substring(5, comma);
        try {
            if (header.endsWith(";base64")) {
                return Base64.getDecoder().decode(s.substring(comma + 1));
            }
            return URLDecoder.decode(s.substring(comma + 1), StandardCharsets.UTF_8).getBytes(StandardCharsets.ISO_8859_1);
        } catch (IllegalArgumentException e) {
            throw uri.error("malformed data: URI: " + (header.endsWith(";base64") ? "bad base64: " : "") + Printable.text(e.getMessage(), 80));
        }
    }

    /** A relative URI (percent-encoded, as glTF's URIs are) as a file next to the asset. */
    Path resolve(GltfJson uri) throws SceneException {
        String s = uri.string();
        if (s.matches("^[A-Za-z][A-Za-z0-9+.-]*://.*")) {
            throw uri.error("only relative file URIs and data: URIs are supported, got " + Printable.text(s, 80));
        }
        try {
            String decoded = URLDecoder.decode(s.replace("+", "%2B"), StandardCharsets.UTF_8);
            Path folder = file.toAbsolutePath().getParent();
            return folder.resolve(decoded).normalize();
        } catch (IllegalArgumentException e) {            // also InvalidPathException
            throw uri.error("not a valid file path: " + Printable.text(s, 80));
        }
    }

    /** A whole file as bytes; a missing or unreadable file is an error naming it. */
    static byte[] readFile(Path path, Path asset, String what) throws SceneException {
        try {
            if (Files.isDirectory(path)) {
                throw new SceneException(asset, what + " " + Printable.path(path) + " is a directory");
            }
            long size = Files.size(path);
            if (size > Integer.MAX_VALUE - 8) {
                throw new SceneException(asset, what + " " + Printable.path(path) + " is too large (" + size + " bytes; at most 2 GiB)");
            }
            return Files.readAllBytes(path);
        } catch (NoSuchFileException e) {
            throw new SceneException(asset, what + " not found: " + Printable.path(path));
        } catch (IOException e) {
            String why = e instanceof java.nio.file.AccessDeniedException ? "permission denied" : Printable.text(String.valueOf(e.getMessage()), 80);
            throw new SceneException(asset, "cannot read " + what + " " + Printable.path(path) + ": " + why, e);
        }
    }
}
