package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.codec.PfmReader;
import dev.strahl.testing.TestData;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;

class RenderCommandTest {

    static final String CORNELL = Path.of("scenes", "cornell-box.json").toString();
    /** The Williams College Cornell Box, from the test resources. */
    static final Path ORIGINAL = TestData.cornell("CornellBox-Original.obj");

    /** A closed unit cube without any material: no emitter at all. */
    static final String CUBE_OBJ = """
            v 0 0 0
            v 1 0 0
            v 0 1 0
            v 1 1 0
            v 0 0 1
            v 1 0 1
            v 0 1 1
            v 1 1 1
            f 1 5 7 3
            f 2 4 8 6
            f 1 2 6 5
            f 3 7 8 4
            f 1 3 4 2
            f 5 6 8 7
            """;

    @TempDir
    Path in;

    @TempDir
    Path out;

    /** What one run of the command line did. */
    record Run(int code, String out, String err) {
        List<String> errLines() {
            return err.lines().toList();
        }
    }

    static Run strahl(String... args) {
        CommandLine cl = Main.commandLine();
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int code = cl.execute(args);
        cl.getOut().flush();
        cl.getErr().flush();
        return new Run(code, out.toString(), err.toString());
    }

    /** A small, fast render of {@code scene} to {@code output}: 16x16, 4 spp unless the options say otherwise. */
    static Run render(String scene, Path output, String... options) {
        List<String> args = new ArrayList<>(List.of("render", scene, "-o", output.toString()));
        for (String option : List.of("--width", "--height", "--spp")) {
            if (!Arrays.asList(options).contains(option)) {
                args.addAll(List.of(option, option.equals("--spp") ? "4" : "16"));
            }
        }
        args.addAll(Arrays.asList(options));
        return strahl(args.toArray(String[]::new));
    }

    @BeforeEach
    void outputDirectoryStartsEmpty() throws IOException {
        assertThat(listing(out)).isEmpty();
    }

    // ---- bad input: exit 2, one line on stderr, nothing written ----------------------------------

    /** Exit code 2, exactly one line "strahl: ..." on stderr with every fragment, no trace, no output file. */
    private void assertRefused(Run r, String... fragments) throws IOException {
        assertThat(r.code()).as("exit code; stderr: %s", r.err()).isEqualTo(2);
        assertThat(r.errLines()).as("stderr").hasSize(1);
        String line = r.errLines().get(0);
        assertThat(line).startsWith("strahl: ");
        for (String f : fragments) {
            assertThat(line).contains(f);
        }
        assertThat(r.err()).doesNotContain("\tat ").doesNotContain("Exception");
        assertThat(r.out()).isEmpty();
        assertThat(listing(out)).as("files written").isEmpty();
    }

    @Test
    void missingSceneFile() throws IOException {
        Path scene = in.resolve("missing.json");
        assertRefused(render(scene.toString(), out.resolve("a.png")), scene.toString(), "file not found");
    }

    @Test
    void directoryAsScene() throws IOException {
        Path scene = Files.createDirectories(in.resolve("scene.json"));
        assertRefused(render(scene.toString(), out.resolve("a.png")), scene.toString(), "is a directory");
    }

    @Test
    void unknownSceneExtension() throws IOException {
        Path scene = in.resolve("scene.txt");
        Files.writeString(scene, CUBE_OBJ);
        assertRefused(render(scene.toString(), out.resolve("a.png")), scene.toString(), "unknown scene format", ".json, .obj, .ply, .gltf or .glb");
    }

    @Test
    void malformedObjNamesFileAndLine() throws IOException {
        Path scene = in.resolve("bad.obj");
        Files.writeString(scene, "# a comment\nv 0 0 0\nv 1 2 x\n");
        assertRefused(render(scene.toString(), out.resolve("a.png")), scene + ":3: ", "'x'");
    }

