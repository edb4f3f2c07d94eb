package dev.strahl.io.json;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.scene.TestScenes;
import dev.strahl.world.World;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Camera;
import dev.strahl.geometry.Aabb;
import dev.strahl.material.Dielectric;
import dev.strahl.material.Glossy;
import dev.strahl.material.Lambert;
import dev.strahl.scene.Material;
import dev.strahl.material.Mirror;
import dev.strahl.image.Rgb;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
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

class JsonSceneReaderTest {

    private static final String TRIANGLE_OBJ = """
            v 0 0 0
            v 1 0 0
            v 0 1 0
            f 1 2 3
            """;

    @TempDir
    Path dir;

    // ---- every key of the format -----------------------------------------------------------------

    @Test
    void readsEveryKey() throws Exception {
        Files.createDirectories(dir.resolve("models"));
        Files.writeString(dir.resolve("models/tri.obj"), "mtllib tri.mtl\nusemtl red\n" + TRIANGLE_OBJ);
        Files.writeString(dir.resolve("models/tri.mtl"), "newmtl red\nKd 0.5 0.1 0.1\n");
        Scene scene = read("""
                {
                  "camera": { "lookFrom": [1, 2, 10], "lookAt": [1, 2, 0], "up": [1, 0, 0], "fov": 55.5 },
                  "materials": {
                    "lamp": { "type": "diffuse", "albedo": [0.1, 0.2, 0.3], "emission": [4, 5, 6] },
                    "grey": { "type": "diffuse", "albedo": [0.5, 0.5, 0.5] }
                  },
                  "shapes": [
                    { "type": "mesh", "file": "models/tri.obj" },
                    { "type": "sphere", "center": [3, 4, 5], "radius": 0.5, "material": "lamp" },
                    { "type": "sphere", "center": [-3, -4, -5], "radius": 2, "material": "grey" }
                  ],
                  "environment": [0.25, 0.5, 0.75]
                }
                """);

        Camera c = scene.camera();
        assertThat(c.lookFrom()).isEqualTo(new Vector3d(1, 2, 10));
        assertThat(c.lookAt()).isEqualTo(new Vector3d(1, 2, 0));
        assertThat(c.up()).isEqualTo(new Vector3d(1, 0, 0));
        assertThat(c.fovDegrees()).isEqualTo(55.5);

        assertThat(World.of(scene).geometry().triangleCount()).isEqualTo(1);
        assertThat(World.of(scene).geometry().sphereCount()).isEqualTo(2);
        assertThat(World.of(scene).environment().constantRadiance()).isEqualTo(new Rgb(0.25, 0.5, 0.75));

        Material red = material(scene, "red");
        Material lamp = material(scene, "lamp");
        Material grey = material(scene, "grey");
        assertThat(albedo(red)).isEqualTo(new Rgb(0.5, 0.1, 0.1));
        assertThat(red.isEmissive()).isFalse();
        assertThat(albedo(lamp)).isEqualTo(new Rgb(0.1, 0.2, 0.3));
        assertThat(lamp.emission()).isEqualTo(new Rgb(4, 5, 6));
        assertThat(albedo(grey)).isEqualTo(new Rgb(0.5, 0.5, 0.5));
        assertThat(grey.isEmissive()).isFalse();

        // The spheres: centre and radius as given, each with its own material
        var g = World.of(scene).geometry();
        for (int prim = g.triangleCount(); prim < g.primitiveCount(); prim++) {
            Aabb box = new Aabb();
            g.includeBounds(prim, box);
            String name = scene.materials().get(g.material(prim)).name();
            double r = name.equals("lamp") ? 0.5 : 2;
            double sign = name.equals("lamp") ? 1 : -1;
            assertThat((box.maxX - box.minX) / 2).isCloseTo(r, within(1e-12));
            assertThat(new double[] {(box.minX + box.maxX) / 2, (box.minY + box.maxY) / 2, (box.minZ + box.maxZ) / 2})
                    .containsExactly(new double[] {3 * sign, 4 * sign, 5 * sign}, within(1e-12));
        }
        assertThat(World.of(scene).lights().isEmpty()).isFalse();
    }

