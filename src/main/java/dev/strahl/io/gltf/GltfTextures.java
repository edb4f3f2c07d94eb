package dev.strahl.io.gltf;

import dev.strahl.codec.Printable;
import dev.strahl.files.FileReads;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Texture;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

/**
 * glTF texture references ({@code textureInfo}): the image (a file next to the asset, a
 * {@code data:} URI or a buffer view; PNG or JPEG), the sampler's wrap mode and
 * KHR_texture_transform's offset, rotation and scale. Texture coordinates were turned to strahl's
 * bottom-left convention when the mesh was read (v' = 1 − v), so a transform (offset o, rotation
 * r, scale s, in glTF's top-left coordinates) becomes scale s, rotation r and offset
 * (o_u + s_v sin r, 1 − s_v cos r − o_v) here (see {@link #transformed}). Which coordinate set a
 * texture reads ({@link #texCoord}) is the mesh's business: {@link GltfMaterials#uvSet}. An image
 * file that is missing is a warning, as in MTL files: the material keeps its factors; an image that
 * cannot be decoded (a file, a data: URI or a buffer view) is an error naming the asset, the image
 * and the file. Embedded images are written once to a temporary file, as strahl's textures are files.
 */
final class GltfTextures {
    static final int CLAMP_TO_EDGE = 33071;
    static final int MIRRORED_REPEAT = 33648;
    static final int REPEAT = 10497;

    private final GltfDocument doc;
    private final Map<Integer, Texture> images = new HashMap<>();
    private final Map<Integer, Boolean> failed = new HashMap<>();
    private Path tempFolder;

    GltfTextures(GltfDocument doc) {
        this.doc = doc;
    }

    /**
     * The texture a {@code textureInfo} names, with its sampler and transform, or null (with a
     * warning note) when its image cannot be used.
     */
    Texture texture(GltfJson info, String material) throws SceneException {
        GltfJson textureNode = doc.element("textures", info.require("index"));
        GltfJson transform = extension(info, "KHR_texture_transform");
        GltfJson source = textureNode.get("source");
        if (source == null) {
            GltfJson ext = textureNode.get("extensions");
            doc.noteOnce("warning: " + textureNode.path() + " has no PNG or JPEG source"
                    + (ext != null ? " (extensions " + Printable.text(String.join(", ", ext.object().keySet()), 80) + ")" : "") + ": ignored");
            return null;
        }
        int imageIndex = source.index(doc.root.array("images").size());
        Texture t = image(imageIndex, material);
        if (t == null) {
            return null;
        }
        if (textureNode.has("sampler")) {
            GltfJson sampler = doc.element("samplers", textureNode.get("sampler"));
            int s = sampler.integer("wrapS", REPEAT, 0, Integer.MAX_VALUE);
            int tt = sampler.integer("wrapT", REPEAT, 0, Integer.MAX_VALUE);
            if (s != tt) {
                doc.noteOnce(sampler.path() + ": wrapS and wrapT differ; strahl wraps both axes alike, by wrapS");
            }
            t = wrapped(t, sampler, s);
        }
        return transform == null ? t : transformed(t, transform);
    }

    /**
     * The texture with KHR_texture_transform applied. The extension's README defines
     * uv' = T·R·S·uv in glTF's top-left coordinates, with R = [cos r, sin r; −sin r, cos r] as
     * its GLSL literal reads row by row: u' = cos r · s_u u + sin r · s_v v + o_u,
     * v' = −sin r · s_u u + cos r · s_v v + o_v. That reading is the one the README's own example
     * confirms (offset [0, 1], rotation π/2, scale ½ shows the image's lower-left quadrant turned
     * clockwise), and the one the Khronos glTF-Sample-Viewer and Blender's importer use (a
     * column-major reading of the literal would turn the other way). With v = 1 − v_glTF on both
     * sides it is: scale s, rotate counter-clockwise by r, offset (o_u + s_v sin r, 1 − s_v cos r − o_v),
     * which is strahl's {@code UvTransform} order.
     */
    static Texture transformed(Texture t, GltfJson transform) throws SceneException {
        double[] offset = transform.numbers("offset", 2, new double[] {0, 0});
        double[] scale = transform.numbers("scale", 2, new double[] {1, 1});
        double r = transform.number("rotation", 0);
        if (!Double.isFinite(offset[0]) || !Double.isFinite(offset[1]) || !Double.isFinite(scale[0]) || !Double.isFinite(scale[1])
                || !Double.isFinite(r)) {
            throw transform.error("offset, rotation and scale must be finite");
        }
        double sin = Math.sin(r), cos = Math.cos(r);
        double ou = offset[0] + scale[1] * sin, ov = 1 - scale[1] * cos - offset[1];
        if (!Double.isFinite(ou + ov)) {
            throw transform.error("offset and scale too large (the offset in strahl's coordinates is not finite)");
        }
        return t.withUvScale(scale[0], scale[1]).withUvRotation(r).withUvOffset(ou, ov);
    }