    static Stream<Arguments> badJsonScenes() {
        String sphere = "{ \"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\" }";
        return Stream.of(
            Arguments.of("{\n  \"shapes\": [\n    " + sphere + ",\n  ]\n}\n", 4, "malformed JSON"),
            Arguments.of("{\n  \"materials\": { \"m\": { \"type\": \"diffuse\" } },\n  \"shapes\": [ " + sphere + " ],\n  \"lamps\": 1\n}\n",
                    4, "unknown key 'lamps'"),
            Arguments.of("{\n  \"materials\": { \"m\": { \"type\": \"diffuse\", \"albedo\": \"red\" } },\n  \"shapes\": [ " + sphere + " ]\n}\n",
                    2, "'materials.m.albedo' must be an array"),
            Arguments.of("{\n  \"materials\": { \"m\": { \"type\": \"diffuse\" } }\n}\n", 1, "missing required key 'shapes'"),
            Arguments.of("{\n  \"materials\": { \"n\": { \"type\": \"diffuse\" } },\n  \"shapes\": [\n    " + sphere + "\n  ]\n}\n",
                    4, "unknown material 'm'"));
    }

    @ParameterizedTest
    @MethodSource("badJsonScenes")
    void malformedJsonSceneNamesFileLineAndKey(String json, int line, String what) throws IOException {
        Path scene = in.resolve("scene.json");
        Files.writeString(scene, json);
        assertRefused(render(scene.toString(), out.resolve("a.png")), scene + ":" + line + ": ", what);
    }

    @Test
    void unknownOutputExtension() throws IOException {
        assertRefused(render(CORNELL, out.resolve("a.jpg")), "a.jpg", ".png, .pfm or .exr");
    }

    @Test
    void outputWithoutExtension() throws IOException {
        assertRefused(render(CORNELL, out.resolve("image")), "image", ".png, .pfm or .exr");
    }

    @Test
    void missingOutputDirectory() throws IOException {
        Path dir = out.resolve("not-there");
        assertRefused(render(CORNELL, dir.resolve("a.png")), "output directory does not exist", dir.toString());
        assertThat(dir).doesNotExist();
    }

    static Stream<Arguments> badOptions() {
        return Stream.of(
            Arguments.of(List.of("--width", "0"), List.of("image size must be positive", "0x16")),
            Arguments.of(List.of("--height", "-3"), List.of("image size must be positive", "16x-3")),
            Arguments.of(List.of("--spp", "0"), List.of("samples per pixel must be positive", "0")),
            Arguments.of(List.of("--max-depth", "0"), List.of("max depth", "got 0")),
            Arguments.of(List.of("--max-depth", "-2"), List.of("max depth", "got -2")),
            Arguments.of(List.of("--threads", "-1"), List.of("threads", "-1")),
            Arguments.of(List.of("--fov", "200"), List.of("field of view", "200")),
            Arguments.of(List.of("--fov", "0"), List.of("field of view")),
            Arguments.of(List.of("--look-from", "0,1,0", "--look-at", "0,1,0"), List.of("coincide")),
            Arguments.of(List.of("--look-from", "1,2"), List.of("--look-from", "expected x,y,z", "'1,2'")),
            Arguments.of(List.of("--look-at", "1,b,3"), List.of("--look-at", "'b'", "not a number")),
            Arguments.of(List.of("--up", "0,1,NaN"), List.of("--up", "finite")),
            Arguments.of(List.of("--spp", "many"), List.of("--spp", "'many'")),
            Arguments.of(List.of("--hemisphere", "sphere"), List.of("--hemisphere", "'sphere'")),
            Arguments.of(List.of("--accel", "kdtree"), List.of("--accel", "'kdtree'")),
            Arguments.of(List.of("--schedule", "rows"), List.of("--schedule", "'rows'")),
            Arguments.of(List.of("--frobnicate"), List.of("Unknown option: '--frobnicate'")),
            Arguments.of(List.of("--denoise", "--denoiser", "fast"), List.of("--denoiser must be network, atrous or oidn, got 'fast'")),
            Arguments.of(List.of("--max-dpeth", "3"), List.of("'--max-dpeth'", "did you mean --max-depth")));
    }

