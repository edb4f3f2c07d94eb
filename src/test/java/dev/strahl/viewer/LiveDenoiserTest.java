package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.render.Aov;
import dev.strahl.render.RenderBuffers;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import dev.strahl.io.SceneLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import javax.swing.JRootPane;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * The denoise toggle's state machine without a window: a manual clock, the denoiser's thread run
 * by hand, a stand-in filter and frames whose buffers the test says are still to be had or not.
 */
class LiveDenoiserTest {
    static final long MS = TimeUnit.MILLISECONDS.toNanos(1);

    /** The denoiser's thread, run by hand: tasks with the time they are due. */
    final class ManualThread implements RenderJobs.Scheduler {
        record Task(Runnable run, long due) {}

        final List<Task> tasks = new ArrayList<>();

        @Override
        public Runnable schedule(Runnable task, long delayMillis) {
            Task t = new Task(task, now + delayMillis * MS);
            tasks.add(t);
            return () -> tasks.remove(t);
        }

        /** Runs the tasks that are due, in order, including those they schedule and that are due. */
        int runDue() {
            int n = 0;
            for (Task t = next(); t != null; t = next()) {
                tasks.remove(t);
                t.run().run();
                n++;
            }
            return n;
        }

        private Task next() {
            return tasks.stream().filter(t -> t.due() <= now).findFirst().orElse(null);
        }

        @Override
        public void shutdown() {
            tasks.clear();
        }
    }

    /** A pass of a job: its image, and whether its job's film still holds it (what {@code snapshotBuffers} needs). */
    final class Pass {
        final RenderController.Frame frame;
        final RenderBuffers buffers;
        volatile boolean still = true;
        int copies;

        Pass(long generation, int spp, boolean preview) {
            Image image = new Image(2, 1, new float[] {spp, spp, spp, 0, 0, 0});
            buffers = RenderBuffers.of(image);
            frame = new RenderController.Frame(image, spp, preview, generation, () -> {
                copies++;
                return still ? Optional.of(buffers) : Optional.empty();
            });
        }
    }

    volatile long now = 1_000 * MS;
    /** How long the stand-in filter takes. */
    long filterNanos = 100 * MS;
    final List<RenderBuffers> filtered = new ArrayList<>();
    final ManualThread thread = new ManualThread();
    final FramePresenter presenter = new FramePresenter();
    final LiveDenoiser denoiser = new LiveDenoiser(presenter, b -> {
        filtered.add(b);
        now += filterNanos;
        float[] rgb = b.color().rgb();
        rgb[1] = -1;                           // a mark: "denoised"
        return new Image(2, 1, rgb);
    }, thread, () -> now);

    @AfterEach
    void close() {
        denoiser.close();
        presenter.close();
    }

    /** A full-resolution pass of job 1, reported to the denoiser (as the controller does at the end of the pass). */
    Pass pass(int spp) {
        return report(new Pass(1, spp, false));
    }

    Pass report(Pass p) {
        denoiser.accept(p.frame);
        return p;
    }

    /** The frame the display shows now, and whether it is denoised. */
    FramePresenter.Pick shown() {
        return presenter.pick();
    }

    static boolean isDenoisedImage(FramePresenter.Pick p) {
        return p.frame().image().get(0, 0, 1) == -1;
    }

    @Test
    void offTheFramesAreShownAsTheyAreAndNothingIsCopied() {
        Pass p = pass(1);
        pass(2);
        assertThat(thread.tasks).isEmpty();
        assertThat(p.copies).isZero();
        assertThat(shown().denoised()).isFalse();
        assertThat(shown().frame().samplesPerPixel()).isEqualTo(2);
    }

    @Test
    void onAPassIsCopiedAtTheEndOfItsPassAndDenoisedOnTheDenoisersThread() {
        denoiser.setEnabled(true, true);
        assertThat(thread.tasks).as("no frame yet").isEmpty();
        Pass p = pass(1);
        assertThat(p.copies).as("copied in the controller's call, while the film holds the pass").isEqualTo(1);
        assertThat(filtered).as("not denoised on the render's thread").isEmpty();
        assertThat(shown().denoised()).isFalse();
        thread.runDue();
        assertThat(filtered).containsExactly(p.buffers);
        assertThat(shown().denoised()).isTrue();
        assertThat(isDenoisedImage(shown())).isTrue();
        assertThat(shown().frame().samplesPerPixel()).isEqualTo(1);
        assertThat(shown().frame().generation()).isEqualTo(1);
        assertThat(denoiser.denoisedCount()).isEqualTo(1);
    }

