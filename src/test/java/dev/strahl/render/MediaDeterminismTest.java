package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import dev.strahl.testing.Renders;
import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Scenes with participating media give the same bits whatever the threads or pass sizes (as
 * {@link DeterminismTest} for surfaces): delta and ratio tracking draw their variable number of
 * numbers from streams seeded by the sample's own dimensions, so a pixel's numbers stay a function
 * of (seed, pixel, sample, dimension). Fog behind a null box, a grid under a sun, a chromatic
 * scattering medium in glass.
 */
class MediaDeterminismTest {
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withSize(32, 24).withSamplesPerPixel(4).withSeed(17);

    @ParameterizedTest
    @ValueSource(strings = {"fog", "smoke", "subsurface"})
    void oneTwoAndThreeThreadsGiveIdenticalBits(String name) throws Exception {
        Scene scene = SceneLoader.load(Path.of("src/test/resources/golden/media/" + name + ".json"));
        Image one = Renders.render(scene, SETTINGS.withThreads(1));
        assertThat(Renders.render(scene, SETTINGS.withThreads(2)).rgb()).isEqualTo(one.rgb());
        assertThat(Renders.render(scene, SETTINGS.withThreads(3).withSamplesPerPass(1)).rgb()).isEqualTo(one.rgb());
        assertThat(one.mean()[1]).isPositive();
    }
}
