package dev.strahl.viewer;

import dev.strahl.image.Image;
import dev.strahl.render.Aov;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.scene.Scene;
import java.util.Objects;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import java.util.function.UnaryOperator;

/**
 * What the viewer renders and when: the state machine behind pause, resume, restart, stop-at-N
 * and camera moves. No Swing and no rendering code; it starts {@link RenderJob}s (through a
 * {@link JobStarter}) and hands their images to a sink. Thread-safe: user actions call it from
 * the event dispatch thread, render threads report passes, a timer ends camera moves. No method
 * waits for rendering.
 *
 * <h2>Passes and holding</h2>
 * Each job renders passes of 1 sample per pixel without end. The controller pauses the job
 * ({@link RenderJob#pause()}: its workers wait after the tile they are on) while the viewer is
 * paused or has reached its stop-at count, and resumes it when the user resumes or raises the
 * count. So pausing keeps the accumulated samples, and holding costs nothing; no thread of the
 * job is ever blocked in a callback.
 *
 * <h2>Moving the camera</h2>
 * A camera move or a window resize starts a preview job at a quarter of the resolution in each
 * axis; further moves while a preview has not yet shown its first pass are collected and applied
 * when it has, so every preview job shows one image and the preview rate is the render rate.
 * {@value #SETTLE_MILLIS} ms after the last move, full-resolution accumulation starts again.
 * Other changes (start, restart, scene, integrator, depth, sampling, camera reset) render one
 * reduced-resolution pass first, which takes a few milliseconds, so that the change shows at
 * once, and then restart at full resolution.
 */
final class RenderController {

    /** RUNNING: accumulating; PAUSED: held by the user; DONE: held at the stop-at count, or every pixel met the noise threshold; CLOSED: for good. */
    enum State { RUNNING, PAUSED, DONE, CLOSED }

    /** Quiet time after the last camera move before full-resolution rendering restarts. */
    static final long SETTLE_MILLIS = 150;
    /** Stop-at value meaning "never stop". */
    static final int UNLIMITED = 0;

    /** One image to show: the mean after {@code samplesPerPixel} samples of job number {@code generation}; its pass's buffers. */
    record Frame(Image image, int samplesPerPixel, boolean preview, long generation, RenderJobs.Buffers buffers) {}

    /**
     * What the status bar shows. {@code seconds} counts only the time the job was not held; {@code converged} is the share of
     * pixels the noise threshold found converged (0 without one), {@code ended} whether the job ended by itself (all did).
     */
    record Status(State state, boolean preview, int samplesPerPixel, int stopAt, double seconds, long samples,
                  int width, int height, IntegratorKind integrator, int maxDepth, HemisphereSampling hemisphere, long generation,
                  double noiseThreshold, double converged, boolean ended) {
        double samplesPerSecond() {
            return seconds > 0 ? samples / seconds : 0;
        }
    }

    private final RenderJobs.Starter starter;
    private final Consumer<Frame> sink;
    private final SettleTimer settle;
    private final ActiveTime clock;

    private Scene scene;
    private ViewCamera view;
    private RenderSettings settings;          // full-resolution settings (size = the window's film)
    private int stopAt;
    private State state = State.RUNNING;

    private long generation;
    private RenderJobs.Job job;
    private boolean preview;
    private int samplesPerPixel;
    private double converged;
    /** The job ended by itself: every pixel met the noise threshold. */
    private boolean ended;
    private int passes;
    private boolean cameraPending;
    private boolean glance;
    private boolean waitingForDisplay;
    /** The glance pass has shown while the window was not yet on screen: full resolution starts with it. */
    private boolean fullAfterDisplay;

    RenderController(Scene scene, RenderSettings settings, int stopAt, RenderJobs.Starter starter, Consumer<Frame> sink,
                     RenderJobs.Scheduler scheduler, LongSupplier nanoTime) {
        this.scene = Objects.requireNonNull(scene, "scene");
        this.view = new ViewCamera(scene.camera());
        this.settings = SceneIntegrators.supported(scene, Objects.requireNonNull(settings, "settings"));
        this.stopAt = ViewerOptions.checkStopAt(stopAt);
        this.starter = starter;
        this.sink = sink;
        this.settle = new SettleTimer(scheduler, SETTLE_MILLIS);
        this.clock = new ActiveTime(nanoTime);
    }

