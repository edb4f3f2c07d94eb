package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.medium.VolFiles;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Bad media through the real command line (issue 29): one line naming the file and the key (and
 * the {@code .vol} file where it is at fault), exit code 2, no stack trace, no output file; and the
 * integrators that do not render media say so the same way.
 */
class MediaBadInputTest {
    @TempDir
    Path in;

    @TempDir
    Path out;

    static final String SHAPES = "\"materials\": { \"b\": { \"type\": \"null\" }, \"lamp\": { \"type\": \"diffuse\", \"emission\": [1, 1, 1] } },\n"
            + "\"shapes\": [ { \"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"b\", \"interior\": \"m\" },\n"
            + "{ \"type\": \"sphere\", \"center\": [0, 3, 0], \"radius\": 0.5, \"material\": \"lamp\" } ] }\n";

    static Stream<Arguments> cases() {
        String good = "{\n\"media\": { \"m\": { \"type\": \"homogeneous\", \"sigmaT\": 1 } },\n" + SHAPES;
        return Stream.of(
                Arguments.of("negative sigmaT", "{\n\"media\": { \"m\": { \"type\": \"homogeneous\", \"sigmaT\": -1 } },\n" + SHAPES,
                        List.of(), "s.json:2: 'media.m.sigmaT' must be >= 0"),
                Arguments.of("albedo above 1", "{\n\"media\": { \"m\": { \"type\": \"homogeneous\", \"sigmaT\": 1, \"albedo\": [1, 2, 1] } },\n"
                        + SHAPES, List.of(), "s.json:2: 'media.m.albedo' must lie in [0, 1]"),
                Arguments.of("g of 1", "{\n\"media\": { \"m\": { \"type\": \"homogeneous\", \"sigmaT\": 1, \"g\": 1 } },\n" + SHAPES, List.of(),
                        "s.json:2: 'media.m.g' (the phase function's asymmetry) must lie in (-1, 1)"),
                Arguments.of("unknown medium", "{\n\"media\": { \"n\": { \"type\": \"homogeneous\", \"sigmaT\": 1 } },\n" + SHAPES, List.of(),
                        "s.json:4: unknown medium 'm' in 'shapes[0].interior'"),
                Arguments.of("truncated vol", "{\n\"media\": { \"m\": { \"type\": \"grid\", \"file\": \"t.vol\" } },\n" + SHAPES, List.of(),
                        "s.json: 'media.m.file': $IN/t.vol: truncated: a 4x4x4 grid needs 256 bytes after the header, the file holds 100"),
                Arguments.of("three channels", "{\n\"media\": { \"m\": { \"type\": \"grid\", \"file\": \"rgb.vol\" } },\n" + SHAPES, List.of(),
                        "$IN/rgb.vol: holds 3 channels per voxel; a density grid has one"),
                Arguments.of("whitted", good, List.of("--integrator", "whitted"),
                        "the whitted integrator does not render participating media or null surfaces; this scene has them: use path or direct"),
                Arguments.of("photon", good, List.of("--integrator", "photon"), "the photon integrator does not render participating media"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void refusedWithOneLine(String name, String scene, List<String> options, String fragment) throws Exception {
        byte[] truncated = VolFiles.bytes(4, 4, 4, new float[] {0, 0, 0, 1, 1, 1}, new float[64]);
        Files.write(in.resolve("t.vol"), java.util.Arrays.copyOf(truncated, 148));
        byte[] rgb = VolFiles.bytes(1, 1, 1, new float[] {0, 0, 0, 1, 1, 1}, new float[3]);
        java.nio.ByteBuffer.wrap(rgb).order(java.nio.ByteOrder.LITTLE_ENDIAN).putInt(20, 3);
        Files.write(in.resolve("rgb.vol"), rgb);
        Path file = Files.writeString(in.resolve("s.json"), scene);
        List<String> args = new java.util.ArrayList<>(List.of("render", file.toString(), "-o", out.resolve("a.png").toString(), "--width", "8",
                "--height", "8", "--spp", "1"));
        args.addAll(options);
        RenderCommandTest.Run r = RenderCommandTest.strahl(args.toArray(String[]::new));
        assertThat(r.code()).as("exit code; stderr: %s", r.err()).isEqualTo(2);
        assertThat(r.err()).doesNotContain("\tat ").doesNotContain("Exception");
        assertThat(r.errLines()).as("one line").hasSize(1);
        assertThat(r.errLines().get(0)).startsWith("strahl: ").contains(fragment.replace("$IN", in.toString()));
        try (Stream<Path> written = Files.list(out)) {
            assertThat(written).as("files written").isEmpty();
        }
    }
}