    @Test
    void materialsMayFollowTheShapesThatUseThem() throws Exception {
        Scene scene = read("""
                {
                  "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" } ],
                  "materials": { "m": { "type": "diffuse", "albedo": [0.2, 0.3, 0.4] } }
                }
                """);
        assertThat(albedo(material(scene, "m"))).isEqualTo(new Rgb(0.2, 0.3, 0.4));
    }

    // ---- defaults --------------------------------------------------------------------------------

    @Test
    void cameraUpDefaultsToPlusYAndFovTo40Degrees() throws Exception {
        Scene scene = read("""
                {
                  "camera": { "lookFrom": [0, 0, 5], "lookAt": [0, 0, 0] },
                  "materials": { "m": { "type": "diffuse" } },
                  "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" } ]
                }
                """);
        assertThat(scene.camera().up()).isEqualTo(new Vector3d(0, 1, 0));
        assertThat(scene.camera().fovDegrees()).isEqualTo(40);
    }

    @Test
    void albedoDefaultsTo08AndEmissionToBlack() throws Exception {
        Scene scene = read("""
                {
                  "materials": { "m": { "type": "diffuse" } },
                  "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" } ]
                }
                """);
        Material m = material(scene, "m");
        assertThat(albedo(m)).isEqualTo(Rgb.gray(0.8));
        assertThat(m.emission()).isEqualTo(Rgb.BLACK);
    }

    @Test
    void withoutCameraOrLightTheSceneIsFramedFromARaisedThreeQuarterView() throws Exception {
        Scene scene = read("""
                {
                  "materials": { "m": { "type": "diffuse" } },
                  "shapes": [ { "type": "sphere", "center": [1, 2, 3], "radius": 1, "material": "m" } ]
                }
                """);
        Camera c = scene.camera();
        assertThat(c.lookAt()).isEqualTo(new Vector3d(1, 2, 3));
        Vector3d dir = new Vector3d(c.lookFrom()).sub(c.lookAt()).normalize();
        assertThat(Math.toDegrees(Math.asin(dir.y))).isCloseTo(25, within(1e-9));
        assertThat(Math.toDegrees(Math.atan2(dir.x, dir.z))).isCloseTo(40, within(1e-9));
        assertThat(c.lookFrom().distance(c.lookAt())).isGreaterThan(1 / Math.sin(Math.toRadians(20)));
    }

    @Test
    void environmentDefaultsToBlackWithLightsAndTheStudioSkyWithoutThemWithANote() throws Exception {
        Scene lit = read("""
                {
                  "materials": { "lamp": { "type": "diffuse", "emission": [1, 1, 1] } },
                  "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "lamp" } ]
                }
                """);
        assertThat(World.of(lit).environment().constantRadiance()).isEqualTo(Rgb.BLACK);
        assertThat(lit.notes()).isEmpty();

        Scene unlit = read("""
                {
                  "materials": { "m": { "type": "diffuse" } },
                  "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" } ]
                }
                """);
        assertThat(World.of(unlit).environment().isConstant()).isFalse();
        assertThat(World.of(unlit).environment().toString()).contains("studio-sky");
        assertThat(unlit.notes()).singleElement().satisfies(n -> assertThat(n).contains("no light").contains("studio sky")
                .contains("no camera").contains("three-quarter"));
    }

    @Test
    void anExplicitEnvironmentIsKeptAndGivesNoNote() throws Exception {
        Scene scene = read("""
                {
                  "materials": { "m": { "type": "diffuse" } },
                  "shapes": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" } ],
                  "environment": [0, 0, 0]
                }
                """);
        assertThat(World.of(scene).environment().constantRadiance()).isEqualTo(Rgb.BLACK);
        assertThat(scene.notes()).isEmpty();
    }

    // ---- material types --------------------------------------------------------------------------

