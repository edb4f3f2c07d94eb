package dev.strahl.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import dev.strahl.scene.TestScenes;
import dev.strahl.world.World;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.io.obj.ObjReaderTest;
import dev.strahl.image.Image;
import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.material.Lambert;
import dev.strahl.material.Dielectric;
import dev.strahl.material.Glossy;
import dev.strahl.scene.Material;
import dev.strahl.material.Mirror;
import dev.strahl.image.Rgb;
import dev.strahl.render.RenderSettings;
import dev.strahl.testing.Renders;
import dev.strahl.testing.TestData;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class SceneLoaderTest {

    static final Path SHIPPED_OBJ = Path.of("scenes", "cornell-box.obj");
    static final Path SHIPPED_JSON = Path.of("scenes", "cornell-box.json");
    /** The Williams College Cornell Box, from the test resources. */
    static final Path ORIGINAL = TestData.cornell("CornellBox-Original.obj");

    private static final String SQUARE = """
            v 0 0 0
            v 1 0 0
            v 1 1 0
            v 0 1 0
            """;

    @TempDir
    Path dir;

    // ---- the two routes to the shipped Cornell Box -----------------------------------------------

    @Test
    void objAndJsonRoutesGiveTheSameGeometryAndMaterials() throws Exception {
        Scene obj = SceneLoader.load(SHIPPED_OBJ);
        Scene json = SceneLoader.load(SHIPPED_JSON);
        Geometry a = World.of(obj).geometry(), b = World.of(json).geometry();
        assertThat(a.triangleCount()).isEqualTo(b.triangleCount()).isEqualTo(36);   // 18 quads
        assertThat(a.sphereCount()).isEqualTo(b.sphereCount()).isZero();
        assertThat(bounds(a)).containsExactly(bounds(b));
        for (int t = 0; t < a.triangleCount(); t++) {
            assertThat(a.area(t)).as("area of triangle %d", t).isEqualTo(b.area(t));
            assertThat(a.material(t)).as("material of triangle %d", t).isEqualTo(b.material(t));
            assertThat(a.isClosed(t)).as("closed flag of triangle %d", t).isEqualTo(b.isClosed(t));
        }
        assertThat(obj.materials()).isEqualTo(json.materials());
        assertThat(obj.materials()).extracting(Material::name).containsExactly(
                "floor", "ceiling", "backWall", "rightWall", "leftWall", "shortBox", "tallBox", "light");
        assertThat(World.of(obj).environment().constantRadiance()).isEqualTo(World.of(json).environment().constantRadiance()).isEqualTo(Rgb.BLACK);
        assertThat(obj.notes()).isEqualTo(json.notes()).isEmpty();
    }

    @Test
    void objAndJsonRoutesRenderIdenticalImagesWithTheSameCameraAndSeed() throws Exception {
        Scene json = SceneLoader.load(SHIPPED_JSON);
        Scene obj = SceneLoader.load(SHIPPED_OBJ).withCamera(json.camera());
        RenderSettings settings = RenderSettings.defaults().withSize(32, 32).withSamplesPerPixel(8).withSeed(11);
        Image fromJson = Renders.render(json, settings);
        Image fromObj = Renders.render(obj, settings);
        assertThat(fromObj.rgb()).containsExactly(fromJson.rgb());
        assertThat(fromJson.mean()[0]).isPositive();
    }

    @Test
    void shippedMaterialsAreTheOriginalsFigures() throws Exception {
        Scene scene = SceneLoader.load(SHIPPED_JSON);
        Material light = material(scene, "light");
        assertThat(light.emission()).isEqualTo(new Rgb(17, 12, 4));
        assertThat(albedo(light)).isEqualTo(Rgb.gray(0.78));
        assertThat(albedo(material(scene, "leftWall"))).isEqualTo(new Rgb(0.63, 0.065, 0.05));
        assertThat(albedo(material(scene, "rightWall"))).isEqualTo(new Rgb(0.14, 0.45, 0.091));
        assertThat(World.of(scene).lights().isEmpty()).isFalse();
    }

    @Test
    void theBoxesAreMarkedClosedAndTheRoomAndLightAreNot() throws Exception {
        Scene scene = SceneLoader.load(SHIPPED_JSON);
        Geometry g = World.of(scene).geometry();
        Set<String> closed = new TreeSet<>(), open = new TreeSet<>();
        for (int t = 0; t < g.triangleCount(); t++) {
            (g.isClosed(t) ? closed : open).add(scene.materials().get(g.material(t)).name());
        }
        assertThat(closed).containsExactly("shortBox", "tallBox");
        assertThat(open).containsExactlyInAnyOrder("floor", "ceiling", "backWall", "rightWall", "leftWall", "light");
    }

    @Test
    void shippedSceneAndSharedOriginalRenderTheSameImageWithinNoise() throws Exception {
        Scene shipped = SceneLoader.load(SHIPPED_JSON);
        Scene original = SceneLoader.load(ORIGINAL).withCamera(shipped.camera());
        RenderSettings settings = RenderSettings.defaults().withSize(64, 64).withSamplesPerPixel(64);
        // The same seed (common random numbers): the comparison then measures the scenes, not the
        // noise. With independent seeds the mean of one 64x64, 64 spp image alone varies by ~1 %.
        double[] a = Renders.render(shipped, settings.withSeed(1)).mean();
        double[] b = Renders.render(original, settings.withSeed(1)).mean();
        for (int c = 0; c < 3; c++) {
            assertThat(a[c] / b[c] - 1).as("channel %d: %f vs %f", c, a[c], b[c]).isBetween(-0.01, 0.01);
        }
    }

    // ---- MTL → material ----------------------------------------------------------------------------

    @Test
    void kdAboveOneIsClampedWithANote() throws Exception {
        Scene scene = loadObj("newmtl hot\nKd 1.5 0.5 2\n", "hot");
        assertThat(albedo(material(scene, "hot"))).isEqualTo(new Rgb(1, 0.5, 1));
        assertThat(scene.notes()).anySatisfy(n -> assertThat(n).contains("'hot'").contains("Kd").contains("clamped to 1"));
    }

    @Test
    void illumFiveIsAMirrorOfReflectanceKs() throws Exception {
        Scene scene = loadObj("newmtl shiny\nKd 0.3 0.4 0.5\nKs 0.9 0.8 0.7\nillum 5\n", "shiny");
        assertThat(TestScenes.bsdf(material(scene, "shiny"))).isEqualTo(new Mirror(new Rgb(0.9, 0.8, 0.7)));
        assertThat(scene.notes()).noneMatch(n -> n.contains("shiny"));
    }

    @Test
    void illumSevenIsGlassOfIorNi() throws Exception {
        Scene scene = loadObj("newmtl glass\nKd 0.3 0.4 0.5\nKs 1 1 1\nNi 2.5\nillum 7\n", "glass");
        assertThat(TestScenes.bsdf(material(scene, "glass"))).isEqualTo(new Dielectric(2.5));
    }

    @Test
    void illumTwoWithSpecularIsGlossyWithThePhongExponent() throws Exception {
        Scene scene = loadObj("newmtl glossy\nKd 0.3 0.4 0.5\nKs 0.2 0.2 0.2\nNs 80\nillum 2\n", "glossy");
        assertThat(TestScenes.bsdf(material(scene, "glossy"))).isEqualTo(Glossy.fromPhongExponent(new Rgb(0.3, 0.4, 0.5), Rgb.gray(0.2), 80));
    }

    @Test
    void unsupportedIllumIsNotedAndTreatedAsTwo() throws Exception {
        Scene scene = loadObj("newmtl odd\nKd 0.3 0.4 0.5\nillum 3\n", "odd");
        assertThat(albedo(material(scene, "odd"))).isEqualTo(new Rgb(0.3, 0.4, 0.5));
        assertThat(scene.notes()).anySatisfy(n -> assertThat(n).contains("'odd'").contains("illum 3").contains("illum 2"));
    }

    @ParameterizedTest
    @CsvSource({"0", "1", "2"})
    void plainDiffuseMaterialsGiveNoNote(String illum) throws Exception {
        Scene scene = loadObj("newmtl matte\nKd 0.3 0.4 0.5\nKs 0 0 0\nKe 1 1 1\nillum " + illum + "\n", "matte");
        Material m = material(scene, "matte");
        assertThat(albedo(m)).isEqualTo(new Rgb(0.3, 0.4, 0.5));
        assertThat(m.emission()).isEqualTo(Rgb.gray(1));
        assertThat(scene.notes()).isEmpty();
    }

    // ---- notes -------------------------------------------------------------------------------------

    @Test
    void degenerateTrianglesAreSkippedWithANote() throws Exception {
        Path obj = dir.resolve("degenerate.obj");
        Files.writeString(obj, SQUARE + "v 2 0 0\nv 3 0 0\nf 1 2 3\nf 1 2 5\n");   // the second is a segment
        Scene one = SceneLoader.load(obj);
        assertThat(World.of(one).geometry().triangleCount()).isEqualTo(1);
        assertThat(one.notes()).contains("warning: " + obj + ": skipped 1 degenerate triangle (zero area), the first at line 8");

        Files.writeString(obj, SQUARE + "v 2 0 0\nv 3 0 0\nf 1 2 3\nf 1 2 5\nf 1 1 3\n");
        Scene two = SceneLoader.load(obj);
        assertThat(World.of(two).geometry().triangleCount()).isEqualTo(1);
        assertThat(two.notes()).contains("warning: " + obj + ": skipped 2 degenerate triangles (zero area), the first at line 8");
    }

    @Test
    void objWarningsBecomeNotes() throws Exception {
        Path obj = dir.resolve("lines.obj");
        Files.writeString(obj, SQUARE + "f 1 2 3\nl 1 2\n");
        assertThat(SceneLoader.load(obj).notes()).anySatisfy(n -> assertThat(n).contains("lines.obj").contains("'l'").contains("line 6"));
    }

    @Test
    void anObjWithoutLightsIsLitByTheStudioSkyAndFramedFromAboveWithNotes() throws Exception {
        Path obj = dir.resolve("dark.obj");
        Files.writeString(obj, SQUARE + "f 1 2 3 4\n");
        Scene scene = SceneLoader.load(obj);
        assertThat(World.of(scene).environment().toString()).contains("studio-sky");
        assertThat(scene.notes()).containsExactly("the scene has no light and no camera: lighting it with strahl's studio sky"
                + " (a procedural blue sky with a soft sun high at the front left, dark ground) and framing it from a raised"
                + " three-quarter view (azimuth 40° from +Z towards +X, elevation 25°, 40° field of view)");
        // a raised three-quarter view: in front of the square (+Z), to its right (+X) and above its centre
        assertThat(scene.camera().lookAt().x()).isEqualTo(0.5);
        assertThat(scene.camera().lookFrom().z()).isPositive();
        assertThat(scene.camera().lookFrom().x()).isGreaterThan(0.5);
        assertThat(scene.camera().lookFrom().y()).isGreaterThan(scene.camera().lookAt().y());
    }

    // ---- which file, which format ------------------------------------------------------------------

    @Test
    void theExtensionChoosesTheFormatInAnyCase() throws Exception {
        Path obj = dir.resolve("UPPER.OBJ");
        Files.writeString(obj, SQUARE + "f 1 2 3 4\n");
        assertThat(World.of(SceneLoader.load(obj)).geometry().triangleCount()).isEqualTo(2);
        Path json = dir.resolve("Scene.Json");
        Files.writeString(json, "{ \"shapes\": [ { \"type\": \"mesh\", \"file\": \"UPPER.OBJ\" } ] }");
        assertThat(World.of(SceneLoader.load(json)).geometry().triangleCount()).isEqualTo(2);
    }

    @Test
    void unusableFilesAreOneLineErrorsNamingTheFile() throws Exception {
        Path missing = dir.resolve("missing.json");
        assertThat(error(missing)).isEqualTo(missing + ": file not found");
        Path folder = Files.createDirectories(dir.resolve("folder.obj"));
        assertThat(error(folder)).isEqualTo(folder + ": is a directory, not a scene file");
        Path text = dir.resolve("scene.txt");
        Files.writeString(text, SQUARE);
        assertThat(error(text)).isEqualTo(text + ": unknown scene format (expected .json, .obj, .ply, .gltf or .glb)");
        Path noExtension = dir.resolve("scene");
        Files.writeString(noExtension, SQUARE);
        assertThat(error(noExtension)).startsWith(noExtension + ": unknown scene format");
        Path bad = dir.resolve("bad.obj");
        Files.writeString(bad, "v 1 2 x\n");
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneLoader.load(bad));
        assertThat(e.line()).isEqualTo(1);
        assertThat(e.getMessage()).startsWith(bad + ":1: ").doesNotContain("\n");
    }

    // ---- helpers -----------------------------------------------------------------------------------

    /** Loads a one-square OBJ whose faces use material {@code use} of the given MTL text. */
    private Scene loadObj(String mtl, String use) throws IOException, SceneException {
        Files.writeString(dir.resolve("m.mtl"), mtl);
        Path obj = dir.resolve("m.obj");
        Files.writeString(obj, "mtllib m.mtl\n" + SQUARE + "usemtl " + use + "\nf 1 2 3 4\n");
        return SceneLoader.load(obj);
    }

    private static String error(Path file) {
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneLoader.load(file));
        assertThat(e).as("expected a SceneException for %s", file).isNotNull();
        assertThat(e.file()).isEqualTo(file);
        return e.getMessage();
    }

    private static double[] bounds(Geometry g) {
        Aabb b = g.bounds();
        return new double[] {b.minX, b.minY, b.minZ, b.maxX, b.maxY, b.maxZ};
    }

    private static Material material(Scene scene, String name) {
        List<Material> all = scene.materials();
        return all.stream().filter(m -> m.name().equals(name)).findFirst()
                .orElseThrow(() -> new AssertionError("no material '" + name + "' in " + all));
    }

    private static Rgb albedo(Material m) {
        assertThat(TestScenes.bsdf(m)).isInstanceOf(Lambert.class);
        return ((Lambert) TestScenes.bsdf(m)).albedo().mean();
    }
}
