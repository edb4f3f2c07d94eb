package dev.strahl.io.gltf;

import static dev.strahl.io.gltf.GltfWriter.map;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import dev.strahl.io.SceneLoader;
import dev.strahl.material.Principled;
import dev.strahl.color.MutableRgb;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.texture.ImageTexture;
import dev.strahl.texture.UvTransform;
import dev.strahl.texture.Wrap;
import dev.strahl.world.World;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Base64;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** glTF materials → principled: factors, extensions, textures, samplers and texture transforms. */
class GltfMaterialsTest {
    @TempDir
    Path dir;

    /** A 1×2 PNG: red on top, green below. */
    static byte[] redOverGreen() throws Exception {
        BufferedImage img = new BufferedImage(1, 2, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, 0xFF0000);
        img.setRGB(0, 1, 0x00FF00);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(img, "png", out);
        return out.toByteArray();
    }

    /** A triangle with texture coordinates and material 0. */
    static GltfWriter textured(Map<String, Object> material) {
        GltfWriter w = new GltfWriter();
        int pos = w.floats("VEC3", GltfReaderTest.TRIANGLE);
        int uv = w.floats("VEC2", 0.5f, 0.25f, 0.5f, 0.75f, 0.5f, 0.25f);
        w.add("meshes", map("primitives", List.of(map("attributes", map("POSITION", pos, "TEXCOORD_0", uv), "material", 0))));
        w.rootNode(map("mesh", 0));
        w.add("materials", material);
        return w;
    }

    static Principled principled(Scene scene) {
        return (Principled) World.of(scene).bsdf(0);
    }

    @Test
    void factorsAndExtensionsMakeThePrincipledMaterial() throws Exception {
        Map<String, Object> m = map("name", "paint",
                "pbrMetallicRoughness", map("baseColorFactor", List.of(0.5, 0.25, 0.125, 1), "metallicFactor", 0.25, "roughnessFactor", 0.5),
                "emissiveFactor", List.of(1, 0.5, 0),
                "extensions", map("KHR_materials_emissive_strength", map("emissiveStrength", 4),
                        "KHR_materials_specular", map("specularFactor", 0.5, "specularColorFactor", List.of(1, 0.8, 0.6)),
                        "KHR_materials_transmission", map("transmissionFactor", 0.75),
                        "KHR_materials_ior", map("ior", 1.33)));
        Scene scene = SceneLoader.load(textured(m).writeGlb(dir.resolve("factors.glb")));
        Material expected = Material.principled("paint").baseColor(new Rgb(0.5, 0.25, 0.125)).metallic(0.25).roughness(0.5)
                .emission(new Rgb(1, 0.5, 0), 4).specular(0.5).specularColor(new Rgb(1, 0.8, 0.6)).transmission(0.75).ior(1.33).build();
        assertThat(scene.materials()).containsExactly(expected);
    }

