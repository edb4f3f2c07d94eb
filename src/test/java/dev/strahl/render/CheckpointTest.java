package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.scene.Camera;
import dev.strahl.film.Film;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.Texture;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.io.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.joml.Vector3d;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Interrupt and resume: a render saved at any moment and resumed gives the very bits of one that
 * ran through; a checkpoint of another scene, other settings, or a damaged file is refused.
 */
class CheckpointTest {
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withSize(40, 30).withSamplesPerPixel(24).withSeed(9);
    private static Scene cornell;
    private static Film uninterrupted;

    @TempDir
    Path dir;

    @BeforeAll
    static void renderOnceThrough() throws Exception {
        cornell = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        try (RenderJob job = RenderJob.start(cornell, SETTINGS)) {
            uninterrupted = TestJobs.awaitFilm(job);
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 2, 4, 8, 23})
    void resumingAtAPassBoundaryIsBitIdentical(int savedSpp) throws Exception {
        Checkpoint cp = Checkpoint.of(cornell, SETTINGS);
        Path file = dir.resolve("a.ck");
        try (RenderJob first = RenderJob.start(cornell, SETTINGS.withSamplesPerPixel(savedSpp))) {
            cp.save(file, TestJobs.awaitFilm(first), null, 0, first.awaitStats().seconds());
        }
        Checkpoint.Restored restored = cp.restore(file);
        assertThat(restored.samplesPerPixel()).isEqualTo(savedSpp);
        try (RenderJob second = TestJobs.resume(cornell, SETTINGS, restored.film(), new RenderListener() {})) {
            assertSameBits(TestJobs.awaitFilm(second), uninterrupted);
            assertThat(second.awaitStats().samplesPerPixel()).isEqualTo(24);
            assertThat(second.awaitStats().samples()).isEqualTo((24L - savedSpp) * 40 * 30);
        }
    }

    /** Cancelled at an arbitrary moment, mid-pass, some pixels ahead of others: still the same bits. */
    @ParameterizedTest
    @ValueSource(ints = {0, 3, 20, 60})
    void resumingAfterACancelAtAnyMomentIsBitIdentical(int delayMillis) throws Exception {
        Checkpoint cp = Checkpoint.of(cornell, SETTINGS);
        Path file = dir.resolve("b.ck");
        try (RenderJob first = RenderJob.start(cornell, SETTINGS.withThreads(2))) {
            Thread.sleep(delayMillis);
            first.cancel();
            cp.save(file, TestJobs.awaitFilm(first), null, first.invalidSamples(), first.elapsedSeconds());
        }
        Film restored = cp.restore(file).film();
        try (RenderJob second = TestJobs.resume(cornell, SETTINGS.withThreads(1), restored, new RenderListener() {})) {
            assertSameBits(TestJobs.awaitFilm(second), uninterrupted);
        }
    }

    /**
     * Cancelled while a pass is half done, seen in the film: some pixels hold a sample more than
     * others. (A cancel at a chosen delay above may fall between passes or after the end.)
     */
    @Test
    void resumingAfterACancelInTheMiddleOfAPassIsBitIdentical() throws Exception {
        int pixels = SETTINGS.output().width() * SETTINGS.output().height();
        Checkpoint cp = Checkpoint.of(cornell, SETTINGS);
        Path file = dir.resolve("m.ck");
        boolean midPass = false;
        for (int attempt = 0; attempt < 5 && !midPass; attempt++) {
            try (RenderJob first = RenderJob.start(cornell, SETTINGS.withThreads(2))) {
                long done;
                while (((done = first.samplesDone()) == 0 || done % pixels == 0) && !first.isDone()) {
                    Thread.onSpinWait();               // rows are counted as they finish: a count between passes' totals is mid-pass
                }
                first.cancel();
                Film film = TestJobs.awaitFilm(first);
                midPass = maxSampleCount(film) > film.minSampleCount();
                cp.save(file, film, null, first.invalidSamples(), first.elapsedSeconds());
            }
        }
        assertThat(midPass).as("a cancel in the middle of a pass in 5 attempts").isTrue();
        try (RenderJob second = TestJobs.resume(cornell, SETTINGS.withThreads(1), cp.restore(file).film(), new RenderListener() {})) {
            assertSameBits(TestJobs.awaitFilm(second), uninterrupted);
        }
    }

