package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.film.Film;
import dev.strahl.scene.Scene;
import dev.strahl.io.SceneLoader;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A photon-mapped render interrupted and resumed gives the bits of one that ran through: each
 * iteration's photon map is a function of (seed, iteration) alone, so the resumed job rebuilds
 * exactly the maps the pixels still need. Checkpoints of other photon parameters are refused.
 */
class PhotonCheckpointTest {
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withSize(40, 30).withSamplesPerPixel(6).withSeed(9)
            .withIntegrator(IntegratorKind.PHOTON).withPhotons(new PhotonParameters(5000, 0));
    private static Scene scene;
    private static Film uninterrupted;

    @TempDir
    Path dir;

    @BeforeAll
    static void renderOnceThrough() throws Exception {
        scene = SceneLoader.load(Path.of("scenes/cornell-sphere.json"));
        try (RenderJob job = RenderJob.start(scene, SETTINGS)) {
            uninterrupted = TestJobs.awaitFilm(job);
        }
    }

    @Test
    void resumingAfterACancelMidRenderIsBitIdentical() throws Exception {
        Checkpoint cp = Checkpoint.of(scene, SETTINGS);
        Path file = dir.resolve("p.ck");
        try (RenderJob first = RenderJob.start(scene, SETTINGS.withThreads(2))) {
            while (first.completedSamplesPerPixel() < 2 && !first.isDone()) {     // then cancel during a later pass
                Thread.sleep(1);
            }
            first.cancel();
            cp.save(file, TestJobs.awaitFilm(first), null, first.invalidSamples(), first.elapsedSeconds());
        }
        Film restored = cp.restore(file).film();
        try (RenderJob second = TestJobs.resume(scene, SETTINGS.withThreads(1), restored, new RenderListener() {})) {
            Film resumed = TestJobs.awaitFilm(second);
            assertThat(resumed.toImage().rgb()).isEqualTo(uninterrupted.toImage().rgb());
        }
    }

    @Test
    void otherPhotonParametersAreRefused() throws Exception {
        Path file = dir.resolve("q.ck");
        Checkpoint.of(scene, SETTINGS).save(file, uninterrupted, null, 0, 0);
        assertThatThrownBy(() -> Checkpoint.of(scene, SETTINGS.withPhotons(new PhotonParameters(6000, 0))).restore(file)).hasMessageContaining("photons");
        assertThatThrownBy(() -> Checkpoint.of(scene, SETTINGS.withPhotons(new PhotonParameters(SETTINGS.transport().photons().photonsPerIteration(), 0.05))).restore(file)).hasMessageContaining("initialRadius");
    }
}
