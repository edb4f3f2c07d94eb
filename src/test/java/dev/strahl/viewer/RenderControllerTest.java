package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Image;
import dev.strahl.render.Aov;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderBuffers;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.scene.Scene;
import dev.strahl.io.SceneLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The controller's state machine, driven by hand: fake jobs, a manual timer and a manual clock. */
class RenderControllerTest {
    static Scene cornell;

    /** A job that renders nothing: the test reports its passes. */
    static final class FakeJob implements RenderJobs.Job {
        final Scene scene;
        final RenderSettings settings;
        final RenderListener listener;
        volatile boolean cancelled;
        volatile boolean paused;
        /** What {@link #snapshotBuffers()} answers. */
        volatile Optional<RenderBuffers> buffers = Optional.empty();

        FakeJob(Scene scene, RenderSettings settings, RenderListener listener) {
            this.scene = scene;
            this.settings = settings;
            this.listener = listener;
        }

        /** Reports a finished pass (on the calling thread: the controller never holds it). */
        void pass(int spp) {
            listener.passCompleted(spp, new Image(settings.output().width(), settings.output().height(), new float[3 * settings.output().width() * settings.output().height()]));
        }

        @Override
        public void cancel() {
            cancelled = true;
        }

        @Override
        public void pause() {
            paused = true;
        }

        @Override
        public void resume() {
            paused = false;
        }

        @Override
        public long samplesDone() {
            return 1000;
        }

        @Override
        public Optional<RenderBuffers> snapshotBuffers() {
            return buffers;
        }
    }

    /** Runs scheduled tasks when the test says so. */
    static final class ManualScheduler implements RenderJobs.Scheduler {
        final List<Runnable> tasks = new ArrayList<>();

        @Override
        public Runnable schedule(Runnable task, long delayMillis) {
            assertThat(delayMillis).isEqualTo(RenderController.SETTLE_MILLIS);
            tasks.add(task);
            return () -> tasks.remove(task);
        }

        void runAll() {
            List<Runnable> now = new ArrayList<>(tasks);
            tasks.clear();
            now.forEach(Runnable::run);
        }

        @Override
        public void shutdown() {
            tasks.clear();
        }
    }

    final List<FakeJob> jobs = new CopyOnWriteArrayList<>();
    final List<RenderController.Frame> frames = new CopyOnWriteArrayList<>();
    final ManualScheduler timer = new ManualScheduler();
    volatile long now;
    RenderController controller;

    @BeforeAll
    static void load() throws Exception {
        cornell = SceneLoader.load(Path.of("scenes", "cornell-box.json"));
    }

    @BeforeEach
    void start() {
        controller = controller(RenderController.UNLIMITED);
    }

    RenderController controller(int stopAt) {
        RenderSettings settings = RenderSettings.defaults().withSize(64, 48).withThreads(1);
        RenderController c = new RenderController(cornell, settings, stopAt,
                (scene, s, listener) -> {
                    FakeJob job = new FakeJob(scene, s, listener);
                    jobs.add(job);
                    return job;
                }, frames::add, timer, () -> now);
        c.start();
        glance();
        frames.clear();
        return c;
    }

    /** Lets the quick reduced-resolution pass that precedes every full restart finish; returns the full job. */
    FakeJob glance() {
        FakeJob quick = job();
        assertThat(quick.settings.output().width()).as("a glance at a quarter of the resolution").isEqualTo(16);
        quick.pass(1);
        assertThat(quick.cancelled).isTrue();
        assertThat(job().settings.output().width()).isEqualTo(64);
        return job();
    }

    FakeJob job() {
        return jobs.get(jobs.size() - 1);
    }