    @Test
    void readsEveryMaterialType() throws Exception {
        Scene scene = read("""
                {
                  "materials": {
                    "silver": { "type": "mirror", "reflectance": [0.95, 0.9, 0.85] },
                    "glass":  { "type": "dielectric", "ior": 2.5 },
                    "paint":  { "type": "glossy", "diffuse": [0.2, 0.3, 0.4], "specular": [0.5, 0.4, 0.3], "exponent": 32 },
                    "panel":  { "type": "glossy", "specular": [0.1, 0.1, 0.1], "exponent": 0, "emission": [2, 3, 4] }
                  },
                  "shapes": [
                    { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "silver" },
                    { "type": "sphere", "center": [3, 0, 0], "radius": 1, "material": "glass" },
                    { "type": "sphere", "center": [6, 0, 0], "radius": 1, "material": "paint" },
                    { "type": "sphere", "center": [9, 0, 0], "radius": 1, "material": "panel" }
                  ]
                }
                """);
        Material silver = material(scene, "silver");
        assertThat(TestScenes.bsdf(silver)).isEqualTo(new Mirror(new Rgb(0.95, 0.9, 0.85)));
        assertThat(silver.isEmissive()).isFalse();

        Material glass = material(scene, "glass");
        assertThat(TestScenes.bsdf(glass)).isEqualTo(new Dielectric(2.5));
        assertThat(glass.isEmissive()).isFalse();

        Material paint = material(scene, "paint");
        assertThat(TestScenes.bsdf(paint)).isEqualTo(Glossy.fromPhongExponent(new Rgb(0.2, 0.3, 0.4), new Rgb(0.5, 0.4, 0.3), 32));
        Glossy g = (Glossy) TestScenes.bsdf(paint);
        assertThat(g.diffuse()).isEqualTo(new Rgb(0.2, 0.3, 0.4));
        assertThat(g.specular()).isEqualTo(new Rgb(0.5, 0.4, 0.3));
        assertThat(g.alpha()).isCloseTo(Math.sqrt(2.0 / 34), within(1e-15));
        assertThat(paint.isEmissive()).isFalse();

        // A glossy emitter: a one-sided area light that also reflects.
        Material panel = material(scene, "panel");
        assertThat(panel.emission()).isEqualTo(new Rgb(2, 3, 4));
        assertThat(((Glossy) TestScenes.bsdf(panel)).alpha()).isEqualTo(1);
        assertThat(World.of(scene).lights().isEmpty()).isFalse();
        assertThat(scene.notes()).isEmpty();
    }

    @Test
    void mirrorReflectanceDefaultsToWhite() throws Exception {
        Scene scene = read("""
                {
                  "materials": { "m": { "type": "mirror" } },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE));
        assertThat(TestScenes.bsdf(material(scene, "m"))).isEqualTo(new Mirror(Rgb.WHITE));
        assertThat(material(scene, "m").emission()).isEqualTo(Rgb.BLACK);
    }

    @Test
    void dielectricIorDefaultsTo15() throws Exception {
        Scene scene = read("""
                {
                  "materials": { "m": { "type": "dielectric" } },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE));
        assertThat(TestScenes.bsdf(material(scene, "m"))).isEqualTo(new Dielectric(1.5));
    }

