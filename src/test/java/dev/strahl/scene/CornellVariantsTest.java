package dev.strahl.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.world.World;
import dev.strahl.io.SceneLoader;
import dev.strahl.io.obj.MtlReader;
import dev.strahl.io.obj.ObjReaderTest;
import dev.strahl.io.obj.MtlMaterial;
import dev.strahl.image.Image;
import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.material.Bsdf;
import dev.strahl.material.Dielectric;
import dev.strahl.material.Glossy;
import dev.strahl.material.Lambert;
import dev.strahl.material.Mirror;
import dev.strahl.image.Rgb;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.testing.Renders;
import dev.strahl.testing.TestData;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The five Cornell Box variants shipped in scenes/, each checked against the public-domain
 * Williams College data it was authored from (src/test/resources/cornell): DESIGN.md §3's camera, every material by the MTL → BSDF table, every surface's area
 * and bounds, the analytic spheres against the data's tessellated ones, closed boxes, walls
 * facing in and lights facing down, and a small render.
 */
class CornellVariantsTest {

    /**
     * One shipped variant and the data file it follows.
     *
     * @param boxes              materials of the closed boxes
     * @param spheres            materials the data tessellates as spheres and strahl ships as analytic spheres
     * @param misindexedBottoms  box bottoms of the data file that index a side face again (see {@link DataObj})
     */
    record Variant(String name, Path json, String data, double cameraY, double ceiling, double lightY,
                   List<String> boxes, List<String> spheres, int misindexedBottoms) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<Variant> variants() {
        return Stream.of(
            new Variant("original", scene("cornell-box.json"), "Original", 1, 1.99, 1.98,
                    List.of("shortBox", "tallBox"), List.of(), 2),
            new Variant("empty-rg", scene("cornell-empty-rg.json"), "Empty-RG", 1, 1.99, 1.98,
                    List.of(), List.of(), 0),
            new Variant("mirror", scene("cornell-mirror.json"), "Mirror", 1, 1.99, 1.98,
                    List.of("shortBox", "tallBox"), List.of(), 2),
            new Variant("sphere", scene("cornell-sphere.json"), "Sphere", 0.8, 1.59, 1.58,
                    List.of(), List.of("leftSphere", "rightSphere"), 0),
            new Variant("glossy", scene("cornell-glossy.json"), "Glossy", 0.8, 1.59, 1.58,
                    List.of("shortBox"), List.of("sphere"), 0));
    }

    private static final List<String> WALLS = List.of("floor", "ceiling", "backWall", "leftWall", "rightWall");