    @Test
    void startsWithAGlanceThenOneFullResolutionJobOfOneSamplePerPassWithoutEnd() {
        assertThat(jobs).hasSize(2);
        assertThat(jobs.get(0).settings.output().width()).isEqualTo(16);
        assertThat(jobs.get(0).settings.output().height()).isEqualTo(12);
        RenderSettings s = job().settings;
        assertThat(s.output().width()).isEqualTo(64);
        assertThat(s.output().height()).isEqualTo(48);
        assertThat(s.execution().samplesPerPass()).isEqualTo(1);
        assertThat(s.sampling().samplesPerPixel()).isEqualTo(Integer.MAX_VALUE);
        assertThat(controller.status().state()).isEqualTo(RenderController.State.RUNNING);
        assertThat(controller.status().preview()).isFalse();
    }

    @Test
    void everyPassIsShownAndCounted() {
        job().pass(1);
        job().pass(2);
        assertThat(frames).extracting(RenderController.Frame::samplesPerPixel).containsExactly(1, 2);
        assertThat(frames).allSatisfy(f -> assertThat(f.preview()).isFalse());
        assertThat(controller.status().samplesPerPixel()).isEqualTo(2);
    }

    @Test
    void pauseHoldsTheJobAndResumeLetsItGoOn() throws Exception {
        job().pass(1);
        controller.togglePause();
        assertThat(controller.status().state()).isEqualTo(RenderController.State.PAUSED);
        assertThat(job().paused).as("the job is paused at once").isTrue();
        job().pass(2);                          // a pass that was under way when the pause came
        assertThat(job().paused).isTrue();
        assertThat(frames).hasSize(2);          // the pass that finished is still shown
        assertThat(jobs).hasSize(2);            // and its samples are kept: no new job
        controller.togglePause();
        assertThat(job().paused).isFalse();
        assertThat(controller.status().state()).isEqualTo(RenderController.State.RUNNING);
        assertThat(job().cancelled).isFalse();
    }

    @Test
    void pausedTimeDoesNotCountAsRenderTime() throws Exception {
        now = TimeUnit.SECONDS.toNanos(2);
        controller.togglePause();               // paused from t = 2 s
        job().pass(1);
        now = TimeUnit.SECONDS.toNanos(10);
        assertThat(controller.status().seconds()).isCloseTo(2, within(1e-9));
        controller.togglePause();
        now = TimeUnit.SECONDS.toNanos(11);
        assertThat(controller.status().seconds()).isCloseTo(3, within(1e-9));
    }

    @Test
    void stopAtHoldsAtTheCountAndRaisingItContinuesTheSameAccumulation() throws Exception {
        controller = controller(4);
        FakeJob j = job();
        for (int spp = 1; spp <= 3; spp++) {
            j.pass(spp);
        }
        assertThat(controller.status().state()).isEqualTo(RenderController.State.RUNNING);
        j.pass(4);
        assertThat(j.paused).isTrue();
        assertThat(controller.status().state()).isEqualTo(RenderController.State.DONE);
        controller.togglePause();               // a finished render stays finished
        assertThat(controller.status().state()).isEqualTo(RenderController.State.DONE);
        assertThat(j.paused).isTrue();
        controller.setStopAt(8);
        assertThat(j.paused).isFalse();
        assertThat(controller.status().state()).isEqualTo(RenderController.State.RUNNING);
        assertThat(job()).as("same job, samples kept").isSameAs(j);
        j.pass(5);
        assertThat(controller.status().samplesPerPixel()).isEqualTo(5);
    }

    @Test
    void unlimitedNeverHolds() {
        for (int spp = 1; spp <= 100; spp++) {
            job().pass(spp);
        }
        assertThat(controller.status().state()).isEqualTo(RenderController.State.RUNNING);
    }

    @Test
    void restartCancelsTheJobAndStartsFromZero() {
        FakeJob first = job();
        first.pass(1);
        first.pass(2);
        controller.restart();
        assertThat(first.cancelled).isTrue();
        assertThat(jobs).hasSize(3);
        assertThat(controller.status().samplesPerPixel()).isZero();
        first.pass(3);                          // a late pass of the old job is ignored
        assertThat(frames).hasSize(2);
        assertThat(controller.status().samplesPerPixel()).isZero();
    }