    /** A controller that runs real {@link RenderJob}s and times camera moves on its own daemon thread. */
    static RenderController rendering(Scene scene, RenderSettings settings, int stopAt, Consumer<Frame> sink) {
        return new RenderController(scene, settings, stopAt, RenderJobs::start, sink, RenderJobs.timer(), System::nanoTime);
    }

    // --- user actions ------------------------------------------------------------------------

    /** Starts the first render. */
    synchronized void start() {
        if (job == null && state != State.CLOSED) {
            startJob(Mode.GLANCE);
        }
    }

    /**
     * Starts with the quick reduced-resolution pass only, and holds there until
     * {@link #displayReady()}: the window is built while only that small pass competes with it
     * for the processors, and full-resolution rendering starts once it is on screen.
     */
    synchronized void startBeforeDisplay() {
        waitingForDisplay = true;
        start();
    }

    /** The window is on screen: full-resolution rendering may start. */
    synchronized void displayReady() {
        waitingForDisplay = false;
        if (fullAfterDisplay && state != State.CLOSED) {
            startJob(Mode.FULL);
        }
    }

    /** Pauses a running render, or resumes a paused one; a finished one stays finished. */
    synchronized void togglePause() {
        if (state == State.RUNNING) {
            state = State.PAUSED;
            hold();
        } else if (state == State.PAUSED) {
            state = reachedStop() || ended ? State.DONE : State.RUNNING;
            if (state == State.RUNNING) {
                goOn();
            }
        }
    }

    /** Throws away the samples and renders again from the first. */
    synchronized void restart() {
        renderAgain();
    }

    /** Samples per pixel at which to hold, or {@link #UNLIMITED}; raising it continues a finished render. */
    synchronized void setStopAt(int n) {
        stopAt = ViewerOptions.checkStopAt(n);
        if (state == State.DONE && !reachedStop() && !ended) {
            state = State.RUNNING;
            goOn();
        }
    }

    /**
     * Changes a setting (the integrator, depth, hemisphere sampling, noise threshold of the toolbar):
     * a render with other settings starts again, unless {@code edit} changes nothing.
     */
    synchronized void change(UnaryOperator<RenderSettings> edit) {
        RenderSettings s = SceneIntegrators.supported(scene, edit.apply(settings));
        if (!s.equals(settings)) {
            settings = s;
            renderAgain();
        }
    }

    /** The feature buffers full-resolution jobs keep (View → Denoise adds its guides); previews keep none. */
    synchronized void setAovs(Set<Aov> aovs) {
        change(s -> s.withAovs(aovs));
    }

    /**
     * Shows another scene, from its own camera, with its own settings (integrator, depth,
     * sampling, seed, film size as the window fits it).
     */
    synchronized void setScene(Scene newScene, RenderSettings newSettings) {
        scene = Objects.requireNonNull(newScene, "scene");
        settings = SceneIntegrators.supported(newScene, Objects.requireNonNull(newSettings, "settings"));
        view = new ViewCamera(newScene.camera());
        renderAgain();
    }

    /**
     * Focuses the thin lens on the surface under a point of the image (fractions of its width and
     * height from the top left); nothing happens where the image shows no surface.
     *
     * @return the new focus distance, or NaN if nothing was hit
     */
    synchronized double focusAt(double fx, double fy) {
        double d = view.focusAt(scene, fx, fy, (double) settings.output().width() / settings.output().height());
        if (d > 0) {
            renderAgain();
        }
        return d;
    }

    /** Moves the camera (orbit, pan, dolly): preview now, full resolution once the moves stop. */
    synchronized void moveCamera(UnaryOperator<OrbitCamera> move) {
        view.move(move);
        moving();
    }

    /** Back to the scene's camera. */
    synchronized void resetCamera() {
        view.reset();
        renderAgain();
    }

    /** The film follows the window: a new size previews like a camera move. */
    synchronized void resize(int width, int height) {
        if (width == settings.output().width() && height == settings.output().height()) {
            return;
        }
        settings = settings.withSize(width, height);
        moving();
    }

    /** Stops rendering for good: the workers stop after the row they are on, also when paused. */
    synchronized void close() {
        state = State.CLOSED;
        generation++;
        if (job != null) {
            job.cancel();
            job = null;
        }
        settle.close();
    }

