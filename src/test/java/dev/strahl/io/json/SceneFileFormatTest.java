package dev.strahl.io.json;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.scene.TestScenes;
import dev.strahl.render.PhotonParameters;
import dev.strahl.world.World;
import dev.strahl.scene.SceneException;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.render.IntegratorKind;
import dev.strahl.material.Dielectric;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.light.PunctualLight;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.HemisphereSampling;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/** The keys the scene file gained with the API (film, integrator, mesh, triangles, transform), the writer and the round trip. */
class SceneFileFormatTest {
    /** A scene that uses every key of the format. */
    static final String EVERY_KEY = """
            {
              "camera": { "lookFrom": [0, 1, 5], "lookAt": [0, 1, 0], "up": [0, 1, 0], "fov": 35, "aperture": 0.05, "focusDistance": 4.5 },
              "film": { "width": 320, "height": 200, "aovs": ["albedo", "depth"] },
              "integrator": { "type": "direct", "spp": 12, "maxDepth": 3, "seed": 9007199254740993, "lightSamples": 4,
                              "hemisphere": "uniform", "photons": 2500, "photonRadius": 0.05, "noiseThreshold": 0.02 },
              "materials": {
                "lamp":  { "type": "diffuse", "albedo": [0.5, 0.5, 0.5], "emission": [8, 7, 6] },
                "white": { "type": "diffuse", "albedo": [0.7, 0.7, 0.7] },
                "chrome": { "type": "mirror", "reflectance": [0.9, 0.9, 0.9] },
                "glass": { "type": "dielectric", "ior": 1.33 },
                "paint": { "type": "glossy", "diffuse": [0.4, 0.1, 0.1], "specular": [0.2, 0.2, 0.2], "exponent": 50,
                           "emission": [0.5, 0, 0] }
              },
              "shapes": [
                { "type": "mesh", "file": "tri.obj", "material": "white",
                  "transform": [ { "scale": 2 }, { "rotate": { "axis": [0, 1, 0], "degrees": 90 } }, { "translate": [1, 0, 0] } ] },
                { "type": "mesh", "file": "tri.ply" },
                { "type": "mesh", "file": "tri.obj" },
                { "type": "triangles", "positions": [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0], "indices": [0, 1, 2, 1, 3, 2],
                  "normals": [0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1], "material": "paint",
                  "transform": [ { "scale": [1, 2, 3] }, { "translate": [0, 0, -2] } ] },
                { "type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "lamp", "transform": [ { "translate": [0, 3, 0] } ] },
                { "type": "sphere", "center": [1, 0, 0], "radius": 1, "material": "glass" },
                { "type": "sphere", "center": [-1, 0, 0], "radius": 1, "material": "chrome" }
              ],
              "environment": [0.1, 0.2, 0.3],
              "lights": [
                { "type": "point", "position": [0, 2, 1], "intensity": [5, 5, 4] },
                { "type": "spot", "position": [1, 3, 0], "direction": [0, -1, 0.2], "intensity": [9, 8, 7], "innerCone": 10, "outerCone": 30 },
                { "type": "directional", "direction": [1, -2, 0], "irradiance": [0.5, 0.5, 0.4] }
              ]
            }
            """;

    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.writeString(p, text);
        return p;
    }

    private Path everyKey() throws IOException {
        write("tri.obj", "mtllib tri.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        write("tri.mtl", "newmtl red\nKd 0.5 0.1 0.1\n");
        write("tri.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                + "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 5\n1 0 5\n0 1 5\n3 0 1 2\n");
        return write("every.json", EVERY_KEY);
    }

    @Test
    void everyKeyIsRead() throws Exception {
        SceneFile file = SceneFile.load(everyKey());
        Scene scene = file.scene();
        assertThat(file.settings()).isEqualTo(new SceneSettings(320, 200, 12, 3, 9007199254740993L, IntegratorKind.DIRECT, 4,
                HemisphereSampling.UNIFORM, 2500, 0.05, java.util.Set.of(dev.strahl.render.Aov.ALBEDO, dev.strahl.render.Aov.DEPTH), null, 0.02));
        assertThat(scene.camera().fovDegrees()).isEqualTo(35);
        assertThat(scene.camera().aperture()).isEqualTo(0.05);
        assertThat(scene.camera().focusDistance()).isEqualTo(4.5);
        assertThat(World.of(scene).environment().constantRadiance()).isEqualTo(new Rgb(0.1, 0.2, 0.3));
        assertThat(World.of(scene).punctualLights()).extracting(Object::toString).containsExactly(
                PunctualLight.point(new Vector3d(0, 2, 1), new Rgb(5, 5, 4)).toString(),
                PunctualLight.spot(new Vector3d(1, 3, 0), new Vector3d(0, -1, 0.2), new Rgb(9, 8, 7), Math.toRadians(10),
                        Math.toRadians(30)).toString(),
                PunctualLight.directional(new Vector3d(1, -2, 0), new Rgb(0.5, 0.5, 0.4)).toString());
        Geometry g = World.of(scene).geometry();
        assertThat(g.triangleCount()).isEqualTo(1 + 1 + 1 + 2);
        assertThat(g.sphereCount()).isEqualTo(3);
        // Primitives are found by material: the BVH stores them in its own order.
        // the first OBJ: scaled by 2, turned 90° about +y (x -> -z), moved by +1 in x, all of "white"
        Aabb first = bounds(scene, "white", 1);
        assertThat(new double[] {first.minX, first.maxX, first.minY, first.maxY, first.minZ, first.maxZ})
                .containsExactly(new double[] {1, 1, 0, 2, -2, 0}, within(1e-6));
        bounds(scene, "default", 1);                                      // the PLY without a material
        bounds(scene, "red", 1);                                          // the OBJ with its MTL
        Aabb quad = bounds(scene, "paint", 2);
        assertThat(new double[] {quad.maxX, quad.maxY, quad.minZ}).containsExactly(new double[] {1, 2, -2}, within(1e-6));
        Material paint = scene.materials().stream().filter(m -> m.name().equals("paint")).findFirst().orElseThrow();
        assertThat(paint.emission()).isEqualTo(new Rgb(0.5, 0, 0));
        // the lamp sphere moved up by 3
        Aabb lamp = bounds(scene, "lamp", 1);
        assertThat(g.isTriangle(prims(scene, "lamp").get(0))).isFalse();
        assertThat((lamp.minY + lamp.maxY) / 2).isCloseTo(3, within(1e-9));
        assertThat(scene.materials()).extracting(TestScenes::bsdf).contains(new Dielectric(1.33));
    }

    @Test
    void theSettingsApplyToRenderSettingsAndOnlyWhereGiven() throws Exception {
        SceneSettings file = SceneFile.load(everyKey()).settings();
        RenderSettings s = file.applyTo(RenderSettings.defaults().withThreads(3));
        assertThat(s).isEqualTo(RenderSettings.defaults().withThreads(3).withSize(320, 200).withSamplesPerPixel(12).withMaxDepth(3)
                .withSeed(9007199254740993L).withIntegrator(IntegratorKind.DIRECT).withLightSamples(4)
                .withHemisphere(HemisphereSampling.UNIFORM).withPhotons(new PhotonParameters(2500, 0.05)).withNoiseThreshold(0.02)
                .withAovs(java.util.EnumSet.of(dev.strahl.render.Aov.ALBEDO, dev.strahl.render.Aov.DEPTH)));
        assertThat(SceneSettings.NONE.applyTo(RenderSettings.defaults())).isEqualTo(RenderSettings.defaults());
        RenderSettings halfGiven = new SceneSettings(100, null, null, null, null, null, null, null, null, null)
                .applyTo(RenderSettings.defaults());
        assertThat(halfGiven.output().width()).isEqualTo(100);
        assertThat(halfGiven.output().height()).isEqualTo(512);
        assertThat(file.applyTo(RenderSettings.defaults(), java.util.EnumSet.allOf(SceneSettings.Setting.class)))
                .as("every setting given on the command line").isEqualTo(RenderSettings.defaults());
    }

    @Test
    void anUnknownIntegratorIsRefusedAtItsLineAndTheReaderKnowsEveryIntegrator() throws Exception {
        Path file = write("i.json", "{\n \"integrator\": {\n  \"type\": \"bidir\" },\n " + M + " \"shapes\": [ " + SPHERE + " ] }");
        var e = catchThrowableOfType(SceneException.class, () -> JsonSceneReader.parse(file));
        assertThat(e).hasMessage(file + ":3: 'integrator.type': unknown integrator 'bidir' (known: path, direct, whitted, photon)");
    }

    @Test
    void photonKeysAreOptionalAndAWholeRadiusIsANumber() throws Exception {
        write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        String shapes = "\"shapes\": [ { \"type\": \"mesh\", \"file\": \"tri.obj\" } ] }";
        SceneSettings s = JsonSceneReader.parse(write("p.json", "{ \"integrator\": { \"type\": \"photon\", \"photonRadius\": 1 }, " + shapes)).settings();
        assertThat(s.integrator()).isEqualTo(IntegratorKind.PHOTON);
        assertThat(s.photons()).as("not given").isNull();
        assertThat(s.photonRadius()).isEqualTo(1.0);
        assertThat(s.applyTo(RenderSettings.defaults()).transport().photons())
                .isEqualTo(new dev.strahl.render.PhotonParameters(dev.strahl.render.PhotonParameters.DEFAULT_PHOTONS, 1.0));
        SceneSettings limits = JsonSceneReader.parse(write("q.json", "{ \"integrator\": { \"photons\": 10000000, \"photonRadius\": 0 }, "
                + shapes)).settings();
        assertThat(limits.photons()).isEqualTo(10_000_000);
        assertThat(limits.photonRadius()).isEqualTo(0.0);
        assertThat(limits.applyTo(RenderSettings.defaults()).transport().photons().photonsPerIteration()).isEqualTo(10_000_000);
    }

    @Test
    void everyKeyRoundTripsThroughTheWriter() throws Exception {
        SceneDescription original = JsonSceneReader.parse(everyKey());
        String written = SceneFileWriter.write(original);
        SceneDescription again = JsonSceneReader.parse(write("again.json", written));
        assertThat(again).isEqualTo(original);
        for (String key : List.of("camera", "lookFrom", "lookAt", "up", "fov", "film", "width", "height", "integrator", "type", "spp",
                "maxDepth", "seed", "lightSamples", "hemisphere", "photons", "photonRadius", "materials", "albedo", "emission", "reflectance", "ior",
                "diffuse", "specular", "exponent", "shapes", "file", "material", "transform", "scale", "rotate", "axis", "degrees",
                "translate", "positions", "indices", "normals", "center", "radius", "environment", "lights", "position", "direction",
                "intensity", "irradiance", "innerCone", "outerCone", "aovs", "noiseThreshold")) {
            assertThat(written).as("key %s", key).contains("\"" + key + "\"");
        }
        assertThat(SceneFileWriter.write(again)).isEqualTo(written);
    }

    @ParameterizedTest
    @ValueSource(strings = {"cornell-box", "cornell-empty-rg", "cornell-mirror", "cornell-sphere", "cornell-glossy"})
    void theShippedScenesRoundTrip(String name) throws Exception {
        SceneDescription shipped = JsonSceneReader.parse(Path.of("scenes", name + ".json"));
        Files.copy(Path.of("scenes", name + ".obj"), dir.resolve(name + ".obj"));
        Files.copy(Path.of("scenes", name + ".mtl"), dir.resolve(name + ".mtl"));
        assertThat(JsonSceneReader.parse(write(name + ".json", SceneFileWriter.write(shipped)))).isEqualTo(shipped);
    }

    @Test
    void defaultsAreWrittenOutSoThatTheFileSaysWhatItMeans() throws Exception {
        write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        SceneDescription d = JsonSceneReader.parse(write("min.json", """
                { "materials": { "m": { "type": "mirror" }, "d": { "type": "diffuse" } },
                  "camera": { "lookFrom": [0, 0, 3], "lookAt": [0, 0, 0] },
                  "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" } ] }
                """));
        String written = SceneFileWriter.write(d);
        assertThat(written).contains("\"reflectance\" : [ 1.0, 1.0, 1.0 ]").contains("\"albedo\" : [ 0.8, 0.8, 0.8 ]")
                .contains("\"up\" : [ 0.0, 1.0, 0.0 ]").contains("\"fov\" : 40.0")
                .doesNotContain("film").doesNotContain("integrator").doesNotContain("environment").doesNotContain("transform");
    }

    // ---- errors of the new keys -----------------------------------------------------------------

    private static final String M = "\"materials\": { \"m\": { \"type\": \"diffuse\" } },\n";
    private static final String SPHERE = "{ \"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\" }";

    static Stream<Arguments> badScenes() {
        return Stream.of(
            bad(3, "\"film\": { \"width\": 64, \"depth\": 3 },", "unknown key 'depth' in film (known: aovs, height, width)"),
            bad(3, "\"film\": { \"aovs\": [\"albedo\", \"variance\"] },", "'film.aovs': unknown feature buffer 'variance': use albedo, normal, depth or spp"),
            bad(3, "\"film\": { \"aovs\": [\"depth\", \"depth\"] },", "'film.aovs' names 'depth' twice"),
            bad(3, "\"film\": { \"aovs\": \"albedo\" },", "'film.aovs' must be an array, got a string"),
            bad(3, "\"lights\": { \"type\": \"point\" },", "'lights' must be an array, got an object"),
            bad(3, "\"lights\": [ { \"type\": \"area\" } ],", "unknown light type 'area' (known: directional, point, spot)"),
            bad(3, "\"lights\": [ { \"type\": \"point\", \"intensity\": [1, 1, 1] } ],", "missing required key 'position'"),
            bad(3, "\"lights\": [ { \"type\": \"point\", \"position\": [0, 1, 0], \"intensity\": [1, 1, 1], \"direction\": [0, 1, 0] } ],",
                    "unknown key 'direction' in lights[0] of type point (known: intensity, position, type)"),
            bad(3, "\"lights\": [ { \"type\": \"point\", \"position\": [0, 1, 0], \"intensity\": [1, -1, 1] } ],",
                    "'lights[0].intensity' must not be negative"),
            bad(3, "\"lights\": [ { \"type\": \"directional\", \"direction\": [0, 0, 0], \"irradiance\": [1, 1, 1] } ],",
                    "'lights[0].direction' must be a non-zero vector of finite length"),
            bad(3, "\"lights\": [ { \"type\": \"spot\", \"position\": [0, 1, 0], \"direction\": [0, -1, 0], \"intensity\": [1, 1, 1], \"outerCone\": 95 } ],",
                    "'lights[0].outerCone' must lie in (0, 90] degrees, got 95"),
            bad(3, "\"lights\": [ { \"type\": \"spot\", \"position\": [0, 1, 0], \"direction\": [0, -1, 0], \"intensity\": [1, 1, 1], \"innerCone\": 50 } ],",
                    "'lights[0].innerCone' must lie in [0, outerCone] = [0, 45] degrees, got 50"),
            bad(3, "\"film\": [64, 64],", "'film' must be an object, got an array"),
            bad(3, "\"film\": { \"width\": 64.5 },", "'film.width' must be a whole number, got 64.5"),
            bad(3, "\"film\": { \"height\": 0 },", "'film.height' must be in [1, 32768], got 0"),
            bad(3, "\"film\": { \"width\": \"wide\" },", "'film.width' must be a number, got a string"),
            bad(3, "\"integrator\": { \"samples\": 4 },",
                    "unknown key 'samples' in integrator (known: hemisphere, lightSamples, maxDepth, noiseThreshold, photonRadius, photons, seed, spp, type)"),
            bad(3, "\"integrator\": { \"spp\": 0 },", "'integrator.spp' must be >= 1, got 0"),
            bad(3, "\"integrator\": { \"noiseThreshold\": -0.01 },", "'integrator.noiseThreshold' must be 0 (none) or in (0, 1] (0.01 = 1 %), got -0.01"),
            bad(3, "\"integrator\": { \"noiseThreshold\": 1.5 },", "'integrator.noiseThreshold' must be 0 (none) or in (0, 1] (0.01 = 1 %), got 1.5"),
            bad(3, "\"integrator\": { \"noiseThreshold\": \"low\" },", "'integrator.noiseThreshold' must be a number, got a string"),
            bad(3, "\"integrator\": { \"maxDepth\": 0 },", "'integrator.maxDepth' must be -1 (unbounded) or >= 1, got 0"),
            bad(3, "\"integrator\": { \"maxDepth\": -2 },", "'integrator.maxDepth' must be >= -1, got -2"),
            bad(3, "\"integrator\": { \"seed\": 1.5 },", "'integrator.seed' must be a whole number, got 1.5"),
            bad(3, "\"integrator\": { \"lightSamples\": 0 },", "'integrator.lightSamples' must be >= 1, got 0"),
            bad(3, "\"integrator\": { \"hemisphere\": \"stratified\" },", "'integrator.hemisphere' must be \"cosine\" or \"uniform\", got 'stratified'"),
            bad(3, "\"integrator\": { \"type\": 3 },", "'integrator.type' must be a string, got a number"),
            bad(3, "\"integrator\": { \"photons\": 0 },", "'integrator.photons' must be in [1, 10000000], got 0"),
            bad(3, "\"integrator\": { \"photons\": 10000001 },", "'integrator.photons' must be in [1, 10000000], got 10000001"),
            bad(3, "\"integrator\": { \"photons\": 2.5 },", "'integrator.photons' must be a whole number, got 2.5"),
            bad(3, "\"integrator\": { \"photons\": \"many\" },", "'integrator.photons' must be a number, got a string"),
            bad(3, "\"integrator\": { \"photonRadius\": -0.1 },", "'integrator.photonRadius' must be >= 0 (0 = automatic), got -0.1"),
            bad(3, "\"integrator\": { \"photonRadius\": 1e999 },", "'integrator.photonRadius' must be finite, got Infinity"),
            bad(3, "\"integrator\": { \"photonRadius\": [0.1] },", "'integrator.photonRadius' must be a number, got an array"),
            shape("{ \"type\": \"triangles\", \"positions\": [0, 0, 0, 1, 0], \"indices\": [0, 1, 2], \"material\": \"m\" }",
                    "'shapes[].positions' must hold x, y, z triples, got 5 numbers"),
            shape("{ \"type\": \"triangles\", \"positions\": [0, 0, 0, 1, 0, 0, 0, 1, 0], \"indices\": [0, 1, 3], \"material\": \"m\" }",
                    "'shapes[].indices[2]' = 3 is out of range (there are 3 vertices)"),
            shape("{ \"type\": \"triangles\", \"positions\": [0, 0, 0, 1, 0, 0, 0, 1, 0], \"indices\": [0, 1], \"material\": \"m\" }",
                    "'shapes[].indices' must hold three vertex indices per triangle, got 2"),
            shape("{ \"type\": \"triangles\", \"positions\": [0, 0, 0, 1, 0, 0, 0, 1, 0], \"indices\": [0, 1, 2.5], \"material\": \"m\" }",
                    "'shapes[].indices[2]' must be a whole number, got 2.5"),
            shape("{ \"type\": \"triangles\", \"positions\": [0, 0, 0, 1, 0, 0, 0, 1, 0], \"indices\": [0, 1, 2], \"normals\": [0, 0, 1],"
                    + " \"material\": \"m\" }", "'shapes[].normals' must have one x, y, z triple per vertex: 3 numbers for 3 vertices"),
            shape("{ \"type\": \"triangles\", \"positions\": [0, 0, 0, 1, 0, 0, 0, 1, 0], \"indices\": [0, 1, 2] }", "missing required key 'material'"),
            shape("{ \"type\": \"triangles\", \"positions\": [0, 0, 0, 1e39, 0, 0, 0, 1, 0], \"indices\": [0, 1, 2], \"material\": \"m\" }",
                    "'shapes[].positions' must fit into floats, got Infinity"),
            shape("{ \"type\": \"triangles\", \"positions\": [0, 0, 0, 1, 0, 0, 0, 1, 0], \"indices\": [0, 1, 2], \"material\": \"n\" }",
                    "unknown material 'n' (define it under 'materials')"),
            shape("{ \"type\": \"mesh\", \"file\": \"tri.stl\" }", "'shapes[].file' must name an .obj or .ply file, got 'tri.stl'"),
            shape("{ \"type\": \"mesh\", \"file\": \"none.ply\" }", "mesh file not found: "),
            shape("{ \"type\": \"cube\" }", "unknown shape type 'cube' (known: gltf, instance, mesh, sphere, triangles)"),
            transform("{ \"translate\": [1, 2, 3] }", "'shapes[].transform' must be an array, got an object"),
            transform("[ { \"translate\": [1, 2, 3], \"scale\": 2 } ]",
                    "each step of 'shapes[].transform' must have exactly one key of rotate, scale, translate, got scale, translate"),
            transform("[ {} ]", "each step of 'shapes[].transform' must have exactly one key of rotate, scale, translate, got none"),
            transform("[ { \"shear\": 2 } ]", "unknown key 'shear' in shapes[].transform[] (known: rotate, scale, translate)"),
            transform("[ { \"translate\": [1, 2] } ]", "'shapes[].transform[].translate' must have 3 numbers, got 2"),
            transform("[ { \"scale\": 0 } ]", "bad 'shapes[].transform[].scale': scale factors must not be zero, got (0.0, 0.0, 0.0)"),
            transform("[ { \"rotate\": { \"axis\": [0, 0, 0], \"degrees\": 30 } } ]", "bad 'shapes[].transform[].rotate': the rotation axis must not be zero"),
            transform("[ { \"rotate\": { \"axis\": [0, 1, 0] } } ]", "missing required key 'degrees'"),
            transform("[ { \"rotate\": { \"axis\": [0, 1, 0], \"degrees\": 30, \"about\": [0, 0, 0] } } ]",
                    "unknown key 'about' in shapes[].transform[].rotate (known: axis, degrees)"),
            transform("[ { \"scale\": [1, 2, 1] } ]",
                    "'shapes[].transform': a sphere can only be translated, rotated and scaled uniformly; this transform scales its axes by 1.0, 2.0 and 1.0"));
    }

    private static Arguments bad(int line, String topLevel, String fragment) {
        return Arguments.of("{\n" + M + topLevel + "\n\"shapes\": [ " + SPHERE + " ]\n}\n", line, fragment);
    }

    private static Arguments shape(String shape, String fragment) {
        return Arguments.of("{\n" + M + "\"shapes\": [\n" + shape + "\n] }\n", 4, fragment);
    }

    private static Arguments transform(String transform, String fragment) {
        return Arguments.of("{\n" + M + "\"shapes\": [\n" + SPHERE.replace(" }", ", \"transform\": " + transform + " }") + "\n] }\n", 4, fragment);
    }

    @ParameterizedTest(name = "{2}")
    @MethodSource("badScenes")
    void badNewKeysAreOneErrorWithFileLineAndKey(String json, int line, String fragment) throws Exception {
        Path file = write("bad.json", json);
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneLoader.load(file));
        assertThat(e).as(json).isNotNull();
        assertThat(e.getMessage()).startsWith(file + ":" + line + ": ").contains(fragment);
        assertThat(e.line()).isEqualTo(line);
    }

    // ---- helpers --------------------------------------------------------------------------------

    private static Aabb bounds(Geometry g, int prim) {
        Aabb box = new Aabb();
        g.includeBounds(prim, box);
        return box;
    }

    private static String name(Scene scene, int prim) {
        return scene.materials().get(World.of(scene).geometry().material(prim)).name();
    }

    /** The primitives made of the named material. */
    private static java.util.List<Integer> prims(Scene scene, String material) {
        java.util.List<Integer> out = new java.util.ArrayList<>();
        for (int p = 0; p < World.of(scene).geometry().primitiveCount(); p++) {
            if (name(scene, p).equals(material)) {
                out.add(p);
            }
        }
        return out;
    }

    /** The bounds of the {@code count} primitives made of the named material (there must be exactly that many). */
    private static Aabb bounds(Scene scene, String material, int count) {
        java.util.List<Integer> list = prims(scene, material);
        assertThat(list).as("primitives of %s", material).hasSize(count);
        Aabb box = new Aabb();
        for (int p : list) {
            World.of(scene).geometry().includeBounds(p, box);
        }
        return box;
    }
}
