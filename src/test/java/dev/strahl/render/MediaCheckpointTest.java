package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.image.Image;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import dev.strahl.testing.Renders;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A render of a scene with media is checkpointed and resumed to the same bits, and its checkpoint
 * is tied to the media: the same scene with another density grid is refused. Feature buffers of
 * such a scene are those of the surfaces behind the media's invisible boundaries.
 */
class MediaCheckpointTest {
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withSize(32, 24).withSamplesPerPixel(12).withSeed(5);

    @TempDir
    Path dir;

    private Path copyOfSmoke() throws Exception {
        Path from = Path.of("src/test/resources/golden/media");
        Files.copy(from.resolve("smoke.json"), dir.resolve("smoke.json"));
        Files.copy(from.resolve("smoke.vol"), dir.resolve("smoke.vol"));
        return dir.resolve("smoke.json");
    }

    @Test
    void aCheckpointedRenderResumesBitIdenticallyAndOnlyWithItsOwnGrid() throws Exception {
        Path sceneFile = copyOfSmoke();
        Scene smoke = SceneLoader.load(sceneFile);
        Image uninterrupted = Renders.render(smoke, SETTINGS);
        Path file = dir.resolve("m.ck");
        try (RenderJob first = RenderJob.start(smoke, SETTINGS.withThreads(2))) {
            while (first.samplesDone() == 0 && !first.isDone()) {
                Thread.onSpinWait();
            }
            first.saveCheckpoint(file);
            first.cancel();
        }
        try (RenderJob second = RenderJob.resumeFrom(file, smoke, SETTINGS.withThreads(1), new RenderListener() {})) {
            assertThat(second.awaitCompletion().rgb()).isEqualTo(uninterrupted.rgb());
        }
        byte[] vol = Files.readAllBytes(dir.resolve("smoke.vol"));
        ByteBuffer.wrap(vol).order(ByteOrder.LITTLE_ENDIAN).putFloat(48 + 4 * 500, 0.123f);   // one voxel of another density
        Files.write(dir.resolve("smoke.vol"), vol);
        Scene other = SceneLoader.load(sceneFile);
        assertThatThrownBy(() -> RenderJob.resumeFrom(file, other, SETTINGS, new RenderListener() {}).close())
                .isInstanceOf(CheckpointException.class).hasMessageContaining("scene");
    }

    @Test
    void featureBuffersLookThroughTheInvisibleBoundaries() throws Exception {
        Scene fog = SceneLoader.load(Path.of("src/test/resources/golden/media/fog.json"));
        RenderBuffers b;
        try (RenderJob job = RenderJob.start(fog, SETTINGS.withSamplesPerPixel(2).withAovs(EnumSet.allOf(Aov.class)))) {
            b = job.awaitBuffers();
        }
        // the middle of the image: the back wall (white, 0.725) at depth 4.9, seen through the fog box's front face at 2.9
        assertThat((double) b.albedo().get(16, 12, 0)).isBetween(0.70, 0.75);
        assertThat((double) b.depth().get(16, 12, 0)).isBetween(4.7, 5.0);
        for (float v : b.normal().rgb()) {
            assertThat(Float.isFinite(v)).isTrue();
        }
    }
}