    /** What the status bar shows now. */
    synchronized Status status() {
        long samples = job != null ? job.samplesDone() : 0;
        int w = preview ? RenderJobs.previewSize(settings.output().width()) : settings.output().width();
        int h = preview ? RenderJobs.previewSize(settings.output().height()) : settings.output().height();
        return new Status(state, preview, samplesPerPixel, stopAt, clock.seconds(), samples, w, h, settings.transport().integrator(),
                settings.transport().maxDepth(), settings.transport().hemisphere(), generation, settings.sampling().noiseThreshold(),
                converged, ended);
    }

    synchronized OrbitCamera camera() {
        return view.orbit();
    }

    synchronized Scene scene() {
        return scene;
    }

    synchronized RenderSettings settings() {
        return settings;
    }

    synchronized int stopAt() {
        return stopAt;
    }

    // --- jobs --------------------------------------------------------------------------------

    private void moving() {
        if (state == State.CLOSED) {
            return;
        }
        settle.restart(this::settled);
        glance = false;                      // the settle timer decides when full resolution starts
        if (preview && passes == 0 && job != null) {
            cameraPending = true;            // applied when this preview has shown its first pass
        } else {
            startJob(Mode.PREVIEW);
        }
    }

    private synchronized void settled(long token) {
        if (state != State.CLOSED && settle.ended(token)) {
            startJob(Mode.FULL);
        }
    }

    /**
     * PREVIEW: reduced resolution while the camera moves. FULL: full resolution. GLANCE: one
     * reduced-resolution pass first (a few milliseconds, so a change shows at once), then FULL.
     */
    private enum Mode { PREVIEW, GLANCE, FULL }

    private void startJob(Mode mode) {
        boolean previewJob = mode != Mode.FULL;
        generation++;
        if (job != null) {
            job.cancel();
        }
        fullAfterDisplay = false;
        if (mode != Mode.PREVIEW) {
            settle.stop();
        }
        preview = previewJob;
        glance = mode == Mode.GLANCE;
        samplesPerPixel = 0;
        converged = 0;
        ended = false;
        passes = 0;
        cameraPending = false;
        clock.restart();
        if (state == State.DONE) {
            state = State.RUNNING;
        }
        long g = generation;
        job = starter.start(scene.withCamera(view.camera()), RenderJobs.settings(settings, previewJob),
                RenderJobs.listener(g, this::onPass, this::onConvergence));
    }

    /** Unless closed: a glance at the change, then full resolution from the first sample. */
    private void renderAgain() {
        if (state != State.CLOSED) {
            startJob(Mode.GLANCE);
        }
    }

    /** Called by job {@code g}'s coordinator thread after each pass; pauses the job while the viewer holds. */
    private void onPass(long g, int spp, Image image) {
        Frame frame;
        synchronized (this) {
            if (g != generation) {
                return;                      // a replaced job finishing its last pass
            }
            samplesPerPixel = spp;
            passes++;
            frame = new Frame(image, spp, preview, g, job::snapshotBuffers);
        }
        sink.accept(frame);                  // outside the lock: the sink may take its time
        synchronized (this) {
            if (g != generation) {
                return;
            }
            if (preview && cameraPending) {
                startJob(Mode.PREVIEW);
                return;
            }
            if (glance) {
                if (waitingForDisplay) {
                    fullAfterDisplay = true;         // displayReady() starts it
                    job.pause();
                } else {
                    startJob(Mode.FULL);
                }
                return;
            }
            if (!preview && state == State.RUNNING && reachedStop()) {
                state = State.DONE;
            }
            if (holds()) {
                hold();
            }
        }
    }

    /** Job {@code g}'s share of converged pixels; {@code end}: it ended by itself, every pixel met the noise threshold. */
    private synchronized void onConvergence(long g, RenderStats stats, boolean end) {
        if (g != generation) {
            return;
        }
        converged = stats.convergedFraction();
        if (end && !preview && !glance && state != State.CLOSED) {
            ended = true;
            state = state == State.PAUSED ? state : State.DONE;
            clock.stop();
        }
    }

    /** Pauses the job and the clock. */
    private void hold() {
        if (job != null) {
            job.pause();
        }
        clock.stop();
    }

    /** Resumes the job and the clock. */
    private void goOn() {
        if (job != null) {
            job.resume();
        }
        clock.start();
    }

    private boolean holds() {
        return state == State.PAUSED || state == State.DONE;
    }

    private boolean reachedStop() {
        return !preview && stopAt != UNLIMITED && samplesPerPixel >= stopAt;
    }
}
