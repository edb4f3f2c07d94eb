package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.scene.Camera;
import dev.strahl.film.Film;
import dev.strahl.image.Image;
import dev.strahl.geometry.Sphere;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.scene.Scene;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.IntStream;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

class RenderJobTest {
    private static final Scene SPHERE = Scene.builder()
            .addSphere(new Vector3d(), 1, Material.diffuse("grey", Rgb.gray(0.5)))
            .camera(new Camera(new Vector3d(0, 0, 4), new Vector3d(), new Vector3d(0, 1, 0), 40))
            .build();

    @Test
    void automaticPassesGrowToSixteenAndStayThere() {
        int[] sizes = IntStream.range(0, 100).map(PassLoop::autoPassSize).toArray();
        assertThat(sizes).startsWith(1, 1, 2, 4, 8, 16, 16);
        assertThat(IntStream.of(sizes).boxed()).allMatch(s -> s >= 1 && s <= 16);
    }

    @Test
    void manyPassesReachTheRequestedSampleCountExactly() throws Exception {
        RenderSettings settings = RenderSettings.defaults().withSize(3, 2).withSamplesPerPixel(1000);
        try (RenderJob job = RenderJob.start(SPHERE, settings)) {
            Film film = TestJobs.awaitFilm(job);
            for (int y = 0; y < 2; y++) {
                for (int x = 0; x < 3; x++) {
                    assertThat(film.sampleCount(x, y)).isEqualTo(1000);
                }
            }
            RenderStats stats = job.awaitStats();
            assertThat(stats.samplesPerPixel()).isEqualTo(1000);
            assertThat(stats.samples()).isEqualTo(6000);
            assertThat(stats.cancelled()).isFalse();
            assertThat(job.progress()).isEqualTo(1.0);
        }
    }

    @Test
    void listenerHearsEveryPassWithAGrowingSampleCount() throws Exception {
        List<Integer> passes = new ArrayList<>();
        RenderListener listener = new RenderListener() {
            @Override
            public void passCompleted(int spp, Image image) {
                passes.add(spp);
                assertThat(image.width()).isEqualTo(8);
            }
        };
        try (RenderJob job = RenderJob.start(SPHERE, RenderSettings.defaults().withSize(8, 8).withSamplesPerPixel(40), listener)) {
            TestJobs.awaitFilm(job);
        }
        assertThat(passes).containsExactly(1, 2, 4, 8, 16, 32, 40);
    }

    @Test
    void cancelStopsALongRenderPromptly() throws Exception {
        RenderSettings huge = RenderSettings.defaults().withSize(256, 256).withSamplesPerPixel(1_000_000);
        RenderJob job = RenderJob.start(SPHERE, huge);
        Thread.sleep(100);
        job.cancel();
        assertThat(job.await(5, TimeUnit.SECONDS)).as("stopped within 5 s").isTrue();
        RenderStats stats = job.awaitStats();
        assertThat(stats.cancelled()).isTrue();
        assertThat(stats.samplesPerPixel()).isLessThan(1_000_000);
        job.close();
    }

    @Test
    void timeLimitStopsAfterThePassThatCrossesIt() throws Exception {
        RenderSettings settings = RenderSettings.defaults().withSize(64, 64).withSamplesPerPixel(1_000_000)
                .withTimeLimit(java.time.Duration.ofMillis(300));
        try (RenderJob job = RenderJob.start(SPHERE, settings)) {
            assertThat(job.await(10, TimeUnit.SECONDS)).as("stopped within 10 s").isTrue();
            RenderStats stats = job.awaitStats();
            assertThat(stats.cancelled()).isFalse();
            assertThat(stats.seconds()).isGreaterThanOrEqualTo(0.3);
            assertThat(stats.samplesPerPixel()).isBetween(1, 999_999);
            assertThat(job.film().sampleCount(0, 0)).as("whole passes only").isEqualTo(stats.samplesPerPixel());
        }
    }

    @Test
    void settingsRefuseNonsense() {
        RenderSettings d = RenderSettings.defaults();
        assertThatThrownBy(() -> d.withSize(0, 10)).hasMessageContaining("0x10");
        assertThatThrownBy(() -> d.withSize(100_000, 10)).hasMessageContaining("larger than");
        assertThatThrownBy(() -> d.withSamplesPerPixel(0)).hasMessageContaining("samples per pixel");
        assertThatThrownBy(() -> d.withMaxDepth(0)).hasMessageContaining("max depth");
        assertThatThrownBy(() -> d.withMaxDepth(-2)).hasMessageContaining("max depth");
        assertThatThrownBy(() -> d.withThreads(-1)).hasMessageContaining("threads");
    }
}
