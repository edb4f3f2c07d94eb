package dev.strahl.io.gltf;

import static dev.strahl.io.gltf.GltfWriter.map;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import dev.strahl.io.SceneLoader;
import dev.strahl.material.Principled;
import dev.strahl.color.MutableRgb;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.texture.ImageTexture;
import dev.strahl.color.Srgb;
import dev.strahl.texture.TextureLookup;
import dev.strahl.texture.UvTransform;
import dev.strahl.world.World;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.util.Base64;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.joml.Vector2d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The specification's factor × texture for every pair strahl reads, KHR_texture_transform's
 * rotation against hand-computed coordinates, and the coordinate set (TEXCOORD_n) a material's
 * textures choose. Every lookup is at a texel centre of a 2×2 image, where the bilinear filter
 * returns the texel itself.
 */
class GltfFactorsTest {
    @TempDir
    java.nio.file.Path dir;

    /** The 2×2 RGBA texels, glTF's top-left first: {r, g, b, a} in 0…255. */
    static final int[][] TEXELS = {{200, 40, 120, 255}, {10, 220, 90, 128}, {255, 128, 0, 64}, {30, 60, 250, 200}};
    /** glTF texture coordinates of the four texel centres, in the order of {@link #TEXELS}. */
    static final double[][] CENTRES = {{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}};