    /**
     * Frames that come while a denoise runs are not copied; after it the denoiser rests three
     * times as long as it took, and the first frame after the rest is denoised: the ones between
     * are skipped.
     */
    @Test
    void framesDuringADenoiseAndItsRestAreSkippedAndTheNextIsDenoised() {
        denoiser.setEnabled(true, true);
        Pass p1 = pass(1);
        Pass p2 = pass(2);
        Pass p3 = pass(3);
        assertThat(p2.copies + p3.copies).as("busy: nothing copied").isZero();
        p3.still = false;                      // the render goes on
        thread.runDue();                       // denoises p1, takes 100 ms; a retry of p3 is due 300 ms later
        assertThat(filtered).containsExactly(p1.buffers);
        assertThat(thread.tasks).hasSize(1);
        assertThat(thread.tasks.get(0).due()).isEqualTo(now + LiveDenoiser.REST_FACTOR * filterNanos);
        now += 100 * MS;
        Pass p4 = pass(4);
        assertThat(p4.copies).as("resting").isZero();
        p4.still = false;
        now += 200 * MS;
        thread.runDue();                       // the retry: p4's pass is gone from the film
        assertThat(p4.copies).isEqualTo(1);
        assertThat(filtered).hasSize(1);
        assertThat(shown().frame().samplesPerPixel()).as("still p1's denoised image").isEqualTo(1);
        Pass p5 = pass(5);
        assertThat(p5.copies).isEqualTo(1);
        thread.runDue();
        assertThat(filtered).containsExactly(p1.buffers, p5.buffers);
        assertThat(shown().frame().samplesPerPixel()).isEqualTo(5);
        assertThat(shown().denoised()).isTrue();
        assertThat(p2.copies + p3.copies).isZero();
    }

    /** A render that holds (stop-at reached) keeps its film at the last pass: the waiting frame is denoised after the rest. */
    @Test
    void theLastPassOfAHeldRenderIsDenoisedAfterTheRest() {
        denoiser.setEnabled(true, true);
        Pass p1 = pass(1);
        Pass p2 = pass(2);                     // the render holds here: p2.still stays true
        thread.runDue();
        assertThat(filtered).containsExactly(p1.buffers);
        now += LiveDenoiser.REST_FACTOR * filterNanos;
        thread.runDue();
        assertThat(filtered).containsExactly(p1.buffers, p2.buffers);
        assertThat(shown().frame().samplesPerPixel()).isEqualTo(2);
        assertThat(shown().denoised()).isTrue();
    }

    /** Buffers that are not the waiting frame's (a newer pass ended meanwhile) are not denoised under its name. */
    @Test
    void buffersOfAnotherPassAreNotTakenForTheWaitingFrame() {
        denoiser.setEnabled(true, true);
        pass(1);
        Pass p2 = new Pass(1, 2, false);
        Pass p3 = new Pass(1, 3, false);
        RenderController.Frame mislabelled = new RenderController.Frame(p2.frame.image(), 2, false, 1, () -> Optional.of(p3.buffers));
        denoiser.accept(mislabelled);
        thread.runDue();
        now += LiveDenoiser.REST_FACTOR * filterNanos;
        thread.runDue();
        assertThat(filtered).hasSize(1);
    }

    @Test
    void previewsAreNotDenoisedAndAResultOfAReplacedJobIsDropped() {
        denoiser.setEnabled(true, true);
        pass(1);
        Pass preview = report(new Pass(2, 1, true));
        assertThat(preview.copies).isZero();
        thread.runDue();
        assertThat(filtered).hasSize(1);
        assertThat(denoiser.denoisedCount()).as("job 1 was replaced while it was denoised").isZero();
        assertThat(shown().frame()).isSameAs(preview.frame);
        assertThat(shown().denoised()).isFalse();
        now += 1000 * MS;
        Pass next = report(new Pass(2, 2, true));
        assertThat(next.copies).isZero();
        assertThat(thread.tasks).isEmpty();
    }

    @Test
    void turningOffShowsTheNoisyFrameAtOnceAndDropsTheRunningResult() {
        denoiser.setEnabled(true, true);
        Pass p1 = pass(1);
        thread.runDue();
        assertThat(shown().denoised()).isTrue();
        now += 1000 * MS;
        pass(2);
        denoiser.setEnabled(false, true);
        assertThat(shown().denoised()).isFalse();
        assertThat(shown().frame().samplesPerPixel()).isEqualTo(2);
        thread.runDue();
        assertThat(shown().denoised()).as("the result came after Denoise was turned off").isFalse();
        assertThat(denoiser.denoisedCount()).isEqualTo(1);
        assertThat(p1.copies).isEqualTo(1);
    }

