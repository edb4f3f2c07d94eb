package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.scene.Scene;
import dev.strahl.io.SceneLoader;
import dev.strahl.testing.Renders;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The same scene, settings and seed give the same bits, whatever the threads or pass sizes. */
class DeterminismTest {
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withSize(70, 50).withSamplesPerPixel(6).withSeed(42);

    private static Scene cornell() throws Exception {
        return SceneLoader.load(Path.of("scenes/cornell-box.json"));
    }

    @Test
    void oneAndTwoThreadsGiveIdenticalBits() throws Exception {
        Scene scene = cornell();
        Image one = Renders.render(scene, SETTINGS.withThreads(1));
        Image two = Renders.render(scene, SETTINGS.withThreads(2));
        Image three = Renders.render(scene, SETTINGS.withThreads(3));
        assertThat(two.rgb()).isEqualTo(one.rgb());
        assertThat(three.rgb()).isEqualTo(one.rgb());
    }

    /** An environment map (importance-sampled) seen through a thin lens (a lens pair per sample), every integrator. */
    @Test
    void anEnvironmentMapThroughAThinLensGivesIdenticalBitsOnOneAndTwoThreads() throws Exception {
        Scene scene = SceneLoader.load(Path.of("src/test/resources/golden/envmap-sphere.json"));
        scene = scene.withCamera(scene.camera().withLens(0.2, 3.5));
        for (IntegratorKind kind : IntegratorKind.values()) {
            RenderSettings s = SETTINGS.withIntegrator(kind).withPhotons(new PhotonParameters(2000, 0));
            Image one = Renders.render(scene, s.withThreads(1));
            Image two = Renders.render(scene, s.withThreads(2));
            assertThat(two.rgb()).as("%s", kind).isEqualTo(one.rgb());
        }
    }

    /** Point, spot and directional lights (chosen by power next to each other), every integrator, the photon mapper's photons from them too. */
    @Test
    void punctualLightsGiveIdenticalBitsOnOneTwoAndThreeThreads() throws Exception {
        Scene scene = SceneLoader.load(Path.of("src/test/resources/golden/punctual.json"));
        for (IntegratorKind kind : IntegratorKind.values()) {
            RenderSettings s = SETTINGS.withIntegrator(kind).withPhotons(new PhotonParameters(5000, 0));
            Image one = Renders.render(scene, s.withThreads(1));
            assertThat(Renders.render(scene, s.withThreads(2)).rgb()).as("%s", kind).isEqualTo(one.rgb());
            assertThat(Renders.render(scene, s.withThreads(3).withSamplesPerPass(1)).rgb()).as("%s", kind).isEqualTo(one.rgb());
        }
    }

    @Test
    void passSizeDoesNotChangeTheImage() throws Exception {
        Scene scene = cornell();
        Image auto = Renders.render(scene, SETTINGS);
        Image single = Renders.render(scene, SETTINGS.withSamplesPerPass(1));
        assertThat(single.rgb()).isEqualTo(auto.rgb());
    }

    /**
     * The photon mapper traces each iteration's photons in chunks on the job's threads: the map,
     * and so the image, must not depend on how many threads took the chunks.
     */
    @Test
    void photonMappingGivesIdenticalBitsOnOneTwoAndThreeThreads() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-sphere.json"));      // glass and mirror: caustic photons
        RenderSettings photon = SETTINGS.withSamplesPerPixel(3).withIntegrator(IntegratorKind.PHOTON).withPhotons(new PhotonParameters(10_000, 0));
        Image one = Renders.render(scene, photon.withThreads(1));
        Image two = Renders.render(scene, photon.withThreads(2));
        Image three = Renders.render(scene, photon.withThreads(3));
        assertThat(two.rgb()).isEqualTo(one.rgb());
        assertThat(three.rgb()).isEqualTo(one.rgb());
        assertThat(Renders.render(scene, photon.withThreads(2).withSamplesPerPass(4)).rgb()).isEqualTo(one.rgb());
        assertThat(Renders.render(scene, photon.withSeed(43)).rgb()).isNotEqualTo(one.rgb());
    }

    @Test
    void anotherSeedGivesAnotherImage() throws Exception {
        Scene scene = cornell();
        Image a = Renders.render(scene, SETTINGS);
        Image b = Renders.render(scene, SETTINGS.withSeed(43));
        assertThat(b.rgb()).isNotEqualTo(a.rgb());
    }
}
