package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.film.Film;
import dev.strahl.image.Image;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import dev.strahl.testing.Renders;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A noise threshold (adaptive sampling) on the Cornell Box with the glass and the mirror sphere: the
 * same bits on any thread count and pass size and across a resume; samples go where the noise is;
 * the render ends by itself; the stopping rule adds no bias beyond the golden tests' tolerance.
 */
class AdaptiveSamplingTest {
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withSize(48, 36).withSamplesPerPixel(512).withSeed(5)
            .withNoiseThreshold(0.1).withThreads(2);
    private static Scene scene;

    @TempDir
    Path dir;

    @BeforeAll
    static void load() throws Exception {
        scene = SceneLoader.load(Path.of("scenes/cornell-sphere.json"));
    }

    @Test
    void oneTwoAndThreeThreadsAndAnyPassSizeGiveTheSameBits() throws Exception {
        RenderBuffers one;
        try (RenderJob job = RenderJob.start(scene, SETTINGS.withThreads(1).withAovs(Set.of(Aov.SPP)))) {
            one = job.awaitBuffers();
        }
        assertThat(Renders.render(scene, SETTINGS).rgb()).isEqualTo(one.color().rgb());
        assertThat(Renders.render(scene, SETTINGS.withThreads(3).withSamplesPerPass(5)).rgb()).isEqualTo(one.color().rgb());
        assertThat(Renders.render(scene, SETTINGS.withSamplesPerPass(1)).rgb()).isEqualTo(one.color().rgb());
        assertThat(Renders.render(scene, SETTINGS.withSeed(6)).rgb()).isNotEqualTo(one.color().rgb());
        float min = Float.MAX_VALUE, max = 0;
        for (float n : one.samples().rgb()) {
            min = Math.min(min, n);
            max = Math.max(max, n);
        }
        assertThat(min).as("the fewest samples: the first decision's").isEqualTo(NoiseTarget.MIN_SAMPLES);
        assertThat(max).as("the noisiest pixels go on to the cap").isEqualTo(512);
    }

    @Test
    void withoutAThresholdEveryPixelTakesTheSampleCount() throws Exception {
        RenderSettings uniform = SETTINGS.withNoiseThreshold(0).withSamplesPerPixel(40).withAovs(Set.of(Aov.SPP));
        try (RenderJob job = RenderJob.start(scene, uniform)) {
            RenderBuffers b = job.awaitBuffers();
            for (float n : b.samples().rgb()) {
                assertThat(n).isEqualTo(40);
            }
            RenderStats s = job.awaitStats();
            assertThat(s.minSamplesPerPixel()).isEqualTo(40);
            assertThat(s.maxSamplesPerPixel()).isEqualTo(40);
            assertThat(s.meanSamplesPerPixel()).isEqualTo(40);
            assertThat(s.convergedFraction()).isZero();
        }
    }

