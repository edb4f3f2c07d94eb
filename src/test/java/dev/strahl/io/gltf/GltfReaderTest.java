package dev.strahl.io.gltf;

import static dev.strahl.io.gltf.GltfWriter.map;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.geometry.Geometry;
import dev.strahl.io.SceneLoader;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Transform;
import dev.strahl.world.World;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The glTF reader's geometry, accessors, nodes and cameras, on assets written by {@link GltfWriter}. */
class GltfReaderTest {
    static final float[] TRIANGLE = {0, 0, 0, 1, 0, 0, 0, 1, 0};

    @TempDir
    Path dir;

    /** The scene's triangles as sorted strings of their three corners (rounded), in geometry order. */
    static TreeSet<String> triangles(Scene scene) {
        Geometry g = World.of(scene).geometry();
        float[] p = g.positionArray();
        int[] idx = g.indexArray();
        TreeSet<String> out = new TreeSet<>();
        for (int t = 0; t < g.triangleCount(); t++) {
            StringBuilder s = new StringBuilder();
            for (int k = 0; k < 3; k++) {
                int v = idx[3 * t + k];
                s.append(String.format("(%.3f %.3f %.3f)", round(p[3 * v]), round(p[3 * v + 1]), round(p[3 * v + 2])));
            }
            out.add(s.toString());
        }
        return out;
    }

    private static double round(float x) {
        return Math.round(x * 1000.0) / 1000.0 + 0.0;           // no "-0.000"
    }

    /** The geometric normal of the scene's only triangle (from its winding). */
    static Vector3d normal(Scene scene) {
        Geometry g = World.of(scene).geometry();
        float[] p = g.positionArray();
        int[] i = g.indexArray();
        Vector3d a = new Vector3d(p[3 * i[0]], p[3 * i[0] + 1], p[3 * i[0] + 2]);
        Vector3d b = new Vector3d(p[3 * i[1]], p[3 * i[1] + 1], p[3 * i[1] + 2]).sub(a);
        Vector3d c = new Vector3d(p[3 * i[2]], p[3 * i[2] + 1], p[3 * i[2] + 2]).sub(a);
        return b.cross(c).normalize();
    }

