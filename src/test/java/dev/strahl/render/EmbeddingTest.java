package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.color.DisplayEncoding;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.scene.Scene;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Transform;
import dev.strahl.testing.Meshes;
import dev.strahl.testing.Renders;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** What an embedding program relies on: jobs that share nothing, progress reports, consistent snapshots, cancellation. */
class EmbeddingTest {

    static Scene inCode() {
        return Scene.builder()
                .addMesh(Meshes.icosphere(2, 1, false), Material.glossy("paint", new Rgb(0.5, 0.2, 0.1), Rgb.gray(0.3), 40),
                        Transform.scaling(0.5).translate(-0.6, 0.5, 0))
                .addSphere(new Vector3d(0.6, 0.5, 0), 0.4, Material.dielectric("glass", 1.5))
                .addSphere(new Vector3d(0, -100, 0), 99.9, Material.diffuse("floor", Rgb.gray(0.6)))
                .addSphere(new Vector3d(0, 3, 1), 0.5, Material.emissive("lamp", Rgb.gray(0.5), Rgb.gray(12)))
                .camera(new dev.strahl.scene.Camera(new Vector3d(0, 1, 4), new Vector3d(0, 0.5, 0), new Vector3d(0, 1, 0), 40))
                .environment(new Rgb(0.05, 0.05, 0.1))
                .build();
    }

    @Test
    void twoJobsAtOnceGiveTheSameImagesAsEachAlone() throws Exception {
        Scene cornell = SceneLoader.load(Path.of("scenes", "cornell-box.json"));
        Scene spheres = inCode();
        RenderSettings a = RenderSettings.defaults().withSize(40, 30).withSamplesPerPixel(6).withSeed(1).withThreads(2);
        RenderSettings b = RenderSettings.defaults().withSize(33, 20).withSamplesPerPixel(5).withSeed(2).withThreads(2).withMaxDepth(4);
        Image aloneA = Renders.render(cornell, a);
        Image aloneB = Renders.render(spheres, b);
        Image togetherA;
        Image togetherB;
        try (RenderJob ja = RenderJob.start(cornell, a); RenderJob jb = RenderJob.start(spheres, b)) {
            togetherA = ja.awaitCompletion();
            togetherB = jb.awaitCompletion();
        }
        assertThat(togetherA).isEqualTo(aloneA);
        assertThat(togetherB).isEqualTo(aloneB);
        assertThat(aloneB.mean()[0]).isPositive();
        // the same scene in two jobs at once, too
        try (RenderJob j1 = RenderJob.start(spheres, b); RenderJob j2 = RenderJob.start(spheres, b)) {
            assertThat(j1.awaitCompletion()).isEqualTo(aloneB);
            assertThat(j2.awaitCompletion()).isEqualTo(aloneB);
        }
    }

    @Test
    void theListenerHearsEveryPassWithItsFiguresAndTheSnapshotIsTheLastPass() throws Exception {
        List<RenderStats> passes = new CopyOnWriteArrayList<>();
        List<Image> images = new CopyOnWriteArrayList<>();
        RenderSettings s = RenderSettings.defaults().withSize(20, 20).withSamplesPerPixel(16).withSeed(4);
        try (RenderJob job = RenderJob.start(inCode(), s, new RenderListener() {
            @Override
            public void passFinished(RenderStats soFar, Image image) {
                passes.add(soFar);
                images.add(image);
            }
        })) {
            job.awaitCompletion();
            assertThat(job.snapshot()).isEqualTo(images.get(images.size() - 1)).isEqualTo(job.film().toImage());
        }
        assertThat(passes).extracting(RenderStats::samplesPerPixel).containsExactly(1, 2, 4, 8, 16);
        assertThat(passes).extracting(RenderStats::passes).containsExactly(1, 2, 3, 4, 5);
        assertThat(passes.get(4).samples()).isEqualTo(16L * 20 * 20);
        assertThat(passes).allSatisfy(p -> assertThat(p.samplesPerSecond()).isPositive());
    }

    @Test
    void aSnapshotDuringTheRenderIsAWholePassAndTheOldPassCompletedStillHears() throws Exception {
        List<Integer> spp = new CopyOnWriteArrayList<>();
        List<Image> images = new CopyOnWriteArrayList<>();
        RenderSettings s = RenderSettings.defaults().withSize(48, 48).withSamplesPerPixel(64).withSeed(5);
        try (RenderJob job = RenderJob.start(inCode(), s, new RenderListener() {
            @Override
            public void passCompleted(int samplesPerPixel, Image image) {
                spp.add(samplesPerPixel);
                images.add(image);
            }
        })) {
            Image seen = null;
            while (!job.isDone()) {
                Image now = job.snapshot();
                if (!now.equals(new Image(48, 48, new float[3 * 48 * 48]))) {
                    seen = now;
                    break;
                }
                Thread.onSpinWait();
            }
            job.awaitCompletion();
            Image first = seen;
            assertThat(first).isNotNull();
            assertThat(images).as("the snapshot is one of the pass images").anySatisfy(i -> assertThat(i).isEqualTo(first));
        }
        assertThat(spp).startsWith(1, 2, 4, 8, 16).endsWith(64);
    }

    @Test
    void cancelStopsSoonAndKeepsTheLastWholePass() throws Exception {
        RenderSettings s = RenderSettings.defaults().withSize(64, 64).withSamplesPerPixel(100_000).withSeed(6);
        try (RenderJob job = RenderJob.start(inCode(), s)) {
            while (job.completedSamplesPerPixel() < 2) {
                Thread.sleep(5);
            }
            job.cancel();
            RenderStats stats = job.awaitStats();
            assertThat(stats.cancelled()).isTrue();
            assertThat(stats.samplesPerPixel()).isLessThan(100_000);
            assertThat(job.snapshot().mean()[0]).isPositive();
        }
    }

    @Test
    void theSnapshotToneMapsToTheDisplayImage() {
        Image img = Renders.render(inCode(), RenderSettings.defaults().withSize(16, 12).withSamplesPerPixel(2));
        BufferedImage bi = DisplayEncoding.toBufferedImage(img, 0);
        assertThat(bi.getWidth()).isEqualTo(16);
        assertThat(bi.getHeight()).isEqualTo(12);
        float[] rgb = img.rgb();
        assertThat(rgb).hasSize(3 * 16 * 12);
        int x = 7, y = 5, o = 3 * (y * 16 + x);
        int expected = DisplayEncoding.toSrgb8(rgb[o]) << 16 | DisplayEncoding.toSrgb8(rgb[o + 1]) << 8 | DisplayEncoding.toSrgb8(rgb[o + 2]);
        assertThat(bi.getRGB(x, y) & 0xFFFFFF).isEqualTo(expected);
    }
}
