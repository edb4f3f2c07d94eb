package dev.strahl;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.charset.CharacterCodingException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * A clone of the repository is all a build needs: no source, test, resource, POM or CI file
 * names a path outside it — neither the data folder that sits beside the repository on the
 * project's own machines nor any path that climbs out of the working directory (the repository
 * root when Maven runs the tests).
 */
class RepositoryBoundaryTest {
    /**
     * A folder beside the repository ({@code ../shared}, {@code ..\shared}, {@code "..", "shared"}),
     * or a path from the working directory upwards ({@code Path.of("..}, {@code Paths.get("..},
     * {@code new File("..}).
     */
    static final Pattern OUTSIDE = Pattern.compile(
            "\\.\\.[/\\\\]+shared|\"\\.\\.\"\\s*,\\s*\"shared\"|(?:Path\\.of|Paths\\.get|new File)\\(\\s*\"\\.\\.");

    /** The places scanned: everything a build reads or runs. */
    static final List<Path> SCANNED = List.of(Path.of("src"), Path.of("pom.xml"), Path.of(".ci"));

    @Test
    void noFileOfTheBuildNamesAPathOutsideTheRepository() throws IOException {
        List<String> found = new ArrayList<>();
        for (Path root : SCANNED) {
            assertThat(root).exists();
            try (Stream<Path> files = Files.walk(root)) {
                files.filter(Files::isRegularFile)
                        .filter(f -> !f.endsWith(Path.of("dev", "strahl", "RepositoryBoundaryTest.java")))
                        .forEach(f -> {
                            String text = text(f);
                            if (text != null) {
                                String[] lines = text.split("\n", -1);
                                for (int i = 0; i < lines.length; i++) {
                                    Matcher m = OUTSIDE.matcher(lines[i]);
                                    if (m.find()) {
                                        found.add(f + ":" + (i + 1) + ": " + lines[i].strip());
                                    }
                                }
                            }
                        });
            }
        }
        assertThat(found).as("files that name a path outside the repository").isEmpty();
    }

    @Test
    void thePatternCatchesTheWaysAPathLeavesTheRepository() {
        for (String line : List.of("Path.of(\"../shared/data/cornell/CornellBox-Original.obj\")",
                "static final Path MESHES = Path.of(\"..\", \"shared\", \"data\", \"meshes\");",
                "defaultValue = \"../shared/data\"", "# with ..\\shared beside it", "Paths.get(\"../refs\")",
                "new File(\"../x.obj\")", "Path.of( \"..\", \"data\")")) {
            assertThat(OUTSIDE.matcher(line).find()).as(line).isTrue();
        }
        for (String line : List.of("Path.of(\"src\", \"test\", \"resources\", \"cornell\")", "dir.resolve(\"sub/../s5.json\")",
                "\"file\": \"../models/tri.obj\"", "shared by all threads")) {
            assertThat(OUTSIDE.matcher(line).find()).as(line).isFalse();
        }
    }

    /** The file's text, or null for a binary file (not UTF-8). */
    private static String text(Path file) {
        try {
            return StandardCharsets.UTF_8.newDecoder().decode(java.nio.ByteBuffer.wrap(Files.readAllBytes(file))).toString();
        } catch (CharacterCodingException e) {
            return null;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