    /** Turned on while the render holds at a pass, that pass is denoised at once; paused within a pass, the next one is. */
    @Test
    void turningOnDenoisesTheLastFrameIfItsPassIsStillThereElseTheNext() {
        Pass held = pass(1);
        denoiser.setEnabled(true, true);
        thread.runDue();
        assertThat(filtered).containsExactly(held.buffers);
        assertThat(shown().denoised()).isTrue();

        denoiser.setEnabled(false, true);
        now += 1000 * MS;
        Pass running = pass(2);
        running.still = false;                 // paused in the middle of the next pass
        denoiser.setEnabled(true, true);
        thread.runDue();
        assertThat(filtered).hasSize(1);
        assertThat(shown().denoised()).as("the denoised frame of pass 1 belongs to the same job").isTrue();
        assertThat(shown().frame().samplesPerPixel()).isEqualTo(1);
        Pass next = pass(3);
        thread.runDue();
        assertThat(filtered).containsExactly(held.buffers, next.buffers);

        denoiser.setEnabled(false, true);
        denoiser.setEnabled(true, false);      // its job is being replaced: wait for the next frame
        assertThat(thread.tasks).isEmpty();
    }

    /** The toggle's command: the guides are added to a render without them (one restart), not to one that has them. */
    @Test
    void theToggleAddsTheGuidesToTheRenderOnce() throws Exception {
        Scene cornell = SceneLoader.load(Path.of("scenes", "cornell-box.json"));
        List<RenderControllerTest.FakeJob> jobs = new ArrayList<>();
        RenderController controller = new RenderController(cornell, RenderSettings.defaults().withSize(64, 48).withThreads(1), 0,
                (scene, s, listener) -> {
                    RenderControllerTest.FakeJob job = new RenderControllerTest.FakeJob(scene, s, listener);
                    jobs.add(job);
                    return job;
                }, denoiser, new RenderControllerTest.ManualScheduler(), () -> now);
        controller.start();
        jobs.get(0).pass(1);
        FileActions files = new FileActions(null, presenter, s -> { }, null, f -> null, o -> { }, null);
        ViewerActions actions = new ViewerActions(controller, presenter, denoiser, files, new JRootPane(), () -> { });
        assertThat(jobs).hasSize(2);
        actions.setDenoise(true);
        assertThat(denoiser.enabled()).isTrue();
        assertThat(actions.denoise.getValue(javax.swing.Action.SELECTED_KEY)).isEqualTo(true);
        assertThat(jobs).as("a restart with the guides").hasSize(3);
        jobs.get(2).pass(1);
        assertThat(jobs.get(3).settings.output().aovs()).isEqualTo(EnumSet.allOf(Aov.class));
        actions.setDenoise(false);
        actions.setDenoise(true);
        assertThat(jobs).as("the render has its guides: no restart").hasSize(4);
        assertThat(controller.settings().output().aovs()).isEqualTo(EnumSet.allOf(Aov.class));
        controller.close();
    }

    @Test
    void theStatusBarSaysWhetherTheImageShownIsDenoised() {
        RenderController.Frame f = new Pass(1, 16, false).frame;
        assertThat(StatusBar.denoiseText(new FramePresenter.Shown(null, f, 0, null, true))).isEqualTo("denoised, 16 spp");
        assertThat(StatusBar.denoiseText(new FramePresenter.Shown(null, f, 0, null, false))).isEqualTo("not denoised yet");
        assertThat(StatusBar.denoiseText(null)).isEqualTo("not denoised yet");
        RenderController.Frame preview = new Pass(2, 1, true).frame;
        assertThat(StatusBar.denoiseText(new FramePresenter.Shown(null, preview, 0, null, false))).isEqualTo("preview not denoised");
        assertThat(FileActions.defaultName(Path.of("scenes/cornell-box.json"), 64, true)).isEqualTo("cornell-box-64spp-denoised.png");
        assertThat(FileActions.savedText(Path.of("a.png"), new FramePresenter.Pick(f, true))).isEqualTo("Saved a.png (16 spp, denoised)");
        assertThat(FileActions.savedText(Path.of("a.png"), new FramePresenter.Pick(f, false))).isEqualTo("Saved a.png (16 spp)");
    }
}
