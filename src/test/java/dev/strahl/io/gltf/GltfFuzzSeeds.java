package dev.strahl.io.gltf;

import static dev.strahl.io.gltf.GltfWriter.map;

import java.nio.charset.StandardCharsets;
import java.util.Base64;
import java.util.List;

/** Seeds for fuzzing the glTF reader: small assets that use most of what it reads, as GLB and as glTF JSON. */
public final class GltfFuzzSeeds {
    /** Words a mutation may insert into the JSON. */
    public static final List<String> WORDS = List.of("\"accessors\"", "\"bufferView\"", "\"byteOffset\"", "\"byteStride\"", "\"count\"",
            "\"componentType\"", "5120", "5121", "5122", "5123", "5125", "5126", "\"normalized\"", "true", "\"sparse\"", "\"indices\"",
            "\"mode\"", "\"children\"", "\"matrix\"", "\"rotation\"", "\"scale\"", "\"camera\"", "\"yfov\"", "\"extensionsRequired\"",
            "\"KHR_lights_punctual\"", "\"KHR_texture_transform\"", "\"uri\"", "\"data:\"", "-1", "0", "1e308", "4294967295", "null", "[]", "{}",
            "\"VEC3\"", "\"SCALAR\"", "\"MAT4\"", "\"texCoord\"", "\"sampler\"", "33071", "33648", "\"alphaMode\"", "\"MASK\"");

    private GltfFuzzSeeds() {}

    /** One asset with a strip, a fan, a sparse accessor, normalised texture coordinates, an embedded image, a camera and a light. */
    static GltfWriter rich() throws Exception {
        GltfWriter w = new GltfWriter();
        int pos = w.floats("VEC3", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0);
        int nrm = w.floats("VEC3", 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1);
        int uvView = w.view(GltfWriter.pack(5123, 0, 0, 65535, 0, 65535, 65535, 0, 65535), null);
        int uv = w.add("accessors", map("bufferView", uvView, "componentType", 5123, "normalized", true, "count", 4, "type", "VEC2"));
        int strip = w.indices(5121, 0, 1, 3, 2);
        int sparseIdx = w.view(GltfWriter.pack(5121, 2), null);
        int sparseVal = w.view(new byte[] {0, 0, 0, 64, 0, 0, 0, 64, 0, 0, 0, 0}, null);
        int moved = w.add("accessors", map("bufferView", 0, "componentType", 5126, "count", 4, "type", "VEC3",
                "sparse", map("count", 1, "indices", map("bufferView", sparseIdx, "componentType", 5121), "values", map("bufferView", sparseVal))));
        int image = w.view(GltfMaterialsTest.redOverGreen(), null);
        w.add("images", map("bufferView", image, "mimeType", "image/png"));
        w.add("samplers", map("wrapS", 33648, "wrapT", 33648));
        w.add("textures", map("source", 0, "sampler", 0));
        w.add("materials", map("name", "m", "pbrMetallicRoughness", map("baseColorTexture", map("index", 0,
                "extensions", map("KHR_texture_transform", map("offset", List.of(0.5, 0), "scale", List.of(2, 2))))),
                "emissiveFactor", List.of(0.1, 0.1, 0.1), "extensions", map("KHR_materials_ior", map("ior", 1.4))));
        w.add("meshes", map("primitives", List.of(
                map("attributes", map("POSITION", pos, "NORMAL", nrm, "TEXCOORD_0", uv), "indices", strip, "mode", 5, "material", 0),
                map("attributes", map("POSITION", moved), "mode", 6))));
        int child = w.add("nodes", map("mesh", 0, "rotation", List.of(0, 0.6, 0, 0.8)));
        w.rootNode(map("scale", List.of(1, 2, 1), "children", List.of(child)));
        w.add("cameras", map("type", "perspective", "perspective", map("yfov", 0.7, "aspectRatio", 1.5)));
        w.rootNode(map("camera", 0, "translation", List.of(0.5, 0.5, 3)));
        w.root.put("extensions", map("KHR_lights_punctual", map("lights", List.of(map("type", "spot", "intensity", 5, "spot", map("outerConeAngle", 0.5))))));
        w.rootNode(map("translation", List.of(0, 2, 2), "extensions", map("KHR_lights_punctual", map("light", 0))));
        w.root.put("extensionsUsed", List.of("KHR_lights_punctual", "KHR_texture_transform", "KHR_materials_ior"));
        return w;
    }

    /** GLB seeds. */
    public static List<byte[]> glb() throws Exception {
        return List.of(rich().glb(), GltfReaderTest.quad().glb());
    }

    /** glTF JSON seeds (buffers as data: URIs). */
    public static List<byte[]> gltf() throws Exception {
        GltfWriter a = rich();
        a.root.put("buffers", List.of(map("byteLength", a.binary().length,
                "uri", "data:application/octet-stream;base64," + Base64.getEncoder().encodeToString(a.binary()))));
        GltfWriter b = GltfReaderTest.quad();
        b.root.put("buffers", List.of(map("byteLength", b.binary().length,
                "uri", "data:application/octet-stream;base64," + Base64.getEncoder().encodeToString(b.binary()))));
        return List.of(GltfWriter.json(a.root).getBytes(StandardCharsets.UTF_8), GltfWriter.json(b.root).getBytes(StandardCharsets.UTF_8));
    }
}