    @Test
    void aCameraMoveRestartsAccumulationWithAPreviewThenFullResolutionWhenTheMovesStop() {
        FakeJob full = job();
        full.pass(1);
        full.pass(2);
        long generation = controller.status().generation();
        controller.moveCamera(c -> c.orbit(0.3, 0.1));
        assertThat(full.cancelled).isTrue();
        FakeJob preview = job();
        assertThat(preview.settings.output().width()).isEqualTo(16);
        assertThat(preview.settings.output().height()).isEqualTo(12);
        assertThat(preview.scene.camera().lookFrom().distance(cornell.camera().lookFrom())).isGreaterThan(0.1);
        RenderController.Status s = controller.status();
        assertThat(s.preview()).isTrue();
        assertThat(s.samplesPerPixel()).isZero();
        assertThat(s.generation()).isGreaterThan(generation);
        preview.pass(1);
        assertThat(frames.get(frames.size() - 1).preview()).isTrue();

        timer.runAll();                          // 150 ms without a move
        FakeJob again = job();
        assertThat(preview.cancelled).isTrue();
        assertThat(again.settings.output().width()).isEqualTo(64);
        assertThat(again.scene.camera().lookFrom()).isEqualTo(preview.scene.camera().lookFrom());
        assertThat(controller.status().preview()).isFalse();
    }

    @Test
    void movesDuringAPreviewPassAreAppliedTogetherWhenItEnds() {
        controller.moveCamera(c -> c.orbit(0.1, 0));
        FakeJob preview = job();
        controller.moveCamera(c -> c.orbit(0.1, 0));
        controller.moveCamera(c -> c.orbit(0.1, 0));
        assertThat(job()).as("no restart before the preview has shown a pass").isSameAs(preview);
        preview.pass(1);
        FakeJob next = job();
        assertThat(next).isNotSameAs(preview);
        assertThat(next.scene.camera().lookFrom().distance(controller.camera().toCamera().lookFrom())).isZero();
        assertThat(jobs).hasSize(4);
        controller.moveCamera(c -> c.orbit(0.1, 0));
        assertThat(job()).as("waits for this preview's first pass too").isSameAs(next);
        next.pass(1);
        assertThat(jobs).hasSize(5);
        assertThat(timer.tasks).as("one pending settle, re-armed by each move").hasSize(1);
    }

    @Test
    void resetCameraGoesBackToTheSceneCamera() {
        controller.moveCamera(c -> c.orbit(1, 0.5).pan(0.2, 0.1).dolly(0.5));
        controller.resetCamera();
        assertThat(timer.tasks).as("the pending settle is dropped: the reset restarts at once").isEmpty();
        glance();
        assertThat(job().scene.camera().lookFrom().distance(cornell.camera().lookFrom())).isLessThan(1e-12);
        assertThat(controller.status().preview()).isFalse();
    }

    @Test
    void resizingPreviewsAtTheNewSize() {
        controller.resize(64, 48);
        assertThat(jobs).as("same size: nothing to do").hasSize(2);
        controller.resize(200, 150);
        assertThat(job().settings.output().width()).isEqualTo(50);
        timer.runAll();
        assertThat(job().settings.output().width()).isEqualTo(200);
        assertThat(job().settings.output().height()).isEqualTo(150);
    }

