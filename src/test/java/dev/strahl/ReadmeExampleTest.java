package dev.strahl;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.film.Film;
import dev.strahl.film.ImageWriters;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The library example of the README, kept compiling and working (at a smaller size). */
class ReadmeExampleTest {
    @TempDir
    Path dir;

    @Test
    void readmeExampleRendersThePng() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        RenderSettings settings = RenderSettings.defaults().withSamplesPerPixel(64).withSeed(7)
                .withSize(32, 32);                          // smaller than in the README, to stay quick
        try (RenderJob job = RenderJob.start(scene, settings)) {
            Film film = job.awaitCompletion();
            ImageWriters.write(film, dir.resolve("cornell.png"));
        }
        assertThat(Files.size(dir.resolve("cornell.png"))).isGreaterThan(100);
    }
}