    /** The coordinate set (n of TEXCOORD_n) a {@code textureInfo} reads: its texCoord, or KHR_texture_transform's. */
    static int texCoord(GltfJson info) throws SceneException {
        int texCoord = info.integer("texCoord", 0, 0, Integer.MAX_VALUE);
        GltfJson transform = extension(info, "KHR_texture_transform");
        if (transform != null && transform.has("texCoord")) {
            texCoord = transform.integer("texCoord", 0, 0, Integer.MAX_VALUE);
        }
        return texCoord;
    }

    private static Texture wrapped(Texture t, GltfJson sampler, int mode) throws SceneException {
        switch (mode) {
            case CLAMP_TO_EDGE:
                return t.clamped();
            case MIRRORED_REPEAT:
                return t.mirrored();
            case REPEAT:
                return t;
            default:
                throw sampler.error("unknown wrap mode " + mode + " (known: 33071 CLAMP_TO_EDGE, 33648 MIRRORED_REPEAT, 10497 REPEAT)");
        }
    }

    static GltfJson extension(GltfJson element, String name) throws SceneException {
        GltfJson ext = element.get("extensions");
        return ext == null ? null : ext.get(name);
    }

    private Texture image(int index, String material) throws SceneException {
        Texture done = images.get(index);
        if (done != null || failed.containsKey(index)) {
            return done;
        }
        GltfJson image = doc.root.array("images").get(index);
        Path path;
        String embedded = null;               // how the image is embedded, or null for a file of its own
        if (image.has("uri")) {
            GltfJson uri = image.get("uri");
            if (uri.string().startsWith("data:")) {
                embedded = "embedded as a data: URI";
                path = embedded(index, GltfDocument.decodeDataUri(uri));
            } else {
                path = doc.resolve(uri);
            }
        } else {
            GltfJson view = image.require("bufferView");
            int viewIndex = view.index(doc.root.array("bufferViews").size());
            ByteBuffer data = doc.bufferView(viewIndex);
            byte[] bytes = new byte[data.remaining()];
            data.duplicate().get(bytes);
            embedded = "embedded in bufferView " + viewIndex;
            path = embedded(index, bytes);
        }
        try {
            Texture t = Texture.image(path);
            images.put(index, t);
            return t;
        } catch (NoSuchFileException e) {
            // a missing image is a warning, as in MTL files and scene files; a corrupt one is an error
            doc.notes.add("warning: material " + Printable.quote(material) + ": image not found: " + Printable.path(path) + " ("
                    + image.path() + ", ignored)");
        } catch (IOException e) {
            String m = String.valueOf(e.getMessage());
            String prefix = path + ": ";
            if (embedded != null) {          // the temporary file's name means nothing to the user
                m = "(" + embedded + ") " + (m.startsWith(prefix) ? m.substring(prefix.length()) : m);
            }
            throw new SceneException(doc.file, image.path() + ": cannot read the texture image of material " + Printable.quote(material)
                    + ": " + Printable.line(m), e);
        } finally {
            if (embedded != null) {
                forget(path);
            }
        }
        failed.put(index, true);
        return null;
    }

    /**
     * Deletes an embedded image's temporary file once it is read (its pixels are in memory), so that a
     * process that loads many assets (the viewer, a server, the fuzzer) leaves no files behind; kept
     * (until exit) only while a cluster render records the scene's files, which ships them.
     */
    private void forget(Path file) {
        if (FileReads.isRecording()) {
            return;
        }
        try {
            Files.deleteIfExists(file);
            if (tempFolder != null) {
                Files.deleteIfExists(tempFolder);       // once empty
                tempFolder = null;
            }
        } catch (IOException e) {
            // not empty (another image of this asset is being read), or gone: the exit hook or the next call removes it
        }
    }

    private Path embedded(int index, byte[] bytes) throws SceneException {
        try {
            if (tempFolder == null) {
                tempFolder = Files.createTempDirectory("strahl-gltf");
                if (FileReads.isRecording()) {
                    tempFolder.toFile().deleteOnExit();
                }
            }
            Path f = tempFolder.resolve("image" + index);
            Files.write(f, bytes);
            if (FileReads.isRecording()) {
                f.toFile().deleteOnExit();
            }
            return f;
        } catch (IOException e) {
            throw new SceneException(doc.file, "cannot store embedded image " + index + " in a temporary file: " + e.getMessage(), e);
        }
    }
}