    @Test
    void renderSettingsRestartOnlyWhenTheyChange() {
        controller.change(s -> s.withMaxDepth(-1));
        controller.change(s -> s.withHemisphere(HemisphereSampling.COSINE));
        controller.change(s -> s.withIntegrator(IntegratorKind.PATH));
        assertThat(jobs).hasSize(2);
        controller.change(s -> s.withMaxDepth(3));
        assertThat(glance().settings.transport().maxDepth()).isEqualTo(3);
        controller.change(s -> s.withHemisphere(HemisphereSampling.UNIFORM));
        assertThat(glance().settings.transport().hemisphere()).isEqualTo(HemisphereSampling.UNIFORM);
        controller.change(s -> s.withIntegrator(IntegratorKind.WHITTED));
        assertThat(glance().settings.transport().integrator()).isEqualTo(IntegratorKind.WHITTED);
        assertThat(controller.status().integrator()).isEqualTo(IntegratorKind.WHITTED);
        assertThat(jobs).hasSize(8);
        assertThat(jobs.subList(0, 7)).allSatisfy(j -> assertThat(j.cancelled).isTrue());
    }

    /** A scene with media: whitted and photon do not render it, so the viewer renders it with path and says so in the status. */
    @Test
    void aSceneWithMediaIsRenderedWithPathWhereWhittedOrPhotonIsChosen() throws Exception {
        Scene fog = SceneLoader.load(Path.of("src/test/resources/golden/media/fog.json"));
        controller.setScene(fog, RenderSettings.defaults().withSize(64, 48).withIntegrator(IntegratorKind.PHOTON));
        assertThat(job().settings.transport().integrator()).isEqualTo(IntegratorKind.PATH);
        controller.change(s -> s.withIntegrator(IntegratorKind.WHITTED));
        assertThat(controller.status().integrator()).isEqualTo(IntegratorKind.PATH);
        controller.change(s -> s.withIntegrator(IntegratorKind.DIRECT));
        assertThat(job().settings.transport().integrator()).isEqualTo(IntegratorKind.DIRECT);
        controller.setScene(cornell, RenderSettings.defaults().withSize(64, 48).withIntegrator(IntegratorKind.WHITTED));
        assertThat(job().settings.transport().integrator()).as("a scene of surfaces keeps its integrator").isEqualTo(IntegratorKind.WHITTED);
    }

    /** View → Denoise: feature buffers for full-resolution jobs (a restart only when they change), never for previews. */
    @Test
    void featureBuffersRestartOnlyWhenTheyChangeAndPreviewsKeepNone() {
        Set<Aov> all = EnumSet.allOf(Aov.class);
        controller.setAovs(all);
        FakeJob full = glance();
        assertThat(full.settings.output().aovs()).isEqualTo(all);
        assertThat(jobs.get(jobs.size() - 2).settings.output().aovs()).as("the glance").isEmpty();
        controller.setAovs(EnumSet.allOf(Aov.class));
        assertThat(job()).as("the same buffers: no restart").isSameAs(full);
        controller.moveCamera(c -> c.orbit(0.1, 0));
        assertThat(job().settings.output().aovs()).as("a preview").isEmpty();
        timer.runAll();
        assertThat(job().settings.output().aovs()).as("full resolution again").isEqualTo(all);
    }

    /** A frame's buffers are its job's, asked for when the frame's user wants them (the denoiser). */
    @Test
    void aFramesBuffersAreThoseOfItsJob() {
        FakeJob full = job();
        full.pass(1);
        RenderController.Frame f = frames.get(frames.size() - 1);
        assertThat(f.buffers().get()).isEmpty();
        RenderBuffers b = RenderBuffers.of(new dev.strahl.image.Image(64, 48, new float[3 * 64 * 48]));
        full.buffers = Optional.of(b);
        assertThat(f.buffers().get()).containsSame(b);
    }

    @Test
    void aNewSceneStartsFromItsOwnCamera() {
        controller.moveCamera(c -> c.orbit(1, 0));
        controller.setScene(cornell, controller.settings());
        assertThat(timer.tasks).isEmpty();
        assertThat(glance().scene.camera().lookFrom().distance(cornell.camera().lookFrom())).isLessThan(1e-12);
        assertThat(controller.status().preview()).isFalse();
    }