    /** Saved in the middle of passes (and of decisions), resumed on another thread count: the same bits as never stopped. */
    @Test
    void aResumedRenderIsTheSameBitsAsOneNeverStopped() throws Exception {
        Image uninterrupted = Renders.render(scene, SETTINGS);
        for (int delay : new int[] {30, 120, 400}) {
            Path file = dir.resolve("a" + delay + ".ck");
            try (RenderJob first = RenderJob.start(scene, SETTINGS)) {
                Thread.sleep(delay);
                first.saveCheckpoint(file);
                first.cancel();
            }
            try (RenderJob second = RenderJob.resumeFrom(file, scene, SETTINGS.withThreads(1), new RenderListener() {})) {
                assertThat(second.awaitCompletion().rgb()).as("saved after %d ms", delay).isEqualTo(uninterrupted.rgb());
            }
        }
        Path file = dir.resolve("other.ck");
        try (RenderJob first = RenderJob.start(scene, SETTINGS.withSamplesPerPixel(40))) {
            first.awaitCompletion();
            first.saveCheckpoint(file);
        }
        assertThat(Files.size(file)).isEqualTo(Checkpoint.of(scene, SETTINGS).fileSize());
        for (RenderSettings other : new RenderSettings[] {SETTINGS.withNoiseThreshold(0.2), SETTINGS.withNoiseThreshold(0)}) {
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> RenderJob.resumeFrom(file, scene, other, new RenderListener() {}))
                    .hasMessageContaining("noiseThreshold");
        }
    }

    @Test
    void aLooseThresholdEndsTheRenderByItselfWithTheFiguresToSayIt() throws Exception {
        RenderSettings loose = SETTINGS.withNoiseThreshold(0.5).withSamplesPerPixel(100_000);
        try (RenderJob job = RenderJob.start(scene, loose)) {
            RenderStats s = job.awaitStats();
            assertThat(s.convergedFraction()).isEqualTo(1);
            assertThat(s.cancelled()).isFalse();
            assertThat(s.maxSamplesPerPixel()).isLessThan(100_000);
            assertThat(s.minSamplesPerPixel()).isEqualTo(NoiseTarget.MIN_SAMPLES);
            assertThat(s.meanSamplesPerPixel()).isBetween((double) s.minSamplesPerPixel(), (double) s.maxSamplesPerPixel());
            assertThat(s.samples()).isEqualTo(Math.round(s.meanSamplesPerPixel() * 48 * 36));
            assertThat(job.progress()).isEqualTo(1);
        }
    }

    /**
     * The stopping rule's bias, on the scene's small bright caustic under the glass sphere (rare
     * paths: light, glass, floor, found by the floor's BSDF samples): with the same seed, an
     * adaptive pixel's samples are the first of the uniform render's at the cap, so their
     * difference, averaged over seeds, is the bias of stopping early alone. It stays below the
     * golden tests' 1 % per region ({@code CornellGoldenTest.REGION_TOLERANCE}) on the image and on every
     * 8×8 block, the caustic's among them.
     */
    @Test
    void theStoppingRuleAddsNoBiasBeyondTheGoldenTolerance() {
        int w = 32, h = 24, seeds = 6;
        RenderSettings adaptive = SETTINGS.withSize(w, h).withSamplesPerPixel(384).withNoiseThreshold(0.05);
        double[] diff = new double[w * h], ref = new double[w * h];
        for (int seed = 1; seed <= seeds; seed++) {
            Image a = Renders.render(scene, adaptive.withSeed(seed));
            Image u = Renders.render(scene, adaptive.withSeed(seed).withNoiseThreshold(0));
            for (int i = 0; i < w * h; i++) {
                double la = Film.luminance(a.rgb()[3 * i], a.rgb()[3 * i + 1], a.rgb()[3 * i + 2]);
                double lu = Film.luminance(u.rgb()[3 * i], u.rgb()[3 * i + 1], u.rgb()[3 * i + 2]);
                diff[i] += (la - lu) / seeds;
                ref[i] += lu / seeds;
            }
        }
        double worst = 0;
        for (int by = 0; by < h; by += 8) {
            for (int bx = 0; bx < w; bx += 8) {
                double d = 0, r = 0;
                for (int y = by; y < by + 8; y++) {
                    for (int x = bx; x < bx + 8; x++) {
                        d += diff[y * w + x];
                        r += ref[y * w + x];
                    }
                }
                worst = Math.abs(d / r) > Math.abs(worst) ? d / r : worst;
            }
        }
        double all = java.util.Arrays.stream(diff).sum() / java.util.Arrays.stream(ref).sum();
        System.out.printf("stopping-rule bias: image %+.4f %%, worst 8x8 block %+.4f %%%n", 100 * all, 100 * worst);
        assertThat(Math.abs(all)).isLessThan(0.01);
        assertThat(Math.abs(worst)).isLessThan(0.01);
    }
}
