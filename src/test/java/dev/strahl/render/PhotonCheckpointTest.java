package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.film.Film;
import dev.strahl.integrator.IntegratorKind;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneLoader;
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
            .withIntegrator(IntegratorKind.PHOTON).withPhotons(5000);
    private static Scene scene;
    private static Film uninterrupted;

    @TempDir
    Path dir;

    @BeforeAll
    static void renderOnceThrough() throws Exception {
        scene = SceneLoader.load(Path.of("scenes/cornell-sphere.json"));
        try (RenderJob job = RenderJob.start(scene, SETTINGS)) {
            uninterrupted = job.awaitCompletion();
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
            cp.save(file, first.awaitCompletion(), first.invalidSamples(), first.elapsedSeconds());
        }
        Film restored = cp.restore(file).film();
        try (RenderJob second = RenderJob.resume(scene, SETTINGS.withThreads(1), restored, new RenderListener() {})) {
            Film resumed = second.awaitCompletion();
            assertThat(resumed.toImage().rgb()).isEqualTo(uninterrupted.toImage().rgb());
        }
    }

    @Test
    void otherPhotonParametersAreRefused() throws Exception {
        Path file = dir.resolve("q.ck");
        Checkpoint.of(scene, SETTINGS).save(file, uninterrupted, 0, 0);
        assertThatThrownBy(() -> Checkpoint.of(scene, SETTINGS.withPhotons(6000)).restore(file)).hasMessageContaining("photons");
        assertThatThrownBy(() -> Checkpoint.of(scene, SETTINGS.withPhotonRadius(0.05)).restore(file)).hasMessageContaining("photonRadius");
    }
}