    @Test
    void aNewSceneRendersWithItsOwnSettings() {
        RenderSettings asked = controller.settings().withSize(80, 40).withIntegrator(IntegratorKind.DIRECT).withMaxDepth(7)
                .withSeed(42).withLightSamples(3).withHemisphere(HemisphereSampling.UNIFORM);
        controller.setScene(cornell, asked);
        FakeJob quick = job();
        assertThat(quick.settings.output().width()).as("the glance at a quarter of the new film").isEqualTo(20);
        assertThat(quick.settings.output().height()).isEqualTo(10);
        quick.pass(1);
        RenderSettings s = job().settings;
        assertThat(s.output().width()).isEqualTo(80);
        assertThat(s.output().height()).isEqualTo(40);
        assertThat(s.transport().integrator()).isEqualTo(IntegratorKind.DIRECT);
        assertThat(s.transport().maxDepth()).isEqualTo(7);
        assertThat(s.sampling().seed()).isEqualTo(42);
        assertThat(s.transport().lightSamples()).isEqualTo(3);
        assertThat(s.transport().hemisphere()).isEqualTo(HemisphereSampling.UNIFORM);
        assertThat(s.execution().samplesPerPass()).isEqualTo(1);
        assertThat(s.sampling().samplesPerPixel()).isEqualTo(Integer.MAX_VALUE);
        RenderController.Status status = controller.status();
        assertThat(status.integrator()).isEqualTo(IntegratorKind.DIRECT);
        assertThat(status.maxDepth()).isEqualTo(7);
        assertThat(status.hemisphere()).isEqualTo(HemisphereSampling.UNIFORM);
        assertThat(status.width()).isEqualTo(80);
        assertThat(controller.settings()).isEqualTo(asked);
    }

    @Test
    void closeCancelsTheJobAlsoWhenPaused() throws Exception {
        controller.togglePause();
        job().pass(1);
        assertThat(job().paused).isTrue();
        controller.close();
        assertThat(job().cancelled).isTrue();
        assertThat(controller.status().state()).isEqualTo(RenderController.State.CLOSED);
        controller.restart();
        controller.moveCamera(c -> c.orbit(1, 0));
        assertThat(jobs).as("nothing starts after closing").hasSize(2);
    }

    @Test
    void aMoveDuringTheGlanceWaitsForItAndThenPreviews() {
        controller.restart();
        FakeJob quick = job();
        controller.moveCamera(c -> c.orbit(0.2, 0));
        assertThat(job()).isSameAs(quick);
        quick.pass(1);
        assertThat(job().settings.output().width()).as("a preview, not the full job the glance would start").isEqualTo(16);
        assertThat(controller.status().preview()).isTrue();
        timer.runAll();
        assertThat(job().settings.output().width()).isEqualTo(64);
    }

    @Test
    void beforeTheWindowIsShownOnlyTheGlanceRenders() throws Exception {
        jobs.clear();
        RenderController c = new RenderController(cornell, RenderSettings.defaults().withSize(64, 48), RenderController.UNLIMITED,
                (scene, s, listener) -> {
                    FakeJob job = new FakeJob(scene, s, listener);
                    jobs.add(job);
                    return job;
                }, frames::add, timer, () -> now);
        c.startBeforeDisplay();
        job().pass(1);
        assertThat(job().paused).as("the glance waits for the window").isTrue();
        assertThat(jobs).hasSize(1);
        assertThat(frames).as("but its image is shown").hasSize(1);
        c.displayReady();
        assertThat(jobs).hasSize(2);
        assertThat(job().settings.output().width()).isEqualTo(64);
        c.close();
    }

    @Test
    void previewSizeIsAQuarterAndNeverZero() {
        assertThat(RenderJobs.previewSize(512)).isEqualTo(128);
        assertThat(RenderJobs.previewSize(3)).isEqualTo(1);
        assertThat(RenderJobs.previewSize(1)).isEqualTo(1);
    }
}
