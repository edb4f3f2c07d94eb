package dev.strahl.io.json;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import dev.strahl.io.SceneLoader;
import dev.strahl.medium.GridMedium;
import dev.strahl.medium.HomogeneousMedium;
import dev.strahl.medium.VolFiles;
import dev.strahl.image.Rgb;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.world.Media;
import dev.strahl.world.World;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The scene file's participating media, the interface of issue 29 word for word: {@code media}
 * with {@code homogeneous} ({@code sigmaT} a number or RGB, {@code scale}, {@code albedo},
 * {@code g}) and {@code grid} ({@code file}, {@code bounds}) entries, the {@code null} material,
 * each shape's {@code interior} and {@code exterior}, and {@code "camera": {"medium": ...}}; the
 * round trip through the writer; and every bad value as one error naming the file, the line and
 * the key (and the {@code .vol} file where that is at fault).
 */
class MediaSceneFileTest {
    static final String SCENE = """
            {
              "camera": { "lookFrom": [0, 1, 5], "lookAt": [0, 1, 0], "medium": "fog" },
              "media": {
                "fog":   { "type": "homogeneous", "sigmaT": 0.6, "albedo": [0.85, 0.85, 0.85], "g": 0.4 },
                "tint":  { "type": "homogeneous", "sigmaT": [1.0, 0.375, 0.104], "scale": 2.4, "albedo": 0 },
                "smoke": { "type": "grid", "file": "smoke.vol", "bounds": [[-0.5, 0, -0.5], [0.5, 1, 0.5]],
                           "scale": 9, "albedo": 0.9, "g": 0.3 },
                "haze":  { "type": "grid", "file": "smoke.vol" },
                "air":   { "type": "homogeneous" }
              },
              "materials": { "boundary": { "type": "null" }, "glass": { "type": "dielectric", "ior": 1.5 },
                             "white": { "type": "diffuse", "albedo": [0.7, 0.7, 0.7] } },
              "shapes": [
                { "type": "triangles", "positions": [-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1], "indices": [0, 2, 1, 0, 3, 2],
                  "material": "boundary", "interior": "smoke", "exterior": "fog" },
                { "type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "glass", "interior": "tint" },
                { "type": "sphere", "center": [2, 0.5, 0], "radius": 0.5, "material": "glass", "exterior": "haze" },
                { "type": "sphere", "center": [-2, 0.5, 0], "radius": 0.5, "material": "white" }
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

    private void smokeVol() throws IOException {
        VolFiles.write(dir.resolve("smoke.vol"), 2, 2, 2, new float[] {-1, -1, -1, 1, 2, 1}, new float[] {0, 1, 2, 3, 4, 5, 6, 7});
    }

    @Test
    void everyMediaKeyIsRead() throws Exception {
        smokeVol();
        Scene scene = SceneLoader.load(write("media.json", SCENE));
        Media media = World.of(scene).media();
        assertThat(media.count()).isEqualTo(5);
        assertThat(media.medium(4)).as("Mitsuba's defaults: sigma_t 1, albedo 0.75, isotropic").isEqualTo(new HomogeneousMedium(Rgb.WHITE, Rgb.gray(0.75), 0));
        assertThat(media.medium(0)).isEqualTo(new HomogeneousMedium(Rgb.gray(0.6), Rgb.gray(0.85), 0.4));
        assertThat(media.medium(1)).isEqualTo(new HomogeneousMedium(new Rgb(2.4, 0.375 * 2.4, 0.104 * 2.4), Rgb.BLACK, 0));
        GridMedium smoke = (GridMedium) media.medium(2);
        assertThat(smoke.albedo()).isEqualTo(Rgb.gray(0.9));
        assertThat(smoke.g()).isEqualTo(0.3);
        assertThat(smoke.sigmaT(0.25, 0.75, 0.25)).as("voxel (1, 1, 1) of the bounds, x 9").isEqualTo(9 * 7, org.assertj.core.api.Assertions.within(1e-9));
        GridMedium haze = (GridMedium) media.medium(3);
        assertThat(haze.sigmaT(0.5, 1.5, 0.5)).as("voxel (1, 1, 1) of the header's box, scale 1").isEqualTo(7, org.assertj.core.api.Assertions.within(1e-9));
        assertThat(haze.g()).isZero();
        assertThat(haze.albedo()).as("Mitsuba's default albedo").isEqualTo(Rgb.gray(0.75));
        assertThat(media.camera()).isZero();
        int boundary = material(scene, "boundary");
        assertThat(media.isInvisible(boundary)).isTrue();
        assertThat(media.after(boundary, 0, -0.5)).as("into the quad against its normal: the smoke").isEqualTo(2);
        assertThat(media.after(boundary, 2, 0.5)).as("out of it: the fog").isZero();
        int white = material(scene, "white");
        assertThat(media.isInvisible(white)).isFalse();
        assertThat(media.after(white, 3, -1)).as("a shape without interior and exterior leaves the medium as it is").isEqualTo(3);
        List<Integer> glass = materials(scene, "glass");
        assertThat(glass).as("glass bounds two different pairs of media: a material index each").hasSize(2);
        assertThat(glass.stream().map(m -> media.after(m, 0, -1)).toList()).containsExactlyInAnyOrder(1, -1);
        assertThat(glass.stream().map(m -> media.after(m, 0, 1)).toList()).containsExactlyInAnyOrder(-1, 3);
    }

    @Test
    void theMediaRoundTripThroughTheWriter() throws Exception {
        smokeVol();
        SceneDescription original = JsonSceneReader.parse(write("media.json", SCENE));
        String written = SceneFileWriter.write(original);
        assertThat(JsonSceneReader.parse(write("again.json", written))).isEqualTo(original);
        for (String key : List.of("media", "type", "sigmaT", "scale", "albedo", "g", "file", "bounds", "interior", "exterior", "medium", "null")) {
            assertThat(written).as("key %s", key).contains("\"" + key + "\"");
        }
    }

    static final String M = "\"materials\": { \"b\": { \"type\": \"null\" } },\n";
    static final String SHAPE = "\"shapes\": [ { \"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"b\", \"interior\": \"m\" } ]";

    static Stream<Arguments> badScenes() {
        return Stream.of(
                medium("{ \"type\": \"homogeneous\", \"sigmaT\": -0.5 }", "'media.m.sigmaT' must be >= 0, got -0.5"),
                medium("{ \"type\": \"homogeneous\", \"sigmaT\": [1, -1, 1] }", "'media.m.sigmaT' must not be negative"),
                medium("{ \"type\": \"homogeneous\", \"sigmaT\": 1e308, \"scale\": 1e10 }", "'media.m.sigmaT' times 'scale' must be finite"),
                medium("{ \"type\": \"homogeneous\", \"sigmaT\": 1, \"albedo\": 1.2 }", "'media.m.albedo' must lie in [0, 1], got (1.2, 1.2, 1.2)"),
                medium("{ \"type\": \"homogeneous\", \"sigmaT\": 1, \"albedo\": [0.5, 1.5, 0.5] }", "'media.m.albedo' must lie in [0, 1]"),
                medium("{ \"type\": \"homogeneous\", \"sigmaT\": 1, \"g\": 1 }", "'media.m.g' (the phase function's asymmetry) must lie in (-1, 1), got 1"),
                medium("{ \"type\": \"homogeneous\", \"sigmaT\": 1, \"g\": -1.5 }", "must lie in (-1, 1), got -1.5"),
                medium("{ \"type\": \"homogeneous\", \"sigmaT\": 1, \"scale\": -2 }", "'media.m.scale' must be >= 0, got -2"),
                medium("{ \"type\": \"homogeneous\", \"sigmaT\": 1, \"density\": 2 }", "unknown key 'density'"),
                medium("{ \"type\": \"fog\", \"sigmaT\": 1 }", "unknown medium type 'fog' for 'media.m' (known: grid, homogeneous)"),
                medium("{ \"type\": \"grid\" }", "missing required key 'file'"),
                medium("{ \"type\": \"grid\", \"file\": \"none.vol\" }", "volume file not found: "),
                medium("{ \"type\": \"grid\", \"file\": \"smoke.raw\" }", "'media.m.file' must name a Mitsuba .vol file, got 'smoke.raw'"),
                medium("{ \"type\": \"grid\", \"file\": \"smoke.vol\", \"bounds\": [[0, 0, 0]] }", "'media.m.bounds' must be two corners"),
                medium("{ \"type\": \"grid\", \"file\": \"smoke.vol\", \"bounds\": [[0, 0, 0], [1, 0, 1]] }", "must have min < max on every axis"),
                Arguments.of("{\n" + M + "\"media\": {},\n" + SHAPE + " }\n", 4, "unknown medium 'm' in 'shapes[0].interior' (define it under 'media')"),
                Arguments.of("{\n" + M + "\"media\": { \"m\": { \"type\": \"homogeneous\", \"sigmaT\": 1 } },\n"
                        + SHAPE.replace("\"interior\": \"m\"", "\"exterior\": \"n\"") + " }\n", 4, "unknown medium 'n' in 'shapes[0].exterior' (define it under 'media'; known: m)"),
                Arguments.of("{\n" + M + "\"camera\": { \"lookFrom\": [0, 0, 3], \"lookAt\": [0, 0, 0],\n\"medium\": \"air\" },\n"
                        + "\"media\": { \"m\": { \"type\": \"homogeneous\", \"sigmaT\": 1 } },\n" + SHAPE + " }\n", 4, "unknown medium 'air' in 'camera.medium'"));
    }

    private static Arguments medium(String medium, String fragment) {
        return Arguments.of("{\n" + M + "\"media\": {\n\"m\": " + medium + "\n},\n" + SHAPE + " }\n", 4, fragment);
    }

    @ParameterizedTest(name = "{2}")
    @MethodSource("badScenes")
    void badMediaAreOneErrorWithFileLineAndKey(String json, int line, String fragment) throws Exception {
        smokeVol();
        Path file = write("bad.json", json);
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneLoader.load(file));
        assertThat(e).as(json).isNotNull();
        assertThat(e.getMessage()).startsWith(file + ":" + line + ": ").contains(fragment).doesNotContain("\n");
    }

    @Test
    void aBadVolFileIsOneErrorNamingTheSceneTheKeyAndTheVolFile() throws Exception {
        Path vol = Files.write(dir.resolve("smoke.vol"), java.util.Arrays.copyOf(VolFiles.bytes(2, 2, 2, new float[] {0, 0, 0, 1, 1, 1},
                new float[8]), 70));
        Path file = write("bad.json", "{\n" + M + "\"media\": { \"m\": { \"type\": \"grid\", \"file\": \"smoke.vol\" } },\n" + SHAPE + " }\n");
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneLoader.load(file));
        assertThat(e.getMessage()).startsWith(file + ": 'media.m.file': " + vol + ": truncated: a 2x2x2 grid needs 32 bytes").doesNotContain("\n");
        Files.write(vol, VolFiles.bytes(1, 1, 1, new float[] {0, 0, 0, 1, 0, 1}, new float[] {1}));
        e = catchThrowableOfType(SceneException.class, () -> SceneLoader.load(file));
        assertThat(e.getMessage()).contains("'media.m.file'").contains("the box in the file's header: the grid's bounds must be finite with min < max");
    }

    private static int material(Scene scene, String name) {
        return materials(scene, name).get(0);
    }

    private static List<Integer> materials(Scene scene, String name) {
        List<Integer> out = new java.util.ArrayList<>();
        for (int i = 0; i < scene.materials().size(); i++) {
            if (scene.materials().get(i).name().equals(name)) {
                out.add(i);
            }
        }
        return out;
    }
}