    @Test
    void glossyDiffuseDefaultsToBlackAndEmissionToBlack() throws Exception {
        Scene scene = read("""
                {
                  "materials": { "m": { "type": "glossy", "specular": [0.7, 0.7, 0.7], "exponent": 100 } },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE));
        Material m = material(scene, "m");
        Glossy g = (Glossy) TestScenes.bsdf(m);
        assertThat(g.diffuse()).isEqualTo(Rgb.BLACK);
        assertThat(g.specular()).isEqualTo(Rgb.gray(0.7));
        assertThat(g.alpha()).isCloseTo(Glossy.alphaFromPhongExponent(100), within(1e-15));
        assertThat(m.emission()).isEqualTo(Rgb.BLACK);
    }

    @Test
    void glossyWithDiffusePlusSpecularAboveOneIsNormalisedLikeTheMtlRoute() throws Exception {
        // The Glossy Cornell sphere: Kd + Ks = 1.363 in blue, so both are divided by 1.363 (DESIGN.md §3).
        Scene scene = read("""
                {
                  "materials": { "m": { "type": "glossy", "diffuse": [0.486, 0.631, 0.663],
                                        "specular": [0.7, 0.7, 0.7], "exponent": 32 } },
                  "shapes": [ %s ],
                  "environment": [1, 1, 1]
                }
                """.formatted(SPHERE));
        Glossy g = (Glossy) TestScenes.bsdf(material(scene, "m"));
        assertThat(g.diffuse().b() + g.specular().b()).isCloseTo(1, within(1e-12));
        assertThat(g.diffuse().r()).isCloseTo(0.486 / 1.363, within(1e-12));
        assertThat(g.specular().g()).isCloseTo(0.7 / 1.363, within(1e-12));
        assertThat(scene.notes()).as("the normalisation is the documented mapping, not a problem").isEmpty();
    }

    // ---- OBJ paths -------------------------------------------------------------------------------

    @Test
    void objPathsAreRelativeToTheSceneFileNotTheWorkingDirectory() throws Exception {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Path models = Files.createDirectories(dir.resolve("models"));
        Files.writeString(models.resolve("tri.obj"), TRIANGLE_OBJ);
        Files.writeString(scenes.resolve("near.obj"), TRIANGLE_OBJ + "v 0 0 1\nf 1 2 4\n");
        Path file = scenes.resolve("scene.json");
        Files.writeString(file, """
                {
                  "shapes": [
                    { "type": "mesh", "file": "../models/tri.obj" },
                    { "type": "mesh", "file": "near.obj" }
                  ]
                }
                """);
        assertThat(Path.of("").toAbsolutePath()).isNotEqualTo(scenes); // the test runs elsewhere
        assertThat(World.of(JsonSceneReader.read(file).scene()).geometry().triangleCount()).isEqualTo(3);
        // the same with a relative path to the scene file
        Path relative = Path.of("").toAbsolutePath().relativize(file);
        assertThat(World.of(JsonSceneReader.read(relative).scene()).geometry().triangleCount()).isEqualTo(3);
    }

    @Test
    void anAbsoluteObjPathIsUsedAsItIs() throws Exception {
        Path obj = dir.resolve("elsewhere/tri.obj");
        Files.createDirectories(obj.getParent());
        Files.writeString(obj, TRIANGLE_OBJ);
        Path sub = Files.createDirectories(dir.resolve("sub"));
        Path file = sub.resolve("scene.json");
        Files.writeString(file, "{ \"shapes\": [ { \"type\": \"mesh\", \"file\": " + quote(obj.toString()) + " } ] }");
        assertThat(World.of(JsonSceneReader.read(file).scene()).geometry().triangleCount()).isEqualTo(1);
    }

    @Test
    void aMissingObjIsAnErrorNamingTheResolvedFile() throws Exception {
        Path sub = Files.createDirectories(dir.resolve("sub"));
        Path file = sub.resolve("scene.json");
        Files.writeString(file, "{ \"shapes\": [ { \"type\": \"mesh\", \"file\": \"nope.obj\" } ] }");
        SceneException e = catchThrowableOfType(SceneException.class, () -> JsonSceneReader.read(file));
        assertThat(e).isNotNull();
        assertThat(e.getMessage()).contains(sub.resolve("nope.obj").toAbsolutePath().toString()).contains("file not found");
    }

    @Test
    void errorsInAnObjAreReportedAtTheObjLine() throws Exception {
        Files.writeString(dir.resolve("bad.obj"), "v 0 0 0\nv 1 2 x\n");
        SceneException e = error("{ \"shapes\": [ { \"type\": \"mesh\", \"file\": \"bad.obj\" } ] }");
        assertThat(e.file().getFileName().toString()).isEqualTo("bad.obj");
        assertThat(e.line()).isEqualTo(2);
        assertThat(e.getMessage()).contains("bad.obj:2: ");
    }

    // ---- errors: file, line and key ------------------------------------------------------------

    private static final String SPHERE = "{ \"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\" }";
    private static final String MATERIALS = "\"materials\": { \"m\": { \"type\": \"diffuse\" } },";

    static Stream<Arguments> badScenes() {
        return Stream.of(
            // malformed JSON
            bad("syntax error", 4, """
                {
                  %s
                  "shapes": [
                    { "type": "sphere", "center": [0, 0, 0] "radius": 1, "material": "m" }
                  ]
                }
                """.formatted(MATERIALS), "malformed JSON"),
            bad("duplicate key", 8, """
                {
                  %s
                  "shapes": [ %s ],
                  "camera": {
                    "lookFrom": [0, 0, 5],
                    "lookAt": [0, 0, 0],
                    "fov": 30,
                    "fov": 40
                  }
                }
                """.formatted(MATERIALS, SPHERE), "malformed JSON", "'fov'"),
            bad("content after the scene", 4, """
                {
                  "shapes": []
                }
                {}
                """, "unexpected content after the end"),
            bad("empty file", 1, "", "empty scene file"),
            bad("root is an array", 1, "[1, 2]\n", "'scene' must be an object, got an array"),
            // unknown keys at every level
            bad("unknown key in scene", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "lamps": []
                }
                """.formatted(MATERIALS, SPHERE), "unknown key 'lamps' in scene", "camera, environment, film, groups, integrator, lights, materials, media, shapes"),
            bad("unknown key in camera", 6, """
                {
                  %s
                  "shapes": [ %s ],
                  "camera": {
                    "lookFrom": [0, 0, 5], "lookAt": [0, 0, 0],
                    "focalLength": 50
                  }
                }
                """.formatted(MATERIALS, SPHERE), "unknown key 'focalLength' in camera"),
            bad("unknown key in a material", 4, """
                {
                  "materials": {
                    "m": { "type": "diffuse",
                           "roughness": 0.2 }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "unknown key 'roughness' in materials.m"),
            bad("unknown key in a sphere", 5, """
                {
                  %s
                  "shapes": [
                    { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m",
                      "colour": [1, 0, 0] }
                  ]
                }
                """.formatted(MATERIALS), "unknown key 'colour' in shapes[] of type sphere"),
            bad("unknown key in an obj shape", 4, """
                {
                  %s
                  "shapes": [
                    { "type": "mesh", "file": "x.obj", "scale": 2 }
                  ]
                }
                """.formatted(MATERIALS), "unknown key 'scale' in shapes[] of type mesh", "exterior, file, interior, material, transform, type"),
            // wrong types
            bad("fov is a string", 5, """
                {
                  %s
                  "shapes": [ %s ],
                  "camera": { "lookFrom": [0, 0, 5], "lookAt": [0, 0, 0],
                              "fov": "40" }
                }
                """.formatted(MATERIALS, SPHERE), "'camera.fov' must be a number, got a string"),
            bad("lookFrom has two numbers", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "camera": { "lookFrom": [0, 5], "lookAt": [0, 0, 0] }
                }
                """.formatted(MATERIALS, SPHERE), "'camera.lookFrom' must have 3 numbers, got 2"),
            bad("camera is an array", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "camera": [0, 0, 5]
                }
                """.formatted(MATERIALS, SPHERE), "'camera' must be an object, got an array"),
            bad("radius is a string", 4, """
                {
                  %s
                  "shapes": [
                    { "type": "sphere", "center": [0, 0, 0], "radius": "1", "material": "m" }
                  ]
                }
                """.formatted(MATERIALS), "'shapes[].radius' must be a number, got a string"),
            bad("centre component is null", 4, """
                {
                  %s
                  "shapes": [
                    { "type": "sphere", "center": [0, null, 0], "radius": 1, "material": "m" }
                  ]
                }
                """.formatted(MATERIALS), "'shapes[].center[1]' must be a number, got null"),
            bad("shapes is an object", 3, """
                {
                  %s
                  "shapes": { "a": %s }
                }
                """.formatted(MATERIALS, SPHERE), "'shapes' must be an array, got an object"),
            bad("a shape is a string", 3, """
                {
                  "shapes": [
                    "sphere"
                  ]
                }
                """, "'shapes[]' must be an object, got a string"),
            bad("materials is an array", 2, """
                {
                  "materials": [ { "type": "diffuse" } ],
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials' must be an object, got an array"),
            bad("shape type is a number", 3, """
                {
                  "shapes": [
                    { "type": 1, "file": "x.obj" }
                  ]
                }
                """, "'shapes[].type' must be a string, got a number"),
            bad("material type is a boolean", 2, """
                {
                  "materials": { "m": { "type": true } },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.type' must be a string, got a boolean"),
            bad("albedo component is a string", 2, """
                {
                  "materials": { "m": { "type": "diffuse", "albedo": [0.5, "0.5", 0.5] } },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.albedo[1]' must be a number, got a string"),
            bad("environment is a number", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "environment": 1
                }
                """.formatted(MATERIALS, SPHERE), "'environment' must be an array, got a number"),
            bad("obj file is a number", 3, """
                {
                  "shapes": [
                    { "type": "mesh", "file": 7 }
                  ]
                }
                """, "'shapes[].file' must be a string, got a number"),
            // missing required keys
            bad("missing shapes", 1, """
                {
                  %s
                  "camera": { "lookFrom": [0, 0, 5], "lookAt": [0, 0, 0] }
                }
                """.formatted(MATERIALS), "missing required key 'shapes'"),
            bad("missing camera.lookAt", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "camera": { "lookFrom": [0, 0, 5] }
                }
                """.formatted(MATERIALS, SPHERE), "missing required key 'lookAt'"),
            bad("missing camera.lookFrom", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "camera": { "lookAt": [0, 0, 5] }
                }
                """.formatted(MATERIALS, SPHERE), "missing required key 'lookFrom'"),
            bad("missing material type", 3, """
                {
                  "materials": {
                    "m": { "albedo": [0.5, 0.5, 0.5] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "missing required key 'type'"),
            bad("missing shape type", 4, """
                {
                  %s
                  "shapes": [
                    { "file": "x.obj" }
                  ]
                }
                """.formatted(MATERIALS), "missing required key 'type'"),
            bad("missing sphere radius", 4, """
                {
                  %s
                  "shapes": [
                    { "type": "sphere", "center": [0, 0, 0], "material": "m" }
                  ]
                }
                """.formatted(MATERIALS), "missing required key 'radius'"),
            bad("missing sphere centre", 4, """
                {
                  %s
                  "shapes": [
                    { "type": "sphere", "radius": 1, "material": "m" }
                  ]
                }
                """.formatted(MATERIALS), "missing required key 'center'"),
            bad("missing sphere material", 4, """
                {
                  %s
                  "shapes": [
                    { "type": "sphere", "center": [0, 0, 0], "radius": 1 }
                  ]
                }
                """.formatted(MATERIALS), "missing required key 'material'"),
            bad("missing obj file", 3, """
                {
                  "shapes": [
                    { "type": "mesh" }
                  ]
                }
                """, "missing required key 'file'"),
            // values out of range
            bad("empty shapes", 3, """
                {
                  %s
                  "shapes": [
                  ]
                }
                """.formatted(MATERIALS), "'shapes' is empty"),
            bad("unknown material type", 3, """
                {
                  "materials": {
                    "m": { "type": "metal" }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "unknown material type 'metal'", "materials.m", "known: conductor, dielectric, diffuse, glossy, mirror, null, principled"),
            bad("unknown shape type", 4, """
                {
                  %s
                  "shapes": [
                    { "type": "cube", "size": 1 }
                  ]
                }
                """.formatted(MATERIALS), "unknown shape type 'cube'", "known: gltf, instance, mesh, sphere, triangles"),
            bad("albedo above 1", 3, """
                {
                  "materials": {
                    "m": { "type": "diffuse", "albedo": [0.5, 1.2, 0.5] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.albedo' must lie in [0, 1]"),
            bad("negative albedo", 3, """
                {
                  "materials": {
                    "m": { "type": "diffuse", "albedo": [0.5, -0.1, 0.5] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.albedo' must not be negative"),
            bad("negative emission", 4, """
                {
                  "materials": {
                    "m": { "type": "diffuse",
                           "emission": [1, 1, -1] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.emission' must not be negative"),
            bad("negative environment", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "environment": [-1, 0, 0]
                }
                """.formatted(MATERIALS, SPHERE), "'environment' must not be negative"),
            bad("colour with four numbers", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "environment": [1, 1, 1, 1]
                }
                """.formatted(MATERIALS, SPHERE), "'environment' must have 3 numbers, got 4"),
            bad("zero radius", 4, """
                {
                  %s
                  "shapes": [
                    { "type": "sphere", "center": [0, 0, 0], "radius": 0, "material": "m" }
                  ]
                }
                """.formatted(MATERIALS), "'shapes[].radius' must be positive, got 0"),
            bad("negative radius", 5, """
                {
                  %s
                  "shapes": [
                    { "type": "sphere", "center": [0, 0, 0],
                      "radius": -1, "material": "m" }
                  ]
                }
                """.formatted(MATERIALS), "'shapes[].radius' must be positive, got -1"),
            bad("unknown material reference", 5, """
                {
                  %s
                  "shapes": [
                    { "type": "sphere", "center": [0, 0, 0], "radius": 1,
                      "material": "gold" }
                  ]
                }
                """.formatted(MATERIALS), "unknown material 'gold'"),
            bad("camera position equals target", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "camera": {
                    "lookFrom": [1, 2, 3], "lookAt": [1, 2, 3]
                  }
                }
                """.formatted(MATERIALS, SPHERE), "bad 'camera'", "coincide"),
            bad("camera up along the view", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "camera": {
                    "lookFrom": [0, 5, 0], "lookAt": [0, 0, 0]
                  }
                }
                """.formatted(MATERIALS, SPHERE), "bad 'camera'", "parallel"),
            bad("fov of 180 degrees", 4, """
                {
                  %s
                  "shapes": [ %s ],
                  "camera": { "lookFrom": [0, 0, 5], "lookAt": [0, 0, 0], "fov": 180 }
                }
                """.formatted(MATERIALS, SPHERE), "bad 'camera'", "field of view"),
            // the material types beyond diffuse
            bad("emission on a mirror", 4, """
                {
                  "materials": {
                    "m": { "type": "mirror",
                           "emission": [1, 1, 1] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.emission'", "a mirror material cannot emit light", "diffuse, glossy and principled"),
            bad("emission on a dielectric", 3, """
                {
                  "materials": {
                    "m": { "type": "dielectric", "ior": 1.5, "emission": [1, 1, 1] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.emission'", "a dielectric material cannot emit light"),
            bad("albedo on a mirror", 4, """
                {
                  "materials": {
                    "m": { "type": "mirror",
                           "albedo": [1, 1, 1] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "unknown key 'albedo' in materials.m of type mirror", "known: reflectance, type"),
            bad("eta instead of ior", 3, """
                {
                  "materials": {
                    "m": { "type": "dielectric", "eta": 1.5 }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "unknown key 'eta' in materials.m of type dielectric", "known: alpha, ior, type"),
            bad("roughness on a glossy material", 4, """
                {
                  "materials": {
                    "m": { "type": "glossy", "specular": [0.5, 0.5, 0.5], "exponent": 10,
                           "roughness": 0.1 }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "unknown key 'roughness' in materials.m of type glossy",
                "known: diffuse, emission, exponent, specular, type"),
            bad("mirror reflectance above 1", 3, """
                {
                  "materials": {
                    "m": { "type": "mirror", "reflectance": [0.9, 1.1, 0.9] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.reflectance' must lie in [0, 1]"),
            bad("negative mirror reflectance", 3, """
                {
                  "materials": {
                    "m": { "type": "mirror", "reflectance": [0.9, -0.1, 0.9] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.reflectance' must not be negative"),
            bad("mirror reflectance is a number", 3, """
                {
                  "materials": {
                    "m": { "type": "mirror", "reflectance": 0.95 }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.reflectance' must be an array, got a number"),
            bad("ior of zero", 4, """
                {
                  "materials": {
                    "m": { "type": "dielectric",
                           "ior": 0 }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.ior' must be positive, got 0"),
            bad("negative ior", 3, """
                {
                  "materials": {
                    "m": { "type": "dielectric", "ior": -1.5 }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.ior' must be positive, got -1.5"),
            bad("ior is a string", 3, """
                {
                  "materials": {
                    "m": { "type": "dielectric", "ior": "glass" }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.ior' must be a number, got a string"),
            bad("glossy without specular", 3, """
                {
                  "materials": {
                    "m": { "type": "glossy", "diffuse": [0.5, 0.5, 0.5], "exponent": 10 }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "missing required key 'specular'"),
            bad("glossy without exponent", 3, """
                {
                  "materials": {
                    "m": { "type": "glossy", "specular": [0.5, 0.5, 0.5] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "missing required key 'exponent'"),
            bad("negative glossy exponent", 5, """
                {
                  "materials": {
                    "m": { "type": "glossy",
                           "specular": [0.5, 0.5, 0.5],
                           "exponent": -2 }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.exponent' must be >= 0, got -2"),
            bad("glossy exponent is an array", 3, """
                {
                  "materials": {
                    "m": { "type": "glossy", "specular": [0.5, 0.5, 0.5], "exponent": [10] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.exponent' must be a number, got an array"),
            bad("glossy specular above 1", 3, """
                {
                  "materials": {
                    "m": { "type": "glossy", "specular": [1.5, 0.5, 0.5], "exponent": 10 }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.specular' must lie in [0, 1]"),
            bad("glossy diffuse above 1", 4, """
                {
                  "materials": {
                    "m": { "type": "glossy", "specular": [0.5, 0.5, 0.5], "exponent": 10,
                           "diffuse": [0.5, 0.5, 2] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.diffuse' must lie in [0, 1]"),
            bad("glossy diffuse with two numbers", 3, """
                {
                  "materials": {
                    "m": { "type": "glossy", "diffuse": [0.5, 0.5], "specular": [0.5, 0.5, 0.5], "exponent": 10 }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.diffuse' must have 3 numbers, got 2"),
            bad("negative glossy emission", 3, """
                {
                  "materials": {
                    "m": { "type": "glossy", "specular": [0.5, 0.5, 0.5], "exponent": 10, "emission": [-1, 0, 0] }
                  },
                  "shapes": [ %s ]
                }
                """.formatted(SPHERE), "'materials.m.emission' must not be negative"));
    }

    private static Arguments bad(String name, int line, String json, String... fragments) {
        return Arguments.of(name, line, json, List.of(fragments));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badScenes")
    void badSceneIsOneErrorWithFileLineAndKey(String name, int line, String json, List<String> fragments) throws Exception {
        Path file = dir.resolve("scene.json");
        SceneException e = error(json);
        assertThat(e.file()).isEqualTo(file);
        assertThat(e.line()).as("line of: %s", e.getMessage()).isEqualTo(line);
        assertThat(e.getMessage()).startsWith(file + ":" + line + ": ");
        for (String f : fragments) {
            assertThat(e.getMessage()).contains(f);
        }
        assertThat(e.getMessage()).doesNotContain("\n");
    }

    @Test
    void invalidUtf8IsNamedAsSuch() throws Exception {
        Path file = dir.resolve("scene.json");
        byte[] text = "{\n  \"shapes\": [],\n  \"x\": \"caf\u00e9\"\n}\n".getBytes(StandardCharsets.ISO_8859_1);
        Files.write(file, text);
        SceneException e = catchThrowableOfType(SceneException.class, () -> JsonSceneReader.read(file));
        assertThat(e).isNotNull();
        assertThat(e.getMessage()).startsWith(file + ":3: ").contains("UTF-8");
    }

    // ---- helpers ---------------------------------------------------------------------------------

    private Scene read(String json) throws IOException, SceneException {
        Path file = dir.resolve("scene.json");
        Files.writeString(file, json);
        return JsonSceneReader.read(file).scene();
    }

    private SceneException error(String json) throws IOException {
        Path file = dir.resolve("scene.json");
        Files.writeString(file, json);
        SceneException e = catchThrowableOfType(SceneException.class, () -> JsonSceneReader.read(file));
        assertThat(e).as("expected a SceneException for:%n%s", json).isNotNull();
        return e;
    }

    private static Material material(Scene scene, String name) {
        return scene.materials().stream().filter(m -> m.name().equals(name)).findFirst()
                .orElseThrow(() -> new AssertionError("no material '" + name + "' in " + scene.materials()));
    }

    private static Rgb albedo(Material m) {
        assertThat(TestScenes.bsdf(m)).isInstanceOf(Lambert.class);
        return ((Lambert) TestScenes.bsdf(m)).albedo().mean();
    }

    private static String quote(String s) {
        return "\"" + s.replace("\\", "\\\\").replace("\"", "\\\"") + "\"";
    }
}