    @ParameterizedTest
    @MethodSource("badOptions")
    void badOptionIsRefusedBeforeRendering(List<String> options, List<String> fragments) throws IOException {
        assertRefused(render(CORNELL, out.resolve("a.png"), options.toArray(String[]::new)), fragments.toArray(String[]::new));
    }

    @Test
    void missingArgumentsAreUsageErrors() throws IOException {
        assertRefused(strahl("render", CORNELL), "--output");
        assertRefused(strahl("render", "-o", out.resolve("a.png").toString()), "SCENE");
        assertRefused(strahl(), "missing command");
        assertRefused(strahl("draw", CORNELL), "draw");
    }

    // ---- help and version --------------------------------------------------------------------------

    @Test
    void topLevelHelpListsTheCommands() {
        Run r = strahl("--help");
        assertThat(r.code()).isZero();
        assertThat(r.out()).contains("Usage: strahl").contains("render").contains("--version");
        assertThat(r.err()).isEmpty();
    }

    @ParameterizedTest
    @ValueSource(strings = {"render --help", "help render", "render -h"})
    void renderHelpDescribesTheOptions(String args) {
        Run r = strahl(args.split(" "));
        assertThat(r.code()).isZero();
        assertThat(r.out()).contains("Usage: strahl render").contains("SCENE").contains("--output")
                .contains("--spp").contains("--max-depth").contains("--hemisphere").contains("cosine|uniform")
                .contains("--look-from").contains("--fov").contains("--seed").contains("--quiet")
                .contains("--accel").contains("bvh|none").contains("--schedule").contains("tiles|stripes").contains("Teaching option");
        assertThat(r.err()).isEmpty();
    }

    @Test
    void versionNamesTheProgram() {
        for (String[] args : new String[][] {{"--version"}, {"render", "--version"}, {"-V"}}) {
            Run r = strahl(args);
            assertThat(r.code()).isZero();
            assertThat(r.out()).startsWith("strahl ").contains("Java ");
            assertThat(r.err()).isEmpty();
        }
    }

    // ---- rendering ---------------------------------------------------------------------------------

    @Test
    void rendersTheShippedCornellBoxToPngAndPfm() throws IOException {
        Path png = out.resolve("cornell.png");
        Path pfm = out.resolve("cornell.pfm");
        Run a = render(CORNELL, png);
        Run b = render(CORNELL, pfm);
        assertThat(a.code()).as(a.err()).isZero();
        assertThat(b.code()).as(b.err()).isZero();
        assertThat(listing(out)).containsExactlyInAnyOrder("cornell.png", "cornell.pfm");   // no temporary files left

        BufferedImage decoded = ImageIO.read(png.toFile());
        assertThat(decoded).isNotNull();
        assertThat(decoded.getWidth()).isEqualTo(16);
        assertThat(decoded.getHeight()).isEqualTo(16);

        Image img = PfmReader.read(pfm);
        assertThat(img.width()).isEqualTo(16);
        assertThat(img.height()).isEqualTo(16);
        assertThat(img.mean()[0]).isGreaterThan(0.05);
        // The light (radiance 17, 12, 4) is seen directly near the top centre: rows 2..3 at 16x16
        assertThat(maxLuminance(img, 0, 5)).isGreaterThan(3);
        // Nothing below the ceiling is as bright as the light
        assertThat(maxLuminance(img, 6, 16)).isLessThan(3);
        // red wall on the left, green wall on the right
        assertThat(img.get(1, 8, 0)).isGreaterThan(img.get(1, 8, 1));
        assertThat(img.get(14, 8, 1)).isGreaterThan(img.get(14, 8, 0));
    }

    @Test
    void summaryLineReportsSizeSamplesAndRate() {
        Path png = out.resolve("c.png");
        Run r = render(CORNELL, png);
        assertThat(r.code()).isZero();
        assertThat(r.errLines()).singleElement().asString()
                .startsWith("strahl: path, 16x16, 4 spp in ").contains("samples/s").contains("rays/s").endsWith("-> " + png);
        assertThat(r.out()).isEmpty();
    }

