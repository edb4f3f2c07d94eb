package dev.strahl.io;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.codec.ImageFormatException;
import dev.strahl.scene.SceneException;
import dev.strahl.testing.Fuzzer;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every input that once broke a parser (found by {@link ParserFuzzTest} or by hand), kept in
 * {@code src/test/resources/fuzz/KIND/}: each must now be accepted or rejected with a
 * {@link SceneException} (an {@link ImageFormatException} for the image kinds exr, hdr and png). A
 * {@code .txt} beside an input says what it did. (gltf and glb inputs go through the scene loader, as json's.)
 */
class FuzzRegressionTest {
    private static final Path CORPUS = Path.of("src", "test", "resources", "fuzz");
    private static Path work;

    @BeforeAll
    static void copyTheShippedScenes() throws IOException {
        work = ParserFuzzTest.workDirectory();
    }

    @AfterAll
    static void deleteTheCopies() throws IOException {
        ParserFuzzTest.deleteTree(work);
    }

    static Stream<Path> regressionCases() throws IOException {
        List<Path> cases = new ArrayList<>();
        for (String kind : List.of("obj", "mtl", "ply", "json", "gltf", "glb", "exr", "hdr", "pfm", "png", "vol")) {
            Path dir = CORPUS.resolve(kind);
            if (Files.isDirectory(dir)) {
                try (Stream<Path> files = Files.list(dir)) {
                    files.filter(f -> !f.toString().endsWith(".txt")).sorted().forEach(cases::add);
                }
            }
        }
        return cases.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("regressionCases")
    void regressionCasesStayFixed(Path input) throws IOException {
        String kind = input.getParent().getFileName().toString();
        Fuzzer.Target target = switch (kind) {
            case "obj" -> ParserFuzzTest.objTarget();
            case "mtl" -> ParserFuzzTest.mtlTarget();
            case "ply" -> ParserFuzzTest.plyTarget();
            case "exr" -> ParserFuzzTest.exrTarget();
            case "hdr" -> ParserFuzzTest.hdrTarget();
            case "png" -> ParserFuzzTest.pngTarget();
            case "pfm" -> ParserFuzzTest.pfmTarget();
            case "vol" -> ParserFuzzTest.volTarget();
            default -> ParserFuzzTest.jsonTarget();
        };
        Class<? extends Exception> allowed = List.of("exr", "hdr", "pfm", "png", "vol").contains(kind) ? ImageFormatException.class : SceneException.class;
        Fuzzer fuzzer = new Fuzzer("regression-" + kind, target, allowed, work.resolve("regression." + kind));
        // the verdict: null = accepted, "" = rejected with the reader's own exception, else what broke
        assertThat(fuzzer.check(Files.readAllBytes(input))).as("%s: null = accepted, \"\" = %s", input, allowed.getSimpleName())
                .isIn(null, "");
    }

}