    // ---- loading and camera ----------------------------------------------------------------------

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void loadsWithoutNotes(Variant v) throws Exception {
        Scene scene = SceneLoader.load(v.json());
        assertThat(scene.notes()).isEmpty();
        assertThat(World.of(scene).environment().constantRadiance()).isEqualTo(Rgb.BLACK);
        assertThat(World.of(scene).lights().isEmpty()).isFalse();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void cameraIsDesigns(Variant v) throws Exception {
        // DESIGN.md §3: Original / Mirror / Empty-RG from (0, 1, 3.9) at (0, 1, 0); Sphere / Glossy
        // from (0, 0.8, 3.9) at (0, 0.8, 0); up +Y, vertical field of view 40°.
        Camera c = SceneLoader.load(v.json()).camera();
        assertThat(c.lookFrom()).isEqualTo(new Vector3d(0, v.cameraY(), 3.9));
        assertThat(c.lookAt()).isEqualTo(new Vector3d(0, v.cameraY(), 0));
        assertThat(c.up()).isEqualTo(new Vector3d(0, 1, 0));
        assertThat(c.fovDegrees()).isEqualTo(40);
    }

    // ---- materials ---------------------------------------------------------------------------------

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void everyMaterialIsTheDataMtlMappedByTheTable(Variant v) throws Exception {
        Scene scene = SceneLoader.load(v.json());
        List<String> warnings = new ArrayList<>();
        Map<String, MtlMaterial> data = MtlReader.read(dataFile(v, ".mtl"), warnings);
        assertThat(warnings).isEmpty();
        assertThat(scene.materials()).extracting(Material::name).containsExactlyInAnyOrderElementsOf(data.keySet());
        for (MtlMaterial m : data.values()) {
            Material shipped = material(scene, m.name());
            assertSameBsdf(shipped.bsdf(), byTable(m), v + "/" + m.name());
            assertSameRgb(shipped.emission(), m.ke(), v + "/" + m.name() + " emission");
        }
    }

    @Test
    void originalAndEmptyRgAreDiffuseWithTheWarmLight() throws Exception {
        for (String file : List.of("cornell-box.json", "cornell-empty-rg.json")) {
            Scene scene = SceneLoader.load(scene(file));
            for (Material m : scene.materials()) {
                assertThat(m.bsdf()).as(file + "/" + m.name()).isInstanceOf(Lambert.class);
            }
            assertThat(material(scene, "light").emission()).isEqualTo(new Rgb(17, 12, 4));
            assertThat(albedo(material(scene, "rightWall"))).isEqualTo(new Rgb(0.14, 0.45, 0.091));   // green
            assertThat(albedo(material(scene, "leftWall"))).isEqualTo(new Rgb(0.63, 0.065, 0.05));    // red
        }
    }

    @Test
    void mirrorVariantsTallBoxIsAMirrorOfReflectance095() throws Exception {
        Scene scene = SceneLoader.load(scene("cornell-mirror.json"));
        assertSameBsdf(material(scene, "tallBox").bsdf(), new Mirror(Rgb.gray(0.95)), "tallBox");
        assertThat(material(scene, "shortBox").bsdf()).isInstanceOf(Lambert.class);
        assertThat(material(scene, "light").emission()).isEqualTo(new Rgb(17, 12, 4));
        assertThat(scene.materials()).filteredOn(m -> !m.name().equals("tallBox"))
                .allSatisfy(m -> assertThat(m.bsdf()).isInstanceOf(Lambert.class));
    }

    @Test
    void sphereVariantHasAMirrorAndAGlassSphereABlueWallAndAWhiteLight() throws Exception {
        Scene scene = SceneLoader.load(scene("cornell-sphere.json"));
        assertThat(scene.materials()).anySatisfy(m -> assertThat(m.bsdf()).isEqualTo(new Mirror(Rgb.gray(0.95))));
        assertThat(material(scene, "leftSphere").bsdf()).isEqualTo(new Mirror(Rgb.gray(0.95)));
        assertThat(material(scene, "rightSphere").bsdf()).isEqualTo(new Dielectric(2.5));
        assertThat(material(scene, "leftSphere").isEmissive()).isFalse();
        assertThat(material(scene, "rightSphere").isEmissive()).isFalse();
        assertSameRgb(albedo(material(scene, "rightWall")), new Rgb(0.161, 0.133, 0.427), "blue right wall");
        assertThat(material(scene, "light").emission()).isEqualTo(new Rgb(10, 10, 10));
    }

    @Test
    void glossyVariantHasAGlossySphereAndFloorNormalisedByKdPlusKs() throws Exception {
        Scene scene = SceneLoader.load(scene("cornell-glossy.json"));
        // sphere: Kd (0.486, 0.631, 0.663) + Ks 0.7 reaches 1.363 in blue; Ns 32
        Glossy sphere = (Glossy) material(scene, "sphere").bsdf();
        assertSameRgb(sphere.diffuse(), new Rgb(0.486, 0.631, 0.663).scale(1 / 1.363), "sphere Kd");
        assertSameRgb(sphere.specular(), Rgb.gray(0.7 / 1.363), "sphere Ks");
        assertThat(sphere.alpha()).isCloseTo(Math.sqrt(2.0 / 34), within(1e-12));
        // floor: Kd (0.725, 0.71, 0.68) + Ks 0.3 reaches 1.025 in red; Ns 80
        Glossy floor = (Glossy) material(scene, "floor").bsdf();
        assertSameRgb(floor.diffuse(), new Rgb(0.725, 0.71, 0.68).scale(1 / 1.025), "floor Kd");
        assertSameRgb(floor.specular(), Rgb.gray(0.3 / 1.025), "floor Ks");
        assertThat(floor.alpha()).isCloseTo(Math.sqrt(2.0 / 82), within(1e-12));
        assertSameRgb(albedo(material(scene, "rightWall")), new Rgb(0.3725, 0.648, 0.3137), "green right wall");
        assertThat(material(scene, "light").emission()).isEqualTo(new Rgb(10, 10, 10));
        for (String diffuse : List.of("ceiling", "backWall", "leftWall", "rightWall", "shortBox", "light")) {
            assertThat(material(scene, diffuse).bsdf()).as(diffuse).isInstanceOf(Lambert.class);
        }
    }

    // ---- geometry ----------------------------------------------------------------------------------

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void everySurfaceCoversTheDataSetsAreaAndBounds(Variant v) throws Exception {
        Scene scene = SceneLoader.load(v.json());
        Geometry g = World.of(scene).geometry();
        DataObj data = DataObj.read(dataFile(v, ".obj"));
        assertThat(data.misindexedBottoms).as("box bottoms of the data that repeat a side face").isEqualTo(v.misindexedBottoms());

        Set<String> triangleMaterials = new TreeSet<>();
        for (int t = 0; t < g.triangleCount(); t++) {
            triangleMaterials.add(nameOf(scene, t));
        }
        Set<String> surfaces = new TreeSet<>(data.groups.keySet());
        surfaces.removeAll(v.spheres());
        assertThat(triangleMaterials).isEqualTo(surfaces);

        for (String name : surfaces) {
            double area = 0;
            Aabb bounds = new Aabb();
            for (int t = 0; t < g.triangleCount(); t++) {
                if (nameOf(scene, t).equals(name)) {
                    area += g.area(t);
                    g.includeBounds(t, bounds);
                }
            }
            DataObj.Group d = data.groups.get(name);
            assertThat(area).as("%s/%s area", v, name).isCloseTo(d.area(), within(1e-4));
            assertThat(corners(bounds)).as("%s/%s bounds", v, name).containsExactly(corners(d.bounds()), within(1e-6));
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void analyticSpheresFitTheDataSetsTessellatedOnes(Variant v) throws Exception {
        Scene scene = SceneLoader.load(v.json());
        Geometry g = World.of(scene).geometry();
        DataObj data = DataObj.read(dataFile(v, ".obj"));
        assertThat(g.sphereCount()).isEqualTo(v.spheres().size());
        for (String name : v.spheres()) {
            List<Integer> prims = new ArrayList<>();
            for (int p = g.triangleCount(); p < g.primitiveCount(); p++) {
                if (nameOf(scene, p).equals(name)) {
                    prims.add(p);
                }
            }
            assertThat(prims).as(name).hasSize(1);
            Aabb box = new Aabb();
            g.includeBounds(prims.get(0), box);
            Vector3d centre = new Vector3d((box.minX + box.maxX) / 2, (box.minY + box.maxY) / 2, (box.minZ + box.maxZ) / 2);
            double radius = (box.maxX - box.minX) / 2;
            List<double[]> cloud = data.groups.get(name).vertices();
            assertThat(cloud).as("distinct vertices of the data's %s", name).hasSize(546);
            for (double[] p : cloud) {
                double off = centre.distance(p[0], p[1], p[2]) - radius;
                assertThat(off).as("%s: data vertex (%s, %s, %s) off the analytic sphere", name, p[0], p[1], p[2])
                        .isCloseTo(0, within(1e-3));
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void boxesAreClosedAndTheRoomAndLightAreNot(Variant v) throws Exception {
        Scene scene = SceneLoader.load(v.json());
        Geometry g = World.of(scene).geometry();
        Set<String> closed = new TreeSet<>(), open = new TreeSet<>();
        for (int t = 0; t < g.triangleCount(); t++) {
            (g.isClosed(t) ? closed : open).add(nameOf(scene, t));
        }
        assertThat(closed).isEqualTo(new TreeSet<>(v.boxes()));
        assertThat(open).containsExactlyInAnyOrder("floor", "ceiling", "backWall", "leftWall", "rightWall", "light");
        for (String box : v.boxes()) {
            assertThat(count(scene, box)).as(box + " triangles (6 quads)").isEqualTo(12);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void wallsFaceInwardsAndTheLightFacesDown(Variant v) throws Exception {
        Scene scene = SceneLoader.load(v.json());
        Geometry g = World.of(scene).geometry();
        Vector3d middle = new Vector3d(0, v.ceiling() / 2, 0);
        SurfacePoint sp = new SurfacePoint();
        Set<String> seen = new HashSet<>();
        for (int t = 0; t < g.triangleCount(); t++) {
            String name = nameOf(scene, t);
            g.samplePoint(t, 0.5, 0.5, sp);
            if (WALLS.contains(name)) {
                Vector3d toMiddle = new Vector3d(middle).sub(sp.p).normalize();
                assertThat(sp.ng.dot(toMiddle)).as("%s/%s triangle %d faces into the room", v, name, t).isPositive();
                seen.add(name);
            } else if (name.equals("light")) {
                assertThat(sp.ng.y).as("light faces down").isCloseTo(-1, within(1e-9));
                assertThat(sp.p.y).isCloseTo(v.lightY(), within(1e-6));
                seen.add(name);
            }
        }
        assertThat(seen).containsExactlyInAnyOrder("floor", "ceiling", "backWall", "leftWall", "rightWall", "light");
        // the ceiling and the light: 1.99 / 1.98 in the Original's room, 1.59 / 1.58 in the lower one
        Aabb ceiling = new Aabb();
        for (int t = 0; t < g.triangleCount(); t++) {
            if (nameOf(scene, t).equals("ceiling")) {
                g.includeBounds(t, ceiling);
            }
        }
        assertThat(ceiling.minY).isCloseTo(v.ceiling(), within(1e-6));
        assertThat(ceiling.maxY).isCloseTo(v.ceiling(), within(1e-6));
    }

    // ---- a render ------------------------------------------------------------------------------------

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void rendersFiniteNotBlackWithABrightLight(Variant v) throws Exception {
        Scene scene = SceneLoader.load(v.json());
        int size = 32;
        Image image = Renders.render(scene, RenderSettings.defaults().withSize(size, size).withSamplesPerPixel(16).withSeed(5));
        for (float x : image.rgb()) {
            assertThat(Float.isFinite(x)).as("finite pixel").isTrue();
            assertThat(x).as("non-negative pixel").isGreaterThanOrEqualTo(0);
        }
        double[] mean = image.mean();
        for (int c = 0; c < 3; c++) {
            assertThat(mean[c]).as("mean of channel %d", c).isGreaterThan(0.02);
        }
        // The pixels around the light's centre: partly covered by the light, which is 10 to 17
        // times brighter than any lit wall.
        double[] px = project(scene.camera(), new Vector3d(-0.005, v.lightY(), -0.03), size, size);
        int cx = (int) px[0], cy = (int) px[1];
        double brightest = 0;
        for (int y = cy - 1; y <= cy + 1; y++) {
            for (int x = cx - 1; x <= cx + 1; x++) {
                brightest = Math.max(brightest, (image.get(x, y, 0) + image.get(x, y, 1) + image.get(x, y, 2)) / 3);
            }
        }
        double imageMean = (mean[0] + mean[1] + mean[2]) / 3;
        assertThat(brightest).as("light region near pixel (%d, %d)", cx, cy).isGreaterThan(2).isGreaterThan(5 * imageMean);
    }

    // ---- helpers ---------------------------------------------------------------------------------------

    private static Path scene(String file) {
        return Path.of("scenes", file);
    }

    private static Path dataFile(Variant v, String extension) {
        return TestData.cornell("CornellBox-" + v.data() + extension);
    }

    /** DESIGN.md §3's MTL → BSDF table, written out independently of the loader. */
    private static Bsdf byTable(MtlMaterial m) {
        if (m.illum() == 5) {
            return new Mirror(m.ks());                                   // Kd, Ns ignored
        }
        if (m.illum() == 7) {
            return new Dielectric(m.ni());                               // Ks, Tf, Kd, Ns ignored
        }
        assertThat(m.illum()).as("illum of %s", m.name()).isLessThanOrEqualTo(2);
        if (m.ks().isBlack()) {
            return new Lambert(m.kd());
        }
        double max = Math.max(m.kd().r() + m.ks().r(), Math.max(m.kd().g() + m.ks().g(), m.kd().b() + m.ks().b()));
        double scale = max > 1 ? 1 / max : 1;
        return new Glossy(m.kd().scale(scale), m.ks().scale(scale), Math.sqrt(2 / (m.ns() + 2)), false);
    }

    /** Same kind of BSDF with the same parameters up to the round-off of parsing and scaling. */
    private static void assertSameBsdf(Bsdf actual, Bsdf expected, String what) {
        assertThat(actual).as(what).isInstanceOf(expected.getClass());
        if (expected instanceof Lambert e) {
            assertSameRgb(((Lambert) actual).albedo().mean(), e.albedo().mean(), what + " albedo");
        } else if (expected instanceof Mirror e) {
            assertSameRgb(((Mirror) actual).reflectance(), e.reflectance(), what + " reflectance");
        } else if (expected instanceof Dielectric e) {
            assertThat(((Dielectric) actual).eta()).as(what + " ior").isCloseTo(e.eta(), within(1e-12));
        } else if (expected instanceof Glossy e) {
            Glossy a = (Glossy) actual;
            assertSameRgb(a.diffuse(), e.diffuse(), what + " diffuse");
            assertSameRgb(a.specular(), e.specular(), what + " specular");
            assertThat(a.alpha()).as(what + " alpha").isCloseTo(e.alpha(), within(1e-12));
        }
    }

    private static void assertSameRgb(Rgb actual, Rgb expected, String what) {
        assertThat(new double[] {actual.r(), actual.g(), actual.b()}).as(what + ": %s vs %s", actual, expected)
                .containsExactly(new double[] {expected.r(), expected.g(), expected.b()}, within(1e-12));
    }

    private static Material material(Scene scene, String name) {
        return scene.materials().stream().filter(m -> m.name().equals(name)).findFirst()
                .orElseThrow(() -> new AssertionError("no material '" + name + "' in " + scene.materials()));
    }

    private static Rgb albedo(Material m) {
        assertThat(m.bsdf()).as(m.name()).isInstanceOf(Lambert.class);
        return ((Lambert) m.bsdf()).albedo().mean();
    }

    private static String nameOf(Scene scene, int prim) {
        return scene.materials().get(World.of(scene).geometry().material(prim)).name();
    }

    private static int count(Scene scene, String name) {
        int n = 0;
        for (int t = 0; t < World.of(scene).geometry().triangleCount(); t++) {
            n += nameOf(scene, t).equals(name) ? 1 : 0;
        }
        return n;
    }

    private static double[] corners(Aabb b) {
        return new double[] {b.minX, b.minY, b.minZ, b.maxX, b.maxY, b.maxZ};
    }

    /** Film position (px, py) of a point, inverting DESIGN.md §3's camera formula. */
    private static double[] project(Camera c, Vector3d p, int width, int height) {
        Vector3d f = new Vector3d(c.lookAt()).sub(c.lookFrom()).normalize();
        Vector3d r = new Vector3d(f).cross(c.up()).normalize();
        Vector3d u = new Vector3d(r).cross(f);
        Vector3d d = new Vector3d(p).sub(c.lookFrom());
        double t = Math.tan(Math.toRadians(c.fovDegrees()) / 2);
        double x = d.dot(r) / d.dot(f) / (t * width / height);
        double y = d.dot(u) / d.dot(f) / t;
        return new double[] {(x + 1) / 2 * width, (1 - y) / 2 * height};
    }

    /**
     * A tiny reader of the data's OBJ files: the faces of each material ({@code usemtl}) as
     * polygons, fan-triangulated as DESIGN.md §3 says. One repair: in the Original and Mirror
     * files each box's last face, meant as its bottom, indexes a side face again
     * ({@code f -12 -11 -10 -9} and {@code f -8 -7 -6 -5}) instead of the four bottom corners
     * declared just before it. A face that repeats an earlier face of its material is read here as
     * the data intends: the last four vertices declared (and they must lie on the floor).
     */
    static final class DataObj {
        record Group(List<double[][]> faces) {
            double area() {
                double a = 0;
                for (double[][] f : faces) {
                    for (int k = 1; k + 1 < f.length; k++) {
                        a += triangleArea(f[0], f[k], f[k + 1]);
                    }
                }
                return a;
            }

            Aabb bounds() {
                Aabb b = new Aabb();
                for (double[][] f : faces) {
                    for (double[] p : f) {
                        b.include(p[0], p[1], p[2]);
                    }
                }
                return b;
            }

            /** The distinct vertex positions of the group. */
            List<double[]> vertices() {
                Map<String, double[]> distinct = new LinkedHashMap<>();
                for (double[][] f : faces) {
                    for (double[] p : f) {
                        distinct.putIfAbsent(p[0] + " " + p[1] + " " + p[2], p);
                    }
                }
                return List.copyOf(distinct.values());
            }
        }

        final Map<String, Group> groups = new LinkedHashMap<>();
        int misindexedBottoms;

        static DataObj read(Path obj) throws IOException {
            DataObj data = new DataObj();
            List<double[]> v = new ArrayList<>();
            Map<String, Set<Set<Integer>>> seen = new LinkedHashMap<>();
            String material = "";
            for (String line : Files.readAllLines(obj)) {
                String[] t = line.strip().split("\\s+");
                switch (t[0]) {
                    case "v" -> v.add(new double[] {Double.parseDouble(t[1]), Double.parseDouble(t[2]), Double.parseDouble(t[3])});
                    case "usemtl" -> material = t[1];
                    case "f" -> {
                        List<Integer> idx = new ArrayList<>();
                        for (int k = 1; k < t.length; k++) {
                            int i = Integer.parseInt(t[k].split("/")[0]);
                            idx.add(i > 0 ? i - 1 : v.size() + i);
                        }
                        if (!seen.computeIfAbsent(material, m -> new HashSet<>()).add(new HashSet<>(idx))) {
                            data.misindexedBottoms++;
                            idx = List.of(v.size() - 4, v.size() - 3, v.size() - 2, v.size() - 1);
                            for (int i : idx) {
                                assertThat(v.get(i)[1]).as("repaired bottom corner on the floor").isZero();
                            }
                        }
                        double[][] face = new double[idx.size()][];
                        for (int k = 0; k < face.length; k++) {
                            face[k] = v.get(idx.get(k));
                        }
                        data.groups.computeIfAbsent(material, m -> new Group(new ArrayList<>())).faces().add(face);
                    }
                    default -> { }
                }
            }
            return data;
        }

        private static double triangleArea(double[] a, double[] b, double[] c) {
            Vector3d e1 = new Vector3d(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
            Vector3d e2 = new Vector3d(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
            return 0.5 * e1.cross(e2).length();
        }
    }
}