    @Test
    void quietPrintsNothing() {
        Path png = out.resolve("c.png");
        Run r = render(CORNELL, png, "--quiet");
        assertThat(r.code()).isZero();
        assertThat(r.err()).isEmpty();
        assertThat(r.out()).isEmpty();
        assertThat(png).isRegularFile();
    }

    @Test
    void quietStillReportsErrors() throws IOException {
        assertRefused(render(CORNELL, out.resolve("a.png"), "-q", "--spp", "0"), "samples per pixel");
    }

    @Test
    void denoiseUsesTheNetworkUnlessTheFilterIsAskedFor() throws IOException {
        Path net = out.resolve("net.pfm");
        Run r = render(CORNELL, net, "--denoise");
        assertThat(r.code()).isZero();
        assertThat(r.errLines()).last().asString().startsWith("strahl: denoised with Open Image Denoise's network in ");
        Image filter = renderPfm(CORNELL, "atrous.pfm", "--denoise", "--denoiser", "atrous");
        Image oldName = renderPfm(CORNELL, "strahl.pfm", "--denoise", "--denoiser", "strahl");
        assertThat(oldName.rgb()).as("strahl: the filter's old name").isEqualTo(filter.rgb());
        assertThat(PfmReader.read(net).rgb()).isNotEqualTo(filter.rgb());
    }

    @Test
    void sameSeedGivesTheSameImageAndAnotherSeedAnother() throws IOException {
        Image a = renderPfm(CORNELL, "a.pfm", "--seed", "5");
        Image b = renderPfm(CORNELL, "b.pfm", "--seed", "5", "--threads", "1");
        Image c = renderPfm(CORNELL, "c.pfm", "--seed", "6");
        assertThat(b.rgb()).containsExactly(a.rgb());
        assertThat(c.rgb()).isNotEqualTo(a.rgb());
    }

    /** The teaching options change the work, not the image; --stats reports them and the threads' idle time. */
    @Test
    void teachingOptionsGiveTheSameImageAndAreReportedInTheStats() throws IOException {
        Image a = renderPfm(CORNELL, "a.pfm", "--seed", "5");
        Image b = renderPfm(CORNELL, "b.pfm", "--seed", "5", "--accel", "none", "--schedule", "stripes", "--threads", "3",
                "--stats", out.resolve("b.json").toString());
        assertThat(b.rgb()).containsExactly(a.rgb());
        String json = Files.readString(out.resolve("b.json"));
        assertThat(json).contains("\"accel\" : \"none\"").contains("\"schedule\" : \"stripes\"").contains("\"thread_idle_seconds\" : ");
    }

    @Test
    void uniformHemisphereSamplingRendersTheSameSceneDifferently() throws IOException {
        Image cosine = renderPfm(CORNELL, "cosine.pfm");
        Image uniform = renderPfm(CORNELL, "uniform.pfm", "--hemisphere", "uniform");
        Image upper = renderPfm(CORNELL, "upper.pfm", "--hemisphere", "UNIFORM");
        assertThat(uniform.rgb()).isNotEqualTo(cosine.rgb());
        assertThat(upper.rgb()).containsExactly(uniform.rgb());
        assertThat(uniform.mean()[0]).isGreaterThan(0.05);
        assertThat(maxLuminance(uniform, 0, 5)).isGreaterThan(3);     // the light seen directly does not depend on it
    }

    @Test
    void maxDepthOneShowsOnlyTheLight() throws IOException {
        Image img = renderPfm(CORNELL, "emitters.pfm", "--max-depth", "1");
        assertThat(maxLuminance(img, 0, 5)).isGreaterThan(3);
        assertThat(maxLuminance(img, 6, 16)).isZero();
    }