    static byte[] quadPng() throws Exception {
        BufferedImage img = new BufferedImage(2, 2, BufferedImage.TYPE_INT_ARGB);
        for (int i = 0; i < 4; i++) {
            int[] t = TEXELS[i];
            img.setRGB(i % 2, i / 2, (t[3] << 24) | (t[0] << 16) | (t[1] << 8) | t[2]);
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(img, "png", out);
        return out.toByteArray();
    }

    /** A triangle with material 0 (and texture 0, the 2×2 image, embedded), loaded. */
    Scene load(Map<String, Object> material) throws Exception {
        GltfWriter w = GltfMaterialsTest.textured(material);
        w.add("images", map("uri", "data:image/png;base64," + Base64.getEncoder().encodeToString(quadPng())));
        w.add("textures", map("source", 0));
        return SceneLoader.load(w.writeEmbedded(dir.resolve("factors.gltf")));
    }

    /** Texel {@code i}'s channel {@code c} as a linear number (8 bits over 255, as the reader gives it). */
    static double linear(int i, int c) {
        return TEXELS[i][c] / 255f;
    }

    /** Texel {@code i}'s colour channel {@code c}, sRGB-decoded. */
    static double decoded(int i, int c) {
        return Srgb.decode(TEXELS[i][c] / 255f);
    }

    /** The colour a texture gives at glTF's texel centre {@code i} (strahl's v = 1 − v). */
    static MutableRgb colourAt(TextureLookup t, int i) {
        MutableRgb c = new MutableRgb();
        t.rgb(CENTRES[i][0], 1 - CENTRES[i][1], c);
        return c;
    }

    static double valueAt(TextureLookup t, int i) {
        return t.value(CENTRES[i][0], 1 - CENTRES[i][1]);
    }

    @Test
    void baseColorIsFactorTimesDecodedTexel() throws Exception {
        Scene scene = load(map("pbrMetallicRoughness", map("baseColorTexture", map("index", 0), "baseColorFactor", List.of(0.5, 0.8, 0.25, 1))));
        TextureLookup base = GltfMaterialsTest.principled(scene).baseColor();
        double[] f = {0.5, 0.8, 0.25};
        for (int i = 0; i < 4; i++) {
            assertFactorTimesDecodedTexel(colourAt(base, i), 1, f, i);
        }
        assertThat(scene.notes()).noneMatch(n -> n.contains("factor"));
    }

    @Test
    void roughnessIsFactorTimesGreenAndMetallicFactorTimesBlue() throws Exception {
        Scene scene = load(map("pbrMetallicRoughness", map("metallicRoughnessTexture", map("index", 0), "metallicFactor", 0.5,
                "roughnessFactor", 0.25)));
        Principled p = GltfMaterialsTest.principled(scene);
        for (int i = 0; i < 4; i++) {
            assertThat(valueAt(p.roughness(), i)).as("texel %d", i).isCloseTo(0.25 * linear(i, 1), within(1e-9));
            assertThat(valueAt(p.metallic(), i)).as("texel %d", i).isCloseTo(0.5 * linear(i, 2), within(1e-9));
        }
    }

    @Test
    void emissionIsFactorTimesTexelTimesStrengthChannelByChannel() throws Exception {
        Scene scene = load(map("emissiveTexture", map("index", 0), "emissiveFactor", List.of(1, 0.5, 0.25),
                "extensions", map("KHR_materials_emissive_strength", map("emissiveStrength", 2))));
        double[] f = {1, 0.5, 0.25};
        MutableRgb le = new MutableRgb();
        for (int i = 0; i < 4; i++) {
            World.of(scene).emission(0).eval(new Vector2d(CENTRES[i][0], 1 - CENTRES[i][1]), le);
            assertFactorTimesDecodedTexel(le, 2, f, i);
        }
        assertThat(scene.notes()).noneMatch(n -> n.contains("largest channel"));
        Scene dark = load(map("emissiveTexture", map("index", 0)));          // emissiveFactor defaults to black
        assertThat(dark.materials().get(0).isEmissive()).isFalse();
    }

    @Test
    void transmissionIsFactorTimesRed() throws Exception {
        Scene scene = load(map("extensions", map("KHR_materials_transmission", map("transmissionTexture", map("index", 0), "transmissionFactor", 0.5))));
        TextureLookup t = GltfMaterialsTest.principled(scene).transmission();
        for (int i = 0; i < 4; i++) {
            assertThat(valueAt(t, i)).as("texel %d", i).isCloseTo(0.5 * linear(i, 0), within(1e-9));
        }
        Scene none = load(map("extensions", map("KHR_materials_transmission", map("transmissionTexture", map("index", 0)))));
        assertThat(GltfMaterialsTest.principled(none).transmission().isConstant()).as("the factor's default 0 transmits nothing").isTrue();
        assertThat(valueAt(GltfMaterialsTest.principled(none).transmission(), 0)).isZero();
    }

    @Test
    void specularIsFactorTimesAlphaAndSpecularColourFactorTimesDecodedTexel() throws Exception {
        Scene scene = load(map("extensions", map("KHR_materials_specular", map("specularTexture", map("index", 0), "specularFactor", 0.5,
                "specularColorTexture", map("index", 0), "specularColorFactor", List.of(0.5, 1, 2)))));
        Principled p = GltfMaterialsTest.principled(scene);
        double[] f = {0.5, 1, 2};
        for (int i = 0; i < 4; i++) {
            assertThat(valueAt(p.specular(), i)).as("texel %d", i).isCloseTo(0.5 * linear(i, 3), within(1e-9));
            assertFactorTimesDecodedTexel(colourAt(p.specularColor(), i), 1, f, i);
        }
        assertThat(scene.notes()).noneMatch(n -> n.contains("specularTexture"));
    }

    @Test
    void theCutOutIsTexelAlphaTimesFactorAlphaBelowTheCutoffWhileTheColourTakesTheFactorsRgb() throws Exception {
        Scene scene = load(map("alphaMode", "MASK", "alphaCutoff", 0.25,
                "pbrMetallicRoughness", map("baseColorTexture", map("index", 0), "baseColorFactor", List.of(0.5, 0.5, 0.5, 0.5))));
        // alpha × 0.5 < 0.25 ⇔ alpha < 0.5: texel 2 (alpha 64/255) is cut, texel 1 (128/255 > 0.5) stays
        boolean[] cut = {false, false, true, false};
        for (int i = 0; i < 4; i++) {
            assertThat(World.of(scene).maps(0).cutAway(new Vector2d(CENTRES[i][0], 1 - CENTRES[i][1]))).as("texel %d", i).isEqualTo(cut[i]);
            assertThat(colourAt(GltfMaterialsTest.principled(scene).baseColor(), i).r).isCloseTo(0.5 * decoded(i, 0), within(1e-9));
        }
    }

    /** The strahl-coordinate map of the base colour's KHR_texture_transform. */
    UvTransform transformOf(Map<String, Object> transform) throws Exception {
        Scene scene = load(map("pbrMetallicRoughness", map("baseColorTexture", map("index", 0, "extensions", map("KHR_texture_transform", transform)))));
        return ((ImageTexture) GltfMaterialsTest.principled(scene).baseColor()).transform();
    }

    @Test
    void aQuarterTurnMapsGltfCoordinatesAsTheExtensionSays() throws Exception {
        Scene scene = load(map("pbrMetallicRoughness", map("baseColorTexture",
                map("index", 0, "extensions", map("KHR_texture_transform", map("rotation", Math.PI / 2))))));
        ImageTexture t = (ImageTexture) GltfMaterialsTest.principled(scene).baseColor();
        // glTF: u' = cos r·u + sin r·v = v, v' = −sin r·u + cos r·v = −u.
        // (0.25, 0.75) → (0.75, −0.25): in strahl's coordinates (0.25, 0.25) → (0.75, 1.25)
        assertThat(t.transform().mapU(0.25, 0.25)).isCloseTo(0.75, within(1e-12));
        assertThat(t.transform().mapV(0.25, 0.25)).isCloseTo(1.25, within(1e-12));
        // so texel centre (0.25, 0.75) reads texel (0.75, 0.75) (repeat): texel 3; (0.75, 0.25) → (0.25, −0.75) ≡ texel 0
        int[] reads = {2, 0, 3, 1};
        for (int i = 0; i < 4; i++) {
            MutableRgb c = colourAt(t, i);
            assertThat(c.r).as("texel centre %d reads texel %d", i, reads[i]).isCloseTo(decoded(reads[i], 0), within(1e-9));
            assertThat(c.g).as("texel centre %d reads texel %d", i, reads[i]).isCloseTo(decoded(reads[i], 1), within(1e-9));
        }
        assertThat(scene.notes()).noneMatch(n -> n.contains("rotation"));
    }

    @Test
    void offsetRotationAndScaleCombineAsTranslationTimesRotationTimesScale() throws Exception {
        UvTransform t = transformOf(map("offset", List.of(0.25, 0.5), "rotation", Math.PI / 6, "scale", List.of(2, 0.5)));
        // glTF (0.3, 0.6): scale (0.6, 0.3); rotate: (0.866025·0.6 + 0.5·0.3, −0.5·0.6 + 0.866025·0.3) = (0.669615, −0.040192);
        // offset: (0.919615, 0.459808); strahl's v = 1 − 0.459808 = 0.540192
        assertThat(t.mapU(0.3, 1 - 0.6)).isCloseTo(0.919615, within(1e-6));
        assertThat(t.mapV(0.3, 1 - 0.6)).isCloseTo(0.540192, within(1e-6));
    }

    @Test
    void theReadmesExampleShowsTheLowerLeftQuadrant() throws Exception {
        // KHR_texture_transform's README: offset [0, 1], rotation π/2, scale ½ "utilizes only the lower left quadrant of the source image"
        UvTransform t = transformOf(map("offset", List.of(0, 1), "rotation", 1.57079632679, "scale", List.of(0.5, 0.5)));
        for (double u = 0; u <= 1; u += 0.25) {
            for (double v = 0; v <= 1; v += 0.25) {
                double su = t.mapU(u, v), sv = t.mapV(u, v);      // strahl's (0, 0) is the image's bottom-left corner
                assertThat(su).as("u at (%s, %s)", u, v).isBetween(-1e-9, 0.5 + 1e-9);
                assertThat(sv).as("v at (%s, %s)", u, v).isBetween(-1e-9, 0.5 + 1e-9);
            }
        }
    }

    @Test
    void anOffsetThatOverflowsIsAnErrorWithItsPlace() {
        assertThatThrownBy(() -> transformOf(map("offset", List.of(1e308, 0), "rotation", 1, "scale", List.of(1, 1e308))))
                .isInstanceOf(SceneException.class).hasMessageContaining("factors.gltf: materials[0].pbrMetallicRoughness.baseColorTexture"
                        + ".extensions.KHR_texture_transform: offset and scale too large");
    }

    /** A triangle with TEXCOORD_0 = (0, 0) everywhere and TEXCOORD_1 = (0.5, 0.25) everywhere. */
    static GltfWriter twoSets(Map<String, Object> material) {
        GltfWriter w = new GltfWriter();
        int pos = w.floats("VEC3", GltfReaderTest.TRIANGLE);
        int uv0 = w.floats("VEC2", 0, 0, 0, 0, 0, 0);
        int uv1 = w.floats("VEC2", 0.5f, 0.25f, 0.5f, 0.25f, 0.5f, 0.25f);
        w.add("meshes", map("primitives", List.of(map("attributes", map("POSITION", pos, "TEXCOORD_0", uv0, "TEXCOORD_1", uv1), "material", 0))));
        w.rootNode(map("mesh", 0));
        w.add("materials", material);
        w.add("images", map("uri", "data:image/png;base64," + Base64.getEncoder().encodeToString(new byte[] {1})));
        w.add("textures", map("source", 0));
        return w;
    }

    float[] uvsOf(GltfWriter w, String name) throws Exception {
        GltfDocument doc = GltfDocument.read(w.writeGlb(dir.resolve(name)));
        return new GltfMeshes(doc).mesh(0).get(0).uvs();
    }

    @Test
    void aMaterialWhoseTexturesReadTexcoord1GetsThatSet() throws Exception {
        float[] uvs = uvsOf(twoSets(map("pbrMetallicRoughness", map("baseColorTexture", map("index", 0, "texCoord", 1)),
                "normalTexture", map("index", 0, "texCoord", 1))), "one.glb");
        assertThat(uvs).containsExactly(0.5f, 0.75f, 0.5f, 0.75f, 0.5f, 0.75f);     // TEXCOORD_1, v turned
        float[] override = uvsOf(twoSets(map("emissiveTexture", map("index", 0, "extensions",
                map("KHR_texture_transform", map("texCoord", 1))))), "override.glb");
        assertThat(override).as("KHR_texture_transform's texCoord overrides").containsExactly(0.5f, 0.75f, 0.5f, 0.75f, 0.5f, 0.75f);
        float[] zero = uvsOf(twoSets(map("occlusionTexture", map("index", 0, "texCoord", 1))), "occlusion.glb");
        assertThat(zero).as("occlusion is not read, so its set does not count").containsExactly(0f, 1f, 0f, 1f, 0f, 1f);
    }

    @Test
    void texturesOfDifferentSetsAllReadTheBaseColoursWithANote() throws Exception {
        GltfWriter w = twoSets(map("pbrMetallicRoughness", map("baseColorTexture", map("index", 0, "texCoord", 1)),
                "emissiveTexture", map("index", 0)));
        GltfDocument doc = GltfDocument.read(w.writeGlb(dir.resolve("mixed.glb")));
        assertThat(new GltfMeshes(doc).mesh(0).get(0).uvs()).containsExactly(0.5f, 0.75f, 0.5f, 0.75f, 0.5f, 0.75f);
        assertThat(doc.notes).containsExactly("materials[0]: its textures read TEXCOORD_0 and TEXCOORD_1; strahl keeps one coordinate set"
                + " per mesh, so all read TEXCOORD_1 (the baseColorTexture's)");
    }

    @Test
    void aMissingSetIsAWarning() throws Exception {
        GltfWriter w = twoSets(map("pbrMetallicRoughness", map("baseColorTexture", map("index", 0, "texCoord", 2))));
        GltfDocument doc = GltfDocument.read(w.writeGlb(dir.resolve("missing.glb")));
        assertThat(new GltfMeshes(doc).mesh(0).get(0).uvs()).isNull();
        assertThat(doc.notes).containsExactly("warning: meshes[0].primitives[0] has no TEXCOORD_2, which its material's textures read:"
                + " it has no texture coordinates");
    }

    /** Each channel of {@code c} is scale × f[channel] × the decoded texel i's channel. */
    private static void assertFactorTimesDecodedTexel(MutableRgb c, double scale, double[] f, int i) {
        assertThat(c.r).as("texel %d", i).isCloseTo(scale * f[0] * decoded(i, 0), within(1e-9));
        assertThat(c.g).as("texel %d", i).isCloseTo(scale * f[1] * decoded(i, 1), within(1e-9));
        assertThat(c.b).as("texel %d", i).isCloseTo(scale * f[2] * decoded(i, 2), within(1e-9));
    }
}
