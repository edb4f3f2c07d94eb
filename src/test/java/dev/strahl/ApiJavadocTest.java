package dev.strahl;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The API types (docs/architecture.md, "The API") carry complete Javadoc: javadoc with every
 * doclint check, "missing" included (a comment on every public type and member, every
 * {@code @param}, {@code @return} and {@code @throws}), reports nothing for them. The Maven javadoc
 * run covers all exported packages with every check but "missing".
 */
class ApiJavadocTest {
    static final List<String> API = List.of(
            "scene/Scene", "scene/SceneLoader", "scene/SceneException", "scene/SceneSettings", "scene/Transform",
            "render/RenderSettings", "render/RenderJob", "render/RenderListener", "render/RenderStats",
            "render/Checkpoint", "render/CheckpointException", "film/AtomicFile",
            "film/Film", "film/Image", "film/ImageWriters", "film/Tonemap", "film/PfmReader",
            "material/Material", "material/Lambert", "material/Mirror", "material/Dielectric", "material/Glossy",
            "math/Rgb", "camera/Camera", "geometry/TriangleMesh", "geometry/Sphere",
            "integrator/IntegratorKind", "sampling/HemisphereSampling");

    @TempDir
    Path dir;

    @Test
    void everyApiTypeHasCompleteJavadoc() throws Exception {
        String path = System.getProperty("jdk.module.path");
        String classPath = (path == null || path.isBlank() ? "" : path + File.pathSeparator) + System.getProperty("java.class.path");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "javadoc").toString(),
                "-Xdoclint:all", "-quiet", "-d", dir.toString(), "-classpath", classPath));
        for (String type : API) {
            Path source = Path.of("src", "main", "java", "dev", "strahl", type + ".java");
            assertThat(source).exists();
            cmd.add(source.toString());
        }
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor()).as(out).isZero();
        assertThat(out.lines().filter(l -> l.contains("warning") || l.contains("error"))).as(out).isEmpty();
    }

    @Test
    void theArchitecturePageNamesEveryApiType() throws Exception {
        String page = Files.readString(Path.of("docs", "architecture.md"));
        for (String type : API) {
            assertThat(page).contains("`" + type.substring(type.indexOf('/') + 1) + "`");
        }
    }
}