    @Test
    void cameraOptionsReplaceTheScenesCamera() throws IOException {
        Image scene = renderPfm(CORNELL, "scene.pfm");
        // The scene's own camera given as options: the very same image
        Image same = renderPfm(CORNELL, "same.pfm", "--look-from", "0,1,3.9", "--look-at", "0,1,0", "--up", "0,1,0", "--fov", "40");
        assertThat(same.rgb()).containsExactly(scene.rgb());
        // A narrow field of view crops the light (14.5 degrees above the axis) out of the image
        Image narrow = renderPfm(CORNELL, "narrow.pfm", "--fov", "20");
        assertThat(maxLuminance(scene, 0, 16)).isGreaterThan(3);
        assertThat(maxLuminance(narrow, 0, 16)).isLessThan(3);
        // Looking up at the light from below puts it in the middle of the image
        Image up = renderPfm(CORNELL, "up.pfm", "--look-from", "0,0.5,0", "--look-at", "0,2,0", "--up", "0,0,-1", "--fov", "30");
        assertThat(maxLuminance(up, 6, 10)).isGreaterThan(3);
        // Turning the camera upside down flips the image: red wall on the right
        Image flipped = renderPfm(CORNELL, "flipped.pfm", "--up", "0,-1,0");
        assertThat(flipped.get(14, 8, 0)).isGreaterThan(flipped.get(14, 8, 1));
        assertThat(flipped.get(1, 8, 1)).isGreaterThan(flipped.get(1, 8, 0));
    }

    @Test
    void objWithoutEmitterOrCameraGetsTheStudioLookWithANote() throws IOException {
        Path obj = in.resolve("cube.obj");
        Files.writeString(obj, CUBE_OBJ);
        Path pfm = out.resolve("cube.pfm");
        Run r = render(obj.toString(), pfm);
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.errLines()).first().asString()
                .startsWith("strahl: note: the scene has no light and no camera: lighting it with strahl's studio sky")
                .contains("three-quarter view");
        assertThat(r.errLines()).hasSize(2);        // the note and the summary
        Image img = PfmReader.read(pfm);
        // The grey cube (albedo 0.8) is framed in the middle and stands out against the dark ground
        // seen behind it from above (the bottom corners) and the blue sky (the top corners).
        double cube = luminance(img, 8, 8), ground = luminance(img, 0, 15), sky = luminance(img, 0, 0);
        assertThat(cube).isGreaterThan(2.5 * ground);
        assertThat(img.get(0, 0, 2)).isGreaterThan(img.get(0, 0, 0));          // the sky is blue
        assertThat(sky).isGreaterThan(ground);
    }

    @Test
    void rendersTheSharedOriginalObjFramedAutomatically() throws IOException {
        Image img = renderPfm(ORIGINAL.toString(), "original.pfm");
        assertThat(img.mean()[0]).isGreaterThan(0.02);
        assertThat(maxLuminance(img, 0, 16)).isGreaterThan(3);        // the light is in view
        // framed from +Z: red wall left of the centre, green wall right of it
        double[] left = columnMean(img, 0, 8), right = columnMean(img, 8, 16);
        assertThat(left[0] / left[1]).isGreaterThan(right[0] / right[1]);
    }

    // ---- helpers -----------------------------------------------------------------------------------

    private Image renderPfm(String scene, String name, String... options) throws IOException {
        Path pfm = out.resolve(name);
        Run r = render(scene, pfm, options);
        assertThat(r.code()).as("exit code; stderr: %s", r.err()).isZero();
        return PfmReader.read(pfm);
    }

    private static double maxLuminance(Image img, int fromRow, int toRow) {
        double max = 0;
        for (int y = fromRow; y < toRow; y++) {
            for (int x = 0; x < img.width(); x++) {
                max = Math.max(max, 0.2126 * img.get(x, y, 0) + 0.7152 * img.get(x, y, 1) + 0.0722 * img.get(x, y, 2));
            }
        }
        return max;
    }

    private static double[] columnMean(Image img, int fromColumn, int toColumn) {
        double[] m = new double[3];
        for (int y = 0; y < img.height(); y++) {
            for (int x = fromColumn; x < toColumn; x++) {
                for (int c = 0; c < 3; c++) {
                    m[c] += img.get(x, y, c);
                }
            }
        }
        return m;
    }

    private static List<String> listing(Path dir) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).toList();
        }
    }

    static double luminance(Image img, int x, int y) {
        return 0.2126 * img.get(x, y, 0) + 0.7152 * img.get(x, y, 1) + 0.0722 * img.get(x, y, 2);
    }
}
