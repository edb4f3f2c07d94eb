package dev.strahl.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.io.SceneLoader;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** A scene's {@code .vol} grid travels to the cluster's members with the scene file, as its meshes and textures do. */
class JobFilesMediaTest {
    @Test
    void theVolumeFileIsAmongTheFilesShipped() throws Exception {
        Path scene = Path.of("src/test/resources/golden/media/smoke.json");
        Map<String, Path> byHash = new HashMap<>();
        JobFiles job = JobFiles.of(scene, SceneLoader.load(scene).camera(), "", new byte[0], byHash);
        assertThat(job.files().keySet()).containsExactlyInAnyOrder("smoke.json", "smoke.vol");
        assertThat(byHash.values()).contains(scene.resolveSibling("smoke.vol").toAbsolutePath().normalize());
    }
}