    private static int maxSampleCount(Film film) {
        int max = 0;
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                max = Math.max(max, film.sampleCount(x, y));
            }
        }
        return max;
    }

    @Test
    void resumingTwiceAndGoingFurtherIsBitIdenticalToo() throws Exception {
        Checkpoint cp = Checkpoint.of(cornell, SETTINGS);
        Path file = dir.resolve("c.ck");
        Film film = new Film(40, 30);
        for (int spp : new int[] {3, 11, 24}) {
            try (RenderJob job = TestJobs.resume(cornell, SETTINGS.withSamplesPerPixel(spp), film, new RenderListener() {})) {
                cp.save(file, TestJobs.awaitFilm(job), null, 0, 0);
            }
            film = cp.restore(file).film();
        }
        assertSameBits(film, uninterrupted);
    }

    @Test
    void aCheckpointSavedFromTheListenerHoldsThatPass() throws Exception {
        Checkpoint cp = Checkpoint.of(cornell, SETTINGS);
        Path file = dir.resolve("d.ck");
        var job = new java.util.concurrent.atomic.AtomicReference<RenderJob>();
        int[] saves = {0};
        RenderListener saver = new RenderListener() {
            @Override
            public void passCompleted(int spp, dev.strahl.image.Image image) {
                if (spp == 8) {
                    try {
                        job.get().saveCheckpoint(file);
                        saves[0]++;
                    } catch (IOException | InterruptedException e) {
                        throw new AssertionError(e);
                    }
                }
            }
        };
        try (RenderJob j = RenderJob.start(cornell, SETTINGS.withSamplesPerPass(1).withThreads(2), new RenderListener() {
            @Override
            public void passCompleted(int spp, dev.strahl.image.Image image) {
                while (job.get() == null) {
                    Thread.onSpinWait();
                }
                saver.passCompleted(spp, image);
            }
        })) {
            job.set(j);
            j.awaitStats();
        }
        assertThat(saves[0]).isEqualTo(1);
        Checkpoint.Restored at8 = cp.restore(file);
        assertThat(at8.samplesPerPixel()).isEqualTo(8);
        try (RenderJob resumed = RenderJob.resumeFrom(file, cornell, SETTINGS, new RenderListener() {})) {
            assertSameBits(TestJobs.awaitFilm(resumed), uninterrupted);
            // what it began with, not what it has reached (render --resume's message; it once raced with the first pass)
            assertThat(resumed.earlierSamplesPerPixel()).isEqualTo(8);
            assertThat(resumed.completedSamplesPerPixel()).isEqualTo(SETTINGS.sampling().samplesPerPixel()).isNotEqualTo(8);
        }
    }

    /** A checkpoint taken while the workers are in the middle of a pass, then resumed: the same bits. */
    @Test
    void aCheckpointSavedWhileRenderingResumesBitIdentically() throws Exception {
        Path file = dir.resolve("w.ck");
        try (RenderJob first = RenderJob.start(cornell, SETTINGS.withThreads(2))) {
            while (first.samplesDone() == 0 && !first.isDone()) {
                Thread.onSpinWait();
            }
            first.saveCheckpoint(file);
            first.cancel();
        }
        try (RenderJob second = RenderJob.resumeFrom(file, cornell, SETTINGS.withThreads(1), new RenderListener() {})) {
            assertSameBits(TestJobs.awaitFilm(second), uninterrupted);
        }
    }

    /** Paused and resumed at any moment, the render gives the bits of one that ran through. */
    @ParameterizedTest
    @ValueSource(ints = {0, 5, 30})
    void pausingAndResumingChangesNoBit(int delayMillis) throws Exception {
        try (RenderJob job = RenderJob.start(cornell, SETTINGS.withThreads(2))) {
            Thread.sleep(delayMillis);
            job.pause();
            assertThat(job.isPaused()).isTrue();
            Thread.sleep(100);                     // each worker finishes the tile it is on
            long held = job.samplesDone();
            Thread.sleep(100);
            assertThat(job.samplesDone()).as("no tile is started while paused").isEqualTo(held);
            job.resume();
            assertThat(job.isPaused()).isFalse();
            assertSameBits(TestJobs.awaitFilm(job), uninterrupted);
        }
    }

    @Test
    void aCheckpointThatReachedTheTargetRendersNothingMore() throws Exception {
        Checkpoint cp = Checkpoint.of(cornell, SETTINGS);
        Path file = dir.resolve("e.ck");
        cp.save(file, uninterrupted, null, 5, 1.5);
        Checkpoint.Restored r = cp.restore(file);
        assertThat(r.invalidSamples()).isEqualTo(5);
        assertThat(r.seconds()).isEqualTo(1.5);
        try (RenderJob job = TestJobs.resume(cornell, SETTINGS.withSamplesPerPixel(10), r.film(), new RenderListener() {})) {
            assertThat(job.await(30, TimeUnit.SECONDS)).isTrue();
            assertThat(job.awaitStats().samples()).isZero();
            assertSameBits(job.film(), uninterrupted);
        }
    }

    // ---- refusals ------------------------------------------------------------------------------

    @Test
    void otherSettingsAreRefusedNamingTheSetting() throws Exception {
        Path file = dir.resolve("s.ck");
        Checkpoint.of(cornell, SETTINGS).save(file, uninterrupted, null, 0, 0);
        assertRefused(Checkpoint.of(cornell, SETTINGS.withSeed(10)), file, "other settings", "seed 9 in the checkpoint, 10 now");
        assertRefused(Checkpoint.of(cornell, SETTINGS.withMaxDepth(5)), file, "maxDepth -1 in the checkpoint, 5 now");
        assertRefused(Checkpoint.of(cornell, SETTINGS.withSize(41, 30)), file, "width 40 in the checkpoint, 41 now");
        assertRefused(Checkpoint.of(cornell, SETTINGS.withIntegrator(dev.strahl.render.IntegratorKind.DIRECT)), file, "integrator");
        System.setProperty("strahl.sampler", "independent");
        try {
            assertRefused(Checkpoint.of(cornell, SETTINGS), file, "sampler stratified in the checkpoint, independent now");
        } finally {
            System.clearProperty("strahl.sampler");
        }
        // what does not change the bits may differ
        Checkpoint.of(cornell, SETTINGS.withSamplesPerPixel(1000).withThreads(1).withSamplesPerPass(3)
                .withTimeLimit(java.time.Duration.ofSeconds(5))).restore(file);
    }

    /** The teaching option without shadows changes the image: a checkpoint of one is not resumed with the other. */
    @Test
    void shadowsOrNoneAreInTheFingerprint() throws Exception {
        assertThat(Checkpoint.settingsKey(SETTINGS)).contains(";shadows=true;");
        assertThat(Checkpoint.settingsKey(SETTINGS.withShadows(false))).contains(";shadows=false;");
        Path with = dir.resolve("with.ck");
        Checkpoint.of(cornell, SETTINGS).save(with, uninterrupted, null, 0, 0);
        assertRefused(Checkpoint.of(cornell, SETTINGS.withShadows(false)), with, "other settings", "shadows true in the checkpoint, false now");
        Path without = dir.resolve("without.ck");
        Checkpoint.of(cornell, SETTINGS.withShadows(false)).save(without, uninterrupted, null, 0, 0);
        assertRefused(Checkpoint.of(cornell, SETTINGS), without, "shadows false in the checkpoint, true now");
    }

    /** A checkpoint saved before strahl had the shadows setting was rendered with shadows: it resumes with them, and only with them. */
    @Test
    void aCheckpointFromBeforeTheShadowsSettingResumesWithShadows() throws Exception {
        Path file = dir.resolve("older.ck");
        Checkpoint.of(cornell, SETTINGS).save(file, uninterrupted, null, 0, 0);
        removeSetting(file, ";shadows=true");
        assertSameBits(Checkpoint.of(cornell, SETTINGS).restore(file).film(), uninterrupted);
        assertRefused(Checkpoint.of(cornell, SETTINGS.withShadows(false)), file, "shadows true in the checkpoint, false now");
        assertRefused(Checkpoint.of(cornell, SETTINGS.withSeed(10)), file, "seed 9 in the checkpoint, 10 now");
    }

    /** A checkpoint of version 2, written before the noise threshold: it resumes as a render without one, and only as that. */
    @Test
    void aCheckpointOfVersionTwoResumesWithoutANoiseThreshold() throws Exception {
        Path file = dir.resolve("v2.ck");
        Checkpoint.of(cornell, SETTINGS).save(file, uninterrupted, null, 0, 0);
        byte[] b = Files.readAllBytes(file);
        b[11] = 2;
        Files.write(file, b);
        removeSetting(file, ";noiseThreshold=0.0");
        assertSameBits(Checkpoint.of(cornell, SETTINGS).restore(file).film(), uninterrupted);
        assertRefused(Checkpoint.of(cornell, SETTINGS.withNoiseThreshold(0.05)), file, "noiseThreshold 0.0 in the checkpoint, 0.05 now");
    }

    /** Rewrites a checkpoint as one without {@code entry} in its settings: the string, its length and the checksum. */
    private static void removeSetting(Path file, String entry) throws IOException {
        byte[] b = Files.readAllBytes(file);
        int at = 8 + 4 + 32;                            // magic, version, scene digest
        int length = ((b[at] & 0xff) << 8) | (b[at + 1] & 0xff);
        String settings = new String(b, at + 2, length, java.nio.charset.StandardCharsets.US_ASCII);
        assertThat(settings).contains(entry);
        byte[] shorter = settings.replace(entry, "").getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        var body = new java.io.ByteArrayOutputStream();
        body.write(b, 0, at);
        body.write(shorter.length >> 8);
        body.write(shorter.length & 0xff);
        body.write(shorter);
        body.write(b, at + 2 + length, b.length - 4 - (at + 2 + length));
        var crc = new java.util.zip.CRC32C();
        crc.update(body.toByteArray());
        int c = (int) crc.getValue();
        body.write(new byte[] {(byte) (c >>> 24), (byte) (c >>> 16), (byte) (c >>> 8), (byte) c});
        Files.write(file, body.toByteArray());
    }

    @Test
    void anotherSceneOrCameraIsRefused() throws Exception {
        Path file = dir.resolve("t.ck");
        Checkpoint.of(cornell, SETTINGS).save(file, uninterrupted, null, 0, 0);
        Scene mirror = SceneLoader.load(Path.of("scenes/cornell-mirror.json"));
        assertRefused(Checkpoint.of(mirror, SETTINGS), file, "another scene");
        Camera c = cornell.camera();
        Scene moved = cornell.withCamera(new Camera(new Vector3d(c.lookFrom()).add(0, 0, 1e-9), c.lookAt(), c.up(), c.fovDegrees()));
        assertRefused(Checkpoint.of(moved, SETTINGS), file, "another scene");
        // the same content loaded again is the same scene
        Checkpoint.of(SceneLoader.load(Path.of("scenes/cornell-box.json")), SETTINGS).restore(file);
    }

    @Test
    void aTextureWithOtherPixelsUnderTheSameNameIsAnotherScene() throws Exception {
        Path png = dir.resolve("wood.png");
        Scene first = texturedQuad(png, 0x806040);
        Path file = dir.resolve("tex.ck");
        Checkpoint.of(first, SETTINGS).save(file, uninterrupted, null, 0, 0);
        Checkpoint.of(texturedQuad(png, 0x806040), SETTINGS).restore(file);       // same pixels: the same scene
        assertRefused(Checkpoint.of(texturedQuad(png, 0x806041), SETTINGS), file, "another scene");
    }

    /** A quad whose albedo is a 2×2 texture of one colour, written to {@code png} first. */
    private static Scene texturedQuad(Path png, int rgb) throws IOException {
        BufferedImage image = new BufferedImage(2, 2, BufferedImage.TYPE_INT_RGB);
        for (int i = 0; i < 4; i++) {
            image.setRGB(i % 2, i / 2, rgb);
        }
        ImageIO.write(image, "png", png.toFile());
        Files.setLastModifiedTime(png, FileTime.fromMillis(System.currentTimeMillis() + rgb));   // not the texture cache's entry
        TriangleMesh quad = new TriangleMesh(new float[] {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1}, new int[] {0, 1, 2, 0, 2, 3}, null,
                new float[] {0, 0, 1, 0, 1, 1, 0, 1});
        return Scene.builder().addMesh(quad, Material.diffuse("wood", Texture.image(png))).build();
    }

    @Test
    void everyTruncationIsRefusedAsTruncated() throws Exception {
        Path file = dir.resolve("u.ck");
        Checkpoint cp = Checkpoint.of(cornell, SETTINGS);
        cp.save(file, uninterrupted, null, 0, 0);
        byte[] bytes = Files.readAllBytes(file);
        assertThat((long) bytes.length).isEqualTo(cp.fileSize());
        Path cut = dir.resolve("cut.ck");
        for (int length : new int[] {0, 3, 8, 12, 44, 60, 100, 200, bytes.length / 2, bytes.length - 5, bytes.length - 1}) {
            Files.write(cut, java.util.Arrays.copyOf(bytes, length));
            assertThatThrownBy(() -> cp.restore(cut)).as("cut at %d", length).isInstanceOf(CheckpointException.class)
                    .hasMessageStartingWith(cut + ": ")
                    .satisfies(e -> assertThat(e.getMessage()).containsAnyOf("truncated checkpoint", "not a strahl checkpoint"));
        }
    }

    @Test
    void everyFlippedByteIsRefused() throws Exception {
        Path file = dir.resolve("v.ck");
        Checkpoint cp = Checkpoint.of(cornell, SETTINGS);
        cp.save(file, uninterrupted, null, 0, 0);
        byte[] bytes = Files.readAllBytes(file);
        Path bad = dir.resolve("bad.ck");
        SplittableRandom random = new SplittableRandom(4);
        for (int trial = 0; trial < 300; trial++) {
            byte[] copy = bytes.clone();
            int at = trial < 100 ? trial : random.nextInt(copy.length);      // the whole header, then anywhere
            copy[at] ^= (byte) (1 << random.nextInt(8));
            Files.write(bad, copy);
            assertThatThrownBy(() -> cp.restore(bad)).as("byte %d flipped", at).isInstanceOf(CheckpointException.class)
                    .hasMessageStartingWith(bad + ": ");
        }
    }

    @Test
    void missingAndForeignFilesAreRefused() throws Exception {
        Checkpoint cp = Checkpoint.of(cornell, SETTINGS);
        assertRefused(cp, dir.resolve("none.ck"), "checkpoint not found");
        Path png = Files.write(dir.resolve("x.ck"), new byte[] {(byte) 0x89, 'P', 'N', 'G', 13, 10, 26, 10, 0, 0, 0, 0});
        assertRefused(cp, png, "not a strahl checkpoint");
        Path future = dir.resolve("y.ck");
        cp.save(future, uninterrupted, null, 0, 0);
        byte[] b = Files.readAllBytes(future);
        b[11] = 4;                                      // format version 4
        Files.write(future, b);
        assertRefused(cp, future, "version 4");
        b[11] = 1;                                      // version 1: before the film kept the variance
        Files.write(future, b);
        assertRefused(cp, future, "version 1", "render anew");
    }

    private static void assertRefused(Checkpoint cp, Path file, String... fragments) {
        assertThatThrownBy(() -> cp.restore(file)).isInstanceOf(CheckpointException.class)
                .hasMessageStartingWith(file + ": ")
                .satisfies(e -> {
                    for (String f : fragments) {
                        assertThat(e.getMessage()).contains(f);
                    }
                });
    }

    private static void assertSameBits(Film actual, Film expected) {
        assertThat(actual.width()).isEqualTo(expected.width());
        double[] a = new double[actual.stateSums()];
        double[] e = new double[expected.stateSums()];
        for (int y = 0; y < expected.height(); y++) {
            for (int x = 0; x < expected.width(); x++) {
                int na = actual.pixelState(x, y, a);
                int ne = expected.pixelState(x, y, e);
                assertThat(na).as("samples of pixel %d,%d", x, y).isEqualTo(ne);
                for (int c = 0; c < e.length; c++) {
                    assertThat(Double.doubleToRawLongBits(a[c])).as("pixel %d,%d sum %d", x, y, c)
                            .isEqualTo(Double.doubleToRawLongBits(e[c]));
                }
            }
        }
        assertThat(actual.toImage().rgb()).isEqualTo(expected.toImage().rgb());
    }
}