    @Test
    void aPrimitiveWithoutMaterialGetsGltfsDefault() throws Exception {
        GltfWriter w = new GltfWriter();
        w.rootNode(map("mesh", w.mesh(GltfReaderTest.TRIANGLE, null, null)));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("default.glb")));
        assertThat(scene.materials()).containsExactly(Material.principled("glTF default").baseColor(Rgb.WHITE).metallic(1).roughness(1).build());
    }

    @Test
    void specularFactorZeroIsLambertian() throws Exception {
        Map<String, Object> m = map("pbrMetallicRoughness", map("baseColorFactor", List.of(0.6, 0.6, 0.6, 1), "metallicFactor", 0),
                "extensions", map("KHR_materials_specular", map("specularFactor", 0)));
        Principled p = principled(SceneLoader.load(textured(m).writeGlb(dir.resolve("lambert.glb"))));
        MutableRgb f = new MutableRgb();
        org.joml.Vector2d uv = new org.joml.Vector2d();
        for (double[] dirs : new double[][] {{0, 0, 1, 0, 0, 1}, {0.6, 0, 0.8, -0.8, 0, 0.6}, {0, 0.28, 0.96, 0.96, 0, 0.28}}) {
            p.eval(uv, new org.joml.Vector3d(dirs[0], dirs[1], dirs[2]), new org.joml.Vector3d(dirs[3], dirs[4], dirs[5]), f);
            assertThat(f.r).as("f = albedo/π for every pair of directions").isCloseTo(0.6 / Math.PI, within(1e-9));
        }
    }

    /** Embedded images go through a temporary file (textures are files), deleted once read; kept while a cluster render records. */
    @Test
    void embeddedImagesLeaveNoTemporaryFileBehind() throws Exception {
        GltfWriter w = textured(map("pbrMetallicRoughness", map("baseColorTexture", map("index", 0)), "name", "img"));
        w.add("images", map("bufferView", w.view(redOverGreen(), null), "mimeType", "image/png"));
        w.add("textures", map("source", 0));
        Path glb = w.writeGlb(dir.resolve("tex.glb"));
        Path tmp = Path.of(System.getProperty("java.io.tmpdir"));
        java.util.function.Supplier<List<Path>> folders = () -> {
            try (var list = Files.list(tmp)) {
                return list.filter(f -> f.getFileName().toString().startsWith("strahl-gltf")).toList();
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        };
        List<Path> before = folders.get();
        SceneLoader.load(glb);
        assertThat(folders.get()).as("temporary folders").isEqualTo(before);
        java.util.Set<Path> recorded = new java.util.TreeSet<>();
        dev.strahl.files.FileReads.recording(recorded, () -> SceneLoader.load(glb));
        Path image = recorded.stream().filter(f -> f.getFileName().toString().equals("image0")).findFirst().orElseThrow();
        assertThat(image).as("kept for the cluster to ship").isRegularFile();
        Files.delete(image);
        Files.delete(image.getParent());
    }

    @Test
    void anEmbeddedTextureReadsWithGltfsTopLeftOrigin() throws Exception {
        GltfWriter w = textured(map("pbrMetallicRoughness", map("baseColorTexture", map("index", 0)), "name", "img"));
        int view = w.view(redOverGreen(), null);
        w.add("images", map("bufferView", view, "mimeType", "image/png"));
        w.add("textures", map("source", 0));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("tex.glb")));
        ImageTexture t = (ImageTexture) principled(scene).baseColor();
        GltfDocument doc = GltfDocument.read(dir.resolve("tex.glb"));
        float[] uvs = new GltfMeshes(doc).mesh(0).get(0).uvs();
        MutableRgb c = new MutableRgb();
        t.rgb(uvs[0], uvs[1], c);                       // glTF v = 0.25: the image's upper half
        assertThat(c.r).isGreaterThan(0.99);
        assertThat(c.g).isLessThan(0.01);
        t.rgb(uvs[2], uvs[3], c);                       // glTF v = 0.75: the lower half
        assertThat(c.g).isGreaterThan(0.99);
        assertThat(c.r).isLessThan(0.01);
    }

    @Test
    void samplersWrapAndTextureTransformsAreTurnedToStrahlsCoordinates() throws Exception {
        Map<String, Object> info = map("index", 0, "extensions", map("KHR_texture_transform", map("offset", List.of(0.25, 0.125), "scale", List.of(2, 4))));
        GltfWriter w = textured(map("pbrMetallicRoughness", map("baseColorTexture", info)));
        w.add("images", map("uri", "data:image/png;base64," + Base64.getEncoder().encodeToString(redOverGreen())));
        w.add("samplers", map("wrapS", 33071, "wrapT", 33071));
        w.add("textures", map("source", 0, "sampler", 0));
        Scene scene = SceneLoader.load(w.writeEmbedded(dir.resolve("transform.gltf")));
        ImageTexture t = (ImageTexture) principled(scene).baseColor();
        assertThat(t.wrap()).isEqualTo(Wrap.CLAMP);
        // glTF: v' = 4 v + 0.125 from the top; strahl: 1 − v' = 4 (1 − v) + (1 − 4 − 0.125)
        assertThat(t.transform()).isEqualTo(new UvTransform(2, 4, 0.25, 1 - 4 - 0.125, 0));
        for (double vg : new double[] {0.1, 0.2, 0.3}) {
            double vs = 1 - vg;
            double glTfFromTop = 4 * vg + 0.125;
            assertThat(1 - glTfFromTop).isCloseTo(4 * vs + (1 - 4 - 0.125), within(1e-12));
        }
    }

    @Test
    void aMissingImageIsAWarningAndTheFactorStays() throws Exception {
        GltfWriter w = textured(map("name", "m", "pbrMetallicRoughness", map("baseColorTexture", map("index", 0), "baseColorFactor", List.of(0.5, 0.5, 0.5, 1))));
        w.add("images", map("uri", "missing%20file.png"));
        w.add("textures", map("source", 0));
        Scene scene = SceneLoader.load(w.writeSeparate(dir.resolve("missing.gltf"), "missing.bin"));
        assertThat(scene.notes()).anyMatch(n -> n.startsWith("warning: material 'm': image not found: ") && n.contains("missing file.png"));
        assertThat(scene.materials().get(0)).isEqualTo(Material.principled("m").baseColor(Rgb.gray(0.5)).build());
    }

    @Test
    void anExternalImageAndAMetallicRoughnessTextureAreRead() throws Exception {
        Files.write(dir.resolve("rg.png"), redOverGreen());
        GltfWriter w = textured(map("pbrMetallicRoughness", map("metallicRoughnessTexture", map("index", 0))));
        w.add("images", map("uri", "rg.png"));
        w.add("textures", map("source", 0));
        Scene scene = SceneLoader.load(w.writeSeparate(dir.resolve("mr.gltf"), "mr.bin"));
        Principled p = principled(scene);
        // roughness from G, metallic from B: the top texel is red, so roughness 0 and metallic 0 there
        assertThat(p.roughness().value(0.5, 0.75)).isCloseTo(0, within(1e-6));
        assertThat(p.roughness().value(0.5, 0.25)).isCloseTo(1, within(1e-6));
        assertThat(p.metallic().value(0.5, 0.25)).isCloseTo(0, within(1e-6));
    }

    /** A 2×1 RGBA PNG: opaque white, then transparent black. */
    static byte[] halfTransparent() throws Exception {
        BufferedImage img = new BufferedImage(2, 1, BufferedImage.TYPE_INT_ARGB);
        img.setRGB(0, 0, 0xFFFFFFFF);
        img.setRGB(1, 0, 0x00000000);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(img, "png", out);
        return out.toByteArray();
    }

    @Test
    void normalMapsAlphaMasksAndEmissiveTexturesUseTheMaterialMaps() throws Exception {
        Files.write(dir.resolve("base.png"), halfTransparent());
        Files.write(dir.resolve("normal.png"), redOverGreen());
        Files.write(dir.resolve("glow.png"), redOverGreen());
        GltfWriter w = textured(map("name", "leaf", "alphaMode", "MASK", "alphaCutoff", 0.25, "doubleSided", true,
                "pbrMetallicRoughness", map("baseColorTexture", map("index", 0), "baseColorFactor", List.of(1, 1, 1, 0.5)),
                "normalTexture", map("index", 1, "scale", 0.5), "emissiveTexture", map("index", 2), "emissiveFactor", List.of(0.5, 0.5, 0.5),
                "extensions", map("KHR_materials_emissive_strength", map("emissiveStrength", 4))));
        for (String f : List.of("base.png", "normal.png", "glow.png")) {
            w.add("textures", map("source", w.add("images", map("uri", f))));
        }
        Scene scene = SceneLoader.load(w.writeSeparate(dir.resolve("maps.gltf"), "maps.bin"));
        dev.strahl.scene.Texture base = dev.strahl.scene.Texture.image(dir.resolve("base.png"));
        Material expected = Material.principled("leaf").baseColor(base)
                .emission(dev.strahl.scene.Texture.image(dir.resolve("glow.png")).scaled(Rgb.gray(0.5)), 4).build()   // factor × texture
                .withNormalMap(dev.strahl.scene.Texture.image(dir.resolve("normal.png")).linear(), 0.5)
                .withAlphaCutout(base.alpha(), 0.5);           // alpha × 0.5 < 0.25 ⇔ alpha < 0.5
        assertThat(scene.materials()).containsExactly(expected);
    }

    @Test
    void blendIsAMaskAtOneHalfAndAConstantAlphaCutsAllOrNothing() throws Exception {
        GltfWriter w = textured(map("name", "glass", "alphaMode", "BLEND",
                "pbrMetallicRoughness", map("baseColorFactor", List.of(1, 1, 1, 0.25))));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("blend.glb")));
        assertThat(scene.notes()).anyMatch(n -> n.startsWith("alphaMode BLEND is rendered as MASK with alphaCutoff 0.5"));
        assertThat(scene.materials()).containsExactly(Material.principled("glass").build()
                .withAlphaCutout(dev.strahl.scene.Texture.constant(0), 0.5));
        GltfWriter opaque = textured(map("name", "o", "alphaMode", "MASK", "pbrMetallicRoughness", map("baseColorFactor", List.of(1, 1, 1, 0.75))));
        assertThat(SceneLoader.load(opaque.writeGlb(dir.resolve("mask.glb"))).materials())
                .containsExactly(Material.principled("o").build().withAlphaCutout(dev.strahl.scene.Texture.constant(1), 0.5));
    }
}