    static GltfWriter quad() {
        GltfWriter w = new GltfWriter();
        int mesh = w.mesh(new float[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, new int[] {0, 1, 2, 0, 2, 3}, null);
        w.rootNode(map("mesh", mesh));
        return w;
    }

    @Test
    void theThreeContainersGiveTheSameTriangles() throws Exception {
        Scene embedded = SceneLoader.load(quad().writeEmbedded(dir.resolve("a.gltf")));
        Scene separate = SceneLoader.load(quad().writeSeparate(dir.resolve("b.gltf"), "b data.bin"));
        Scene glb = SceneLoader.load(quad().writeGlb(dir.resolve("c.GLB")));
        assertThat(triangles(embedded)).hasSize(2);
        assertThat(triangles(separate)).isEqualTo(triangles(embedded));
        assertThat(triangles(glb)).isEqualTo(triangles(embedded));
    }

    @Test
    void everyComponentTypeIsReadAndNormalisedIntegersMapToUnitRanges() throws Exception {
        GltfWriter w = new GltfWriter();
        int[][] cases = {{5120, -128, -127, 0, 127}, {5121, 0, 51, 255, 255}, {5122, -32768, -32767, 0, 32767},
            {5123, 0, 65535, 13107, 0}, {5125, 0, 1, 7, 123456}};
        double[][] normalised = {{-1, -1, 0, 1}, {0, 0.2, 1, 1}, {-1, -1, 0, 1}, {0, 1, 0.2, 0}};
        List<Integer> plain = new ArrayList<>();
        List<Integer> norm = new ArrayList<>();
        for (int[] c : cases) {
            int[] values = java.util.Arrays.copyOfRange(c, 1, 5);
            int view = w.view(GltfWriter.pack(c[0], values), null);
            plain.add(w.add("accessors", map("bufferView", view, "componentType", c[0], "count", 2, "type", "VEC2")));
            norm.add(w.add("accessors", map("bufferView", view, "componentType", c[0], "count", 2, "type", "VEC2", "normalized", true)));
        }
        GltfDocument doc = GltfDocument.read(w.writeGlb(dir.resolve("types.glb")));
        Accessors a = new Accessors(doc);
        for (int i = 0; i < cases.length; i++) {
            float[] got = a.floats(index(doc, plain.get(i)), 2, "TEXCOORD_0");
            for (int k = 0; k < 4; k++) {
                assertThat(got[k]).as("type %d value %d", cases[i][0], k).isEqualTo((float) cases[i][k + 1]);
            }
            if (i < normalised.length) {
                float[] n = a.floats(index(doc, norm.get(i)), 2, "TEXCOORD_0");
                for (int k = 0; k < 4; k++) {
                    assertThat((double) n[k]).as("normalised type %d value %d", cases[i][0], k).isCloseTo(normalised[i][k], within(1e-6));
                }
            }
        }
    }

    /** A JSON number node (as the accessor index a primitive would hold). */
    static GltfJson index(GltfDocument doc, int i) throws SceneException {
        return GltfJson.parse(doc.file, Integer.toString(i).getBytes(), 0, Integer.toString(i).length());
    }

    @Test
    void interleavedViewsAreReadWithTheirStride() throws Exception {
        GltfWriter w = new GltfWriter();
        // position (3 floats) + normal (3 floats) per vertex: stride 24
        float[] interleaved = {0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 0, 1, 0, 2, 0, 0, 0, 1};
        java.nio.ByteBuffer b = java.nio.ByteBuffer.allocate(72).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        for (float f : interleaved) {
            b.putFloat(f);
        }
        int view = w.view(b.array(), 24);
        int pos = w.add("accessors", map("bufferView", view, "componentType", 5126, "count", 3, "type", "VEC3"));
        int nrm = w.add("accessors", map("bufferView", view, "byteOffset", 12, "componentType", 5126, "count", 3, "type", "VEC3"));
        w.add("meshes", map("primitives", List.of(map("attributes", map("POSITION", pos, "NORMAL", nrm)))));
        w.rootNode(map("mesh", 0));
        GltfDocument doc = GltfDocument.read(w.writeEmbedded(dir.resolve("stride.gltf")));
        GltfMeshes.Primitive p = new GltfMeshes(doc).mesh(0).get(0);
        assertThat(p.positions()).containsExactly(0, 0, 0, 2, 0, 0, 0, 2, 0);
        assertThat(p.normals()).containsExactly(0, 0, 1, 0, 0, 1, 0, 0, 1);
        assertThat(p.indices()).containsExactly(0, 1, 2);                      // non-indexed: 0, 1, 2
    }

    @Test
    void sparseAccessorsSubstituteValuesOverTheViewOrOverZeros() throws Exception {
        GltfWriter w = new GltfWriter();
        int base = w.floats("SCALAR", 1, 2, 3, 4, 5);
        int idx = w.view(GltfWriter.pack(5123, 1, 3), null);
        java.nio.ByteBuffer vb = java.nio.ByteBuffer.allocate(8).order(java.nio.ByteOrder.LITTLE_ENDIAN).putFloat(20).putFloat(40);
        int vals = w.view(vb.array(), null);
        Map<String, Object> sparse = map("count", 2, "indices", map("bufferView", idx, "componentType", 5123), "values", map("bufferView", vals));
        @SuppressWarnings("unchecked")
        Map<String, Object> baseAccessor = (Map<String, Object>) w.list("accessors").get(base);
        baseAccessor.put("sparse", sparse);
        int zeros = w.add("accessors", map("componentType", 5126, "count", 4, "type", "SCALAR", "sparse", sparse));
        GltfDocument doc = GltfDocument.read(w.writeGlb(dir.resolve("sparse.glb")));
        Accessors a = new Accessors(doc);
        assertThat(a.floats(index(doc, base), 1, "x")).containsExactly(1, 20, 3, 40, 5);
        assertThat(a.floats(index(doc, zeros), 1, "x")).containsExactly(0, 20, 0, 40);
    }

    @Test
    void stripsAndFansBecomeTriangleListsWithTheirWinding() {
        assertThat(GltfMeshes.triangles(new int[] {0, 1, 2, 3, 4}, 5)).containsExactly(0, 1, 2, 1, 3, 2, 2, 3, 4);
        assertThat(GltfMeshes.triangles(new int[] {0, 1, 2, 3, 4}, 6)).containsExactly(1, 2, 0, 2, 3, 0, 3, 4, 0);
        assertThat(GltfMeshes.triangles(new int[] {0, 1}, 5)).isEmpty();
        assertThat(GltfMeshes.triangles(new int[] {0, 1, 2, 3}, 4)).containsExactly(0, 1, 2);
    }

    @Test
    void stripFanAndListOfOneQuadCoverTheSameSurface() throws Exception {
        float[] square = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        GltfWriter w = new GltfWriter();
        int pos = w.floats("VEC3", square);
        int strip = w.indices(5121, 0, 1, 3, 2);
        int fan = w.indices(5123, 0, 1, 2, 3);
        w.add("meshes", map("primitives", List.of(map("attributes", map("POSITION", pos), "indices", strip, "mode", 5))));
        w.add("meshes", map("primitives", List.of(map("attributes", map("POSITION", pos), "indices", fan, "mode", 6))));
        w.rootNode(map("mesh", 0));
        w.rootNode(map("mesh", 1, "translation", List.of(0, 0, 5)));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("modes.glb")));
        Geometry g = World.of(scene).geometry();
        assertThat(g.triangleCount()).isEqualTo(4);
        double area = 0;
        for (int t = 0; t < 4; t++) {
            area += g.area(t);
        }
        assertThat(area).isCloseTo(2, within(1e-6));
        for (Vector3d n : normals(g)) {
            assertThat(n.z).as("every triangle keeps the counter-clockwise winding").isCloseTo(1, within(1e-9));
        }
    }

    static List<Vector3d> normals(Geometry g) {
        float[] p = g.positionArray();
        int[] i = g.indexArray();
        List<Vector3d> out = new ArrayList<>();
        for (int t = 0; t < g.triangleCount(); t++) {
            Vector3d a = new Vector3d(p[3 * i[3 * t]], p[3 * i[3 * t] + 1], p[3 * i[3 * t] + 2]);
            Vector3d b = new Vector3d(p[3 * i[3 * t + 1]], p[3 * i[3 * t + 1] + 1], p[3 * i[3 * t + 1] + 2]).sub(a);
            Vector3d c = new Vector3d(p[3 * i[3 * t + 2]], p[3 * i[3 * t + 2] + 1], p[3 * i[3 * t + 2] + 2]).sub(a);
            out.add(b.cross(c).normalize());
        }
        return out;
    }

    @Test
    void pointsAndLinesAreSkippedWithOneNote() throws Exception {
        GltfWriter w = new GltfWriter();
        int pos = w.floats("VEC3", TRIANGLE);
        w.add("meshes", map("primitives", List.of(map("attributes", map("POSITION", pos), "mode", 0),
                map("attributes", map("POSITION", pos), "mode", 1), map("attributes", map("POSITION", pos)))));
        w.rootNode(map("mesh", 0));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("lines.glb")));
        assertThat(World.of(scene).geometry().triangleCount()).isEqualTo(1);
        assertThat(scene.notes().stream().filter(n -> n.contains("POINTS and LINES"))).hasSize(1);
    }

    @Test
    void nodesComposeMatricesAndTranslationRotationScaleDownTheHierarchy() throws Exception {
        GltfWriter w = new GltfWriter();
        int mesh = w.mesh(TRIANGLE, null, null);
        double s = Math.sqrt(0.5);
        // child: rotate 90° about z (quaternion (0, 0, sin 45°, cos 45°)), scale 2; parent: a matrix translating by (10, 0, 0)
        int child = w.add("nodes", map("mesh", mesh, "rotation", List.of(0, 0, s, s), "scale", List.of(2, 2, 2)));
        w.rootNode(map("matrix", List.of(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1), "children", List.of(child)));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("nodes.glb")));
        // (1, 0, 0) → scaled (2, 0, 0) → rotated (0, 2, 0) → moved (10, 2, 0); (0, 1, 0) → (−2, 0, 0) → (8, 0, 0)
        assertThat(triangles(scene).first()).contains("(10.000 0.000 0.000)").contains("(10.000 2.000 0.000)").contains("(8.000 0.000 0.000)");
    }

    @Test
    void aMirroringNodeKeepsTheFacesFacingOutwards() throws Exception {
        GltfWriter w = new GltfWriter();
        w.rootNode(map("mesh", w.mesh(TRIANGLE, null, null), "scale", List.of(-1, 1, 1)));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("mirror.glb")));
        assertThat(normal(scene).z).isCloseTo(1, within(1e-9));
    }

    @Test
    void aMeshUsedByTwoNodesIsInstancedAndSaid() throws Exception {
        GltfWriter w = new GltfWriter();
        int mesh = w.mesh(TRIANGLE, null, null);
        w.rootNode(map("mesh", mesh));
        w.rootNode(map("mesh", mesh, "translation", List.of(0, 0, 3)));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("instances.glb")));
        assertThat(World.of(scene).geometry().triangleCount()).isZero();
        assertThat(World.of(scene).uniqueTriangles()).isEqualTo(1);
        assertThat(World.of(scene).instancedTriangles()).isEqualTo(2);
        assertThat(scene.notes()).anyMatch(n -> n.contains("1 mesh is used by several nodes: 2 instances"));
    }

    @Test
    void aMeshUsedByTwoNodesOneOfThemShearedIsCopiedAndTheMemoryNoted() throws Exception {
        GltfWriter w = new GltfWriter();
        int mesh = w.mesh(TRIANGLE, null, null);
        w.rootNode(map("mesh", mesh));
        // A rotated child under a parent scaled unequally: a shear, which an instance's steps cannot give.
        int child = w.add("nodes", map("mesh", mesh, "rotation", List.of(0, 0, 0.3826834, 0.9238795)));
        w.rootNode(map("scale", List.of(2, 1, 1), "children", List.of(child)));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("sheared.glb")));
        assertThat(World.of(scene).geometry().triangleCount()).isEqualTo(2);
        assertThat(World.of(scene).instances().count()).isZero();
        assertThat(scene.notes()).anyMatch(n -> n.contains("copied per node: 2 copies") && n.contains("MiB"));
    }

    @Test
    void theDefaultSceneIsShownOrElseTheFirst() throws Exception {
        GltfWriter w = new GltfWriter();
        int near = w.mesh(TRIANGLE, null, null);
        w.add("nodes", map("mesh", near));
        w.add("nodes", map("mesh", near, "translation", List.of(0, 0, 7)));
        w.add("scenes", map("nodes", List.of(0)));
        w.add("scenes", map("nodes", List.of(1)));
        w.root.put("scene", 1);
        Scene chosen = SceneLoader.load(w.writeEmbedded(dir.resolve("two.gltf")));
        assertThat(triangles(chosen).first()).contains("7.000");
        w.root.remove("scene");
        Scene first = SceneLoader.load(w.writeEmbedded(dir.resolve("first.gltf")));
        assertThat(triangles(first).first()).doesNotContain("7.000");
        assertThat(first.notes()).anyMatch(n -> n.contains("showing scene 0 (the first"));
    }

    @Test
    void thePerspectiveCameraIsUsedAndItsAspectRatioShapesTheFilm() throws Exception {
        GltfWriter w = new GltfWriter();
        w.rootNode(map("mesh", w.mesh(TRIANGLE, null, null)));
        w.add("cameras", map("type", "orthographic", "orthographic", map("xmag", 1, "ymag", 1, "znear", 0.1, "zfar", 10)));
        w.add("cameras", map("type", "perspective", "perspective", map("yfov", Math.toRadians(30), "aspectRatio", 2.0, "znear", 0.1)));
        w.rootNode(map("camera", 0));
        int parent = w.rootNode(map("translation", List.of(0, 0, 5), "children", new ArrayList<>(List.of())));
        int cam = w.add("nodes", map("camera", 1, "translation", List.of(1, 0, 0)));
        @SuppressWarnings("unchecked")
        List<Object> children = (List<Object>) ((Map<String, Object>) w.list("nodes").get(parent)).get("children");
        children.add(cam);
        Path file = w.writeGlb(dir.resolve("camera.glb"));
        Scene scene = SceneLoader.load(file);
        assertThat(scene.camera().fovDegrees()).isCloseTo(30, within(1e-9));
        assertThat(scene.camera().lookFrom().distance(new Vector3d(1, 0, 5))).isLessThan(1e-9);
        assertThat(scene.camera().lookAt().distance(new Vector3d(1, 0, 4))).isLessThan(1e-9);
        assertThat(scene.notes()).anyMatch(n -> n.contains("orthographic camera cameras[0] is not supported"));
        RenderSettings s = SceneLoader.settings(file, RenderSettings.defaults());
        assertThat(s.output().width()).isEqualTo(512);
        assertThat(s.output().height()).isEqualTo(256);
    }

    @Test
    void withoutACameraTheModelIsFramedAndLitByTheStudioSky() throws Exception {
        Path file = quad().writeGlb(dir.resolve("bare.glb"));
        Scene scene = SceneLoader.load(file);
        assertThat(scene.notes()).anyMatch(n -> n.contains("studio"));
        assertThat(SceneLoader.settings(file, RenderSettings.defaults())).isEqualTo(RenderSettings.defaults());
    }

    @Test
    void aSceneFileShapePlacesTheAssetWithItsTransform() throws Exception {
        quad().writeGlb(dir.resolve("quad.glb"));
        Path json = dir.resolve("placed.json");
        java.nio.file.Files.writeString(json, "{\"camera\": {\"lookFrom\": [0, 0, 9], \"lookAt\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 40},"
                + " \"shapes\": [{\"type\": \"gltf\", \"file\": \"quad.glb\", \"transform\": [{\"translate\": [0, 0, 2]}]}]}");
        Scene scene = SceneLoader.load(json);
        assertThat(triangles(scene)).allMatch(t -> t.contains("2.000)"));
        assertThat(scene.camera().lookFrom().z()).isEqualTo(9);
    }

    @Test
    void unknownOptionalExtensionsGetOneNote() throws Exception {
        GltfWriter w = quad();
        w.root.put("extensionsUsed", List.of("EXT_made_up", "KHR_materials_specular"));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("ext.glb")));
        assertThat(scene.notes()).containsOnlyOnce("extension EXT_made_up is not supported: ignored");
        assertThat(scene.notes()).noneMatch(n -> n.contains("KHR_materials_specular"));
    }

    @Test
    void placementComposesWithTheNodes() throws Exception {
        Path file = quad().writeGlb(dir.resolve("q.glb"));
        Scene.Builder b = Scene.builder();
        GltfReader.add(file, Transform.translation(0, 3, 0), b);
        assertThat(triangles(b.build())).allMatch(t -> t.contains("(0.000 3.000 0.000)") || t.contains("(1.000 3.000 0.000)"));
    }

    @Test
    void theFuzzSeedsLoad() throws Exception {
        for (byte[] seed : GltfFuzzSeeds.glb()) {
            Scene scene = SceneLoader.load(java.nio.file.Files.write(dir.resolve("seed.glb"), seed));
            assertThat(World.of(scene).geometry().triangleCount()).isPositive();
        }
        for (byte[] seed : GltfFuzzSeeds.gltf()) {
            Scene scene = SceneLoader.load(java.nio.file.Files.write(dir.resolve("seed.gltf"), seed));
            assertThat(World.of(scene).geometry().triangleCount()).isPositive();
        }
    }

    /** A 20 × 20 Lambertian floor (albedo 0.5) at y = 0, seen straight down through a 1° camera at (0, 1, 0). */
    static GltfWriter litFloor() {
        GltfWriter w = new GltfWriter();
        int floor = w.mesh(new float[] {-10, 0, -10, 10, 0, -10, 10, 0, 10, -10, 0, 10}, new int[] {0, 2, 1, 0, 3, 2}, 0);
        w.add("materials", map("name", "floor", "pbrMetallicRoughness", map("baseColorFactor", List.of(0.5, 0.5, 0.5, 1), "metallicFactor", 0),
                "extensions", map("KHR_materials_specular", map("specularFactor", 0))));
        w.rootNode(map("mesh", floor));
        double h = Math.sqrt(0.5);
        w.add("cameras", map("type", "perspective", "perspective", map("yfov", Math.toRadians(1), "aspectRatio", 1.0)));
        w.rootNode(map("camera", 0, "translation", List.of(0, 1, 0), "rotation", List.of(-h, 0, 0, h)));
        return w;
    }

    @Test
    void punctualLightsLightTheAssetWithoutTheStudioSky() throws Exception {
        GltfWriter w = litFloor();
        w.root.put("extensions", map("KHR_lights_punctual", map("lights", List.of(map("type", "point", "color", List.of(1, 1, 1), "intensity", 8),
                map("type", "spot", "intensity", 3, "spot", map("innerConeAngle", 0.1, "outerConeAngle", 0.4)),
                map("type", "directional", "color", List.of(1, 0.5, 0.25), "intensity", 2)))));
        w.rootNode(map("translation", List.of(0, 2, 0), "extensions", map("KHR_lights_punctual", map("light", 0))));
        Path file = w.writeGlb(dir.resolve("lit.glb"));
        Scene scene = SceneLoader.load(file);
        assertThat(scene.notes()).noneMatch(n -> n.contains("studio"));
        assertThat(World.of(scene).punctualLights()).hasSize(1);
        assertThat(World.of(scene).punctualLights().get(0).toString())
                .isEqualTo(dev.strahl.light.PunctualLight.point(new Vector3d(0, 2, 0), dev.strahl.image.Rgb.gray(8)).toString());
        // E = I / d² = 8 / 4 at the floor below; a Lambertian floor of albedo 0.5 sends L = 0.5/π · 2
        dev.strahl.image.Image img = dev.strahl.testing.Renders.render(scene, RenderSettings.defaults().withSize(4, 4).withSamplesPerPixel(4));
        double mean = 0;
        for (float f : img.rgb()) {
            mean += f / img.rgb().length;
        }
        assertThat(mean).isCloseTo(0.5 / Math.PI * 2, within(0.005));
    }

    /** Every number of a light's description to 9 decimals (no −0). */
    static String rounded(String description) {
        return java.util.regex.Pattern.compile("-?[0-9.]+(E-?[0-9]+)?").matcher(description)
                .replaceAll(m -> String.format(java.util.Locale.ROOT, "%.9f", Double.parseDouble(m.group()) + 0.0).replace("-0.000000000", "0.000000000"));
    }

    @Test
    void spotAndDirectionalLightsAreMovedByTheirNodes() throws Exception {
        GltfWriter w = litFloor();
        w.root.put("extensions", map("KHR_lights_punctual", map("lights", List.of(
                map("type", "spot", "intensity", 3, "spot", map("innerConeAngle", 0.1, "outerConeAngle", 0.4)),
                map("type", "directional", "color", List.of(1, 0.5, 0.25), "intensity", 2, "range", 5)))));
        double h = Math.sqrt(0.5);
        w.rootNode(map("translation", List.of(1, 3, 0), "rotation", List.of(-h, 0, 0, h), "extensions", map("KHR_lights_punctual", map("light", 0))));
        w.rootNode(map("rotation", List.of(0, h, 0, h), "extensions", map("KHR_lights_punctual", map("light", 1))));
        Scene scene = SceneLoader.load(w.writeGlb(dir.resolve("spot.glb")));
        List<String> lights = World.of(scene).punctualLights().stream().map(l -> rounded(l.toString())).toList();
        // the spot looks down (−Z turned by −90° about x is −Y); the directional light travels along −X (−Z turned 90° about y)
        Vector3d down = new Vector3d(0, -1, 0);
        org.joml.Quaterniond q = new org.joml.Quaterniond(-h, 0, 0, h).normalize();
        Vector3d spotDir = q.transform(new Vector3d(0, 0, -1));
        Vector3d sunDir = new org.joml.Quaterniond(0, h, 0, h).normalize().transform(new Vector3d(0, 0, -1));
        assertThat(spotDir.distance(down)).isLessThan(1e-12);
        assertThat(lights).containsExactly(
                rounded(dev.strahl.light.PunctualLight.spot(new Vector3d(1, 3, 0), spotDir, dev.strahl.image.Rgb.gray(3), 0.1, 0.4).toString()),
                rounded(dev.strahl.light.PunctualLight.directional(sunDir, new dev.strahl.image.Rgb(2, 1, 0.5)).toString()));
        assertThat(scene.notes()).anyMatch(n -> n.contains("range is ignored"));
    }

    @Test
    void aSceneFileUsesTheAssetsCameraAndLightsOnlyWhereItHasNone() throws Exception {
        GltfWriter w = litFloor();
        w.root.put("extensions", map("KHR_lights_punctual", map("lights", List.of(map("type", "point", "intensity", 8)))));
        w.rootNode(map("translation", List.of(0, 2, 0), "extensions", map("KHR_lights_punctual", map("light", 0))));
        w.writeGlb(dir.resolve("asset.glb"));
        Path bare = dir.resolve("bare.json");
        java.nio.file.Files.writeString(bare, "{\"shapes\": [{\"type\": \"gltf\", \"file\": \"asset.glb\"}]}");
        Scene taken = SceneLoader.load(bare);
        assertThat(World.of(taken).punctualLights()).hasSize(1);
        assertThat(taken.camera().fovDegrees()).isCloseTo(1, within(1e-9));
        Path own = dir.resolve("own.json");
        java.nio.file.Files.writeString(own, "{\"camera\": {\"lookFrom\": [0, 5, 5], \"lookAt\": [0, 0, 0], \"up\": [0, 1, 0], \"fov\": 30},"
                + " \"environment\": [0.1, 0.1, 0.1], \"shapes\": [{\"type\": \"gltf\", \"file\": \"asset.glb\"}]}");
        Scene kept = SceneLoader.load(own);
        assertThat(World.of(kept).punctualLights()).isEmpty();
        assertThat(kept.camera().fovDegrees()).isEqualTo(30);
    }
}
