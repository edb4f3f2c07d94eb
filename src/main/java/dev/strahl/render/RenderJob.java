package dev.strahl.render;

import dev.strahl.film.Film;
import dev.strahl.image.Image;
import dev.strahl.integrator.Integrator;
import dev.strahl.scene.Scene;
import dev.strahl.world.World;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;

/**
 * A render running in the background: passes over the whole image, each adding a few samples
 * per pixel, on a fixed pool of worker threads. The random numbers of a sample depend only on
 * (seed, pixel, sample index), and each pixel adds its samples in index order, so the image is
 * bit-identical for any thread count, and for a render paused, checkpointed and resumed.
 *
 * <pre>{@code
 * try (RenderJob job = RenderJob.start(scene, RenderSettings.defaults().withSamplesPerPixel(64))) {
 *     Image image = job.awaitCompletion();
 *     ImageWriters.write(image, Path.of("out.png"));
 * }
 * }</pre>
 *
 * <p>While it runs, {@link #snapshot()} gives the image of the passes completed so far,
 * {@link #pause()} and {@link #resume()} hold the workers and let them go on,
 * {@link #saveCheckpoint(Path)} saves the state for {@link #resumeFrom} in another process, and
 * {@link #cancel()} stops it.
 */
public final class RenderJob implements AutoCloseable {
    private static final AtomicInteger JOB_NUMBER = new AtomicInteger();

    private final RenderSettings settings;
    private final Film film;
    private final PassRunner workers;
    /** With a noise threshold, which pixels still render (saved in checkpoints); else null. */
    private final NoiseTarget target;
    private final PassLoop loop;
    private final Scene scene;
    /** What ties a checkpoint to this scene and these settings; digested when first needed. */
    private Checkpoint identity;
    /** Figures of the renders a resumed job continues: NaN samples and seconds. */
    private final long earlierInvalid;
    private final double earlierSeconds;
    private final int earlierSpp;
    private final CompletableFuture<RenderStats> result = new CompletableFuture<>();
    /** The last completed pass: its image ({@link #snapshot()}) and, when asked for, its buffers. */
    private final PassBuffers passes;
    private final PauseClock clock = new PauseClock();

    /** With {@code cluster} non-null, the passes are rendered by the runner it makes for the job's film (a cluster render). */
    private RenderJob(Scene scene, RenderSettings settings, Integrator integrator, RenderListener listener, Checkpoint identity,
                      Checkpoint.Restored restored, Function<Film, PassRunner> cluster) {
        this.settings = Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(listener, "listener");
        Objects.requireNonNull(integrator, "integrator");
        this.film = restored != null ? restored.film()
                : new Film(settings.output().width(), settings.output().height(), settings.output().keepsFeatures());
        this.scene = Objects.requireNonNull(scene, "scene");
        this.identity = identity;
        this.earlierInvalid = restored != null ? restored.invalidSamples() : 0;
        this.earlierSeconds = restored != null ? restored.seconds() : 0;
        int number = JOB_NUMBER.incrementAndGet();
        this.workers = cluster != null ? cluster.apply(film) : RenderWorkers.of(scene, settings, film, integrator, "strahl-render-" + number);
        NoiseTarget.State noise = restored != null ? restored.noise() : null;
        this.target = settings.sampling().noiseThreshold() == 0 ? null : noise != null
                ? new NoiseTarget(film, settings.sampling().noiseThreshold(), noise.boundary(), noise.mask())
                : new NoiseTarget(film, settings.sampling().noiseThreshold());
        this.passes = new PassBuffers(film, settings.output().aovs());
        this.loop = new PassLoop(settings, integrator, workers, film, passes, listener, target, earlierInvalid);
        this.earlierSpp = loop.completedSamplesPerPixel();
    }

    /**
     * Starts rendering {@code scene} in the background.
     *
     * @param scene    the scene, shared read-only
     * @param settings how to render
     * @return the running job; close it (or wait for it) when done
     */
    public static RenderJob start(Scene scene, RenderSettings settings) {
        return start(scene, settings, new RenderListener() {});
    }

    /**
     * Starts rendering {@code scene} in the background, reporting to {@code listener}.
     *
     * @param scene    the scene, shared read-only
     * @param settings how to render
     * @param listener hears about every pass and the end, on a render thread
     * @return the running job; close it (or wait for it) when done
     */
    public static RenderJob start(Scene scene, RenderSettings settings, RenderListener listener) {
        return start(scene, settings, Integrators.create(World.of(scene), Objects.requireNonNull(settings, "settings")), listener);
    }

    /** Starts rendering with a given integrator made for this scene; the settings' choice is ignored (tests). */
    static RenderJob start(Scene scene, RenderSettings settings, Integrator integrator, RenderListener listener) {
        return launch(new RenderJob(scene, settings, integrator, listener, null, null, null));
    }

    /**
     * Continues the render saved in a checkpoint by {@link #saveCheckpoint}. Each pixel goes on
     * from the sample index it had reached, and the samples of a pixel are added in index order
     * as always, so the result is bit-identical to a render that was never interrupted.
     *
     * @param checkpoint the checkpoint file
     * @param scene      the scene of the saved render (the same geometry, materials, camera, environment)
     * @param settings   the settings of the saved render; the sample count may be higher, and
     *                   threads, pass size and time limit may differ
     * @param listener   hears about every pass and the end
     * @return the running job
     * @throws CheckpointException if the file is no checkpoint, truncated or corrupt, or was made
     *                             for another scene or other settings (the message says which)
     * @throws IOException         if it cannot be read
     */
    public static RenderJob resumeFrom(Path checkpoint, Scene scene, RenderSettings settings, RenderListener listener)
            throws CheckpointException, IOException {
        return launch(scene, settings, listener, Objects.requireNonNull(checkpoint, "checkpoint"), null);
    }

    /**
     * A fresh render, or with {@code checkpoint} non-null the one saved there, whose passes are
     * rendered here or, with {@code runner} non-null, by the members of a cluster ({@link RenderCluster}).
     */
    static RenderJob launch(Scene scene, RenderSettings settings, RenderListener listener, Path checkpoint,
                            Function<Film, PassRunner> runner) throws CheckpointException, IOException {
        Checkpoint identity = Checkpoint.of(scene, settings);
        Checkpoint.Restored restored = checkpoint != null ? identity.restore(checkpoint) : null;
        return launch(new RenderJob(scene, settings, Integrators.create(World.of(scene), settings), listener, identity, restored, runner));
    }

    private static RenderJob launch(RenderJob job) {
        Thread coordinator = new Thread(job::run, "strahl-render-" + JOB_NUMBER.get());
        coordinator.setDaemon(true);
        coordinator.start();
        return job;
    }

    /**
     * The settings the job was started with.
     *
     * @return the settings
     */
    public RenderSettings settings() {
        return settings;
    }

    /**
     * A consistent image of the render so far: the mean of all samples of the passes completed
     * up to now, every pixel with the same sample count (black before the first pass ends).
     * Safe to call from any thread at any time; the render goes on meanwhile.
     *
     * @return the image, immutable
     */
    public Image snapshot() {
        return passes.image();
    }

    /**
     * The last completed pass's image ({@link #snapshot()}), variance and feature buffers, for a
     * {@link Denoiser} while the render goes on: copied from the film when asked for, only while it
     * holds exactly that pass (in a listener, in a pause begun in one, after the render).
     *
     * @return the buffers, or empty while a pass is being rendered (or paused in the middle of one)
     */
    public Optional<RenderBuffers> snapshotBuffers() {
        RenderBuffers now = passes.snapshot();
        return now != null || !isDone() ? Optional.ofNullable(now) : Optional.of(passes.of(film.toImage()));
    }

    /**
     * Samples per pixel of all completed passes (of a resumed render: counting those before).
     *
     * @return the count
     */
    public int completedSamplesPerPixel() {
        return loop.completedSamplesPerPixel();
    }

    /**
     * Fraction of the samples the render will take that it has taken: of the requested samples of
     * every pixel or, with a noise threshold, of what the pixels that have not converged were
     * estimated to need at the last decision (from their error and its fall as 1/√n).
     *
     * @return a number in [0, 1]
     */
    public double progress() {
        return loop.progress();
    }

    /**
     * Camera samples taken so far by this job (not counting those of a resumed render).
     *
     * @return the count
     */
    public long samplesDone() {
        return workers.samplesDone();
    }

    /**
     * Samples whose radiance was NaN or infinite (added to the film as black), counting those of
     * the renders a resumed job continues.
     *
     * @return the count so far
     */
    public long invalidSamples() {
        return earlierInvalid + workers.invalidSamples();
    }

    /**
     * Time this job has rendered: since it started, without the time it was paused.
     *
     * @return seconds
     */
    public double elapsedSeconds() {
        return clock.seconds();
    }

    /**
     * Samples per pixel this job began with: those of the renders whose checkpoint it resumed.
     *
     * @return the count, 0 for a job that was started afresh
     */
    public int earlierSamplesPerPixel() {
        return earlierSpp;
    }

    /**
     * Time spent on this render before this job: by the renders whose checkpoint it resumed.
     *
     * @return seconds, 0 for a job that was started afresh
     */
    public double earlierSeconds() {
        return earlierSeconds;
    }

    /**
     * Holds the workers: each finishes the tile it is on and waits. Returns at once; calling it
     * while paused does nothing. The render goes on, bit for bit as if never paused, after
     * {@link #resume()}.
     */
    public synchronized void pause() {
        if (clock.pause()) {
            passes.pause(workers::hold);
        }
    }

    /** Lets paused workers go on; does nothing unless paused. */
    public synchronized void resume() {
        if (clock.resume()) {
            passes.resume(workers::release);
        }
    }

    /**
     * Whether the job is paused.
     *
     * @return true between {@link #pause()} and {@link #resume()}
     */
    public boolean isPaused() {
        return clock.isPaused();
    }

    /**
     * Saves the render's state, so that {@link #resumeFrom} can continue it, bit-identically, in
     * this or another process. May be called at any time, from any thread (also from a
     * listener): the workers are held while the file is written, each after the tile it is on,
     * and go on afterwards. The file is replaced atomically; a previous one survives a failure.
     *
     * @param file where to save
     * @throws IOException if the file cannot be written
     * @throws InterruptedException if the calling thread is interrupted while waiting for the workers
     */
    public void saveCheckpoint(Path file) throws IOException, InterruptedException {
        Objects.requireNonNull(file, "file");
        workers.hold();
        try {
            workers.awaitStill();
            identity().save(file, film, target != null ? target.state() : null, invalidSamples(), earlierSeconds + elapsedSeconds());
        } finally {
            workers.release();
        }
    }

    private synchronized Checkpoint identity() {
        if (identity == null) {
            identity = Checkpoint.of(scene, settings);
        }
        return identity;
    }

    /** Asks the workers to stop soon (also when paused); {@link #awaitCompletion()} then returns the image as it is. */
    public void cancel() {
        workers.cancel();
    }

    /**
     * Whether the render has ended (completed, cancelled or failed).
     *
     * @return true once it has ended
     */
    public boolean isDone() {
        return result.isDone();
    }

    /**
     * Waits for the render to end and returns its image: the mean of every sample taken, also
     * of a pass a cancel cut short.
     *
     * @return the image
     * @throws InterruptedException if the waiting thread is interrupted
     * @throws IllegalStateException if the render failed
     */
    public Image awaitCompletion() throws InterruptedException {
        awaitStats();
        return film.toImage();
    }

    /**
     * Waits for the render to end and returns its image with the per-pixel variance and the
     * feature buffers of the settings ({@link RenderSettings.Output#aovs()}): what a {@link Denoiser}
     * and the EXR output take.
     *
     * @return the buffers
     * @throws InterruptedException if the waiting thread is interrupted
     * @throws IllegalStateException if the render failed
     */
    public RenderBuffers awaitBuffers() throws InterruptedException {
        awaitStats();
        return passes.of(film.toImage());
    }

    /**
     * Waits up to the given time for the render to end.
     *
     * @param timeout how long to wait at most
     * @param unit    the unit of {@code timeout}
     * @return whether it has ended
     * @throws InterruptedException if the waiting thread is interrupted
     */
    public boolean await(long timeout, TimeUnit unit) throws InterruptedException {
        try {
            result.get(timeout, unit);
        } catch (TimeoutException e) {
            return false;
        } catch (ExecutionException e) {
            return true;                       // the failure is reported by awaitStats
        }
        return true;
    }

    /**
     * Waits for the render to end and returns its figures.
     *
     * @return the figures
     * @throws InterruptedException if the waiting thread is interrupted
     * @throws IllegalStateException if the render failed
     */
    public RenderStats awaitStats() throws InterruptedException {
        try {
            return result.get();
        } catch (ExecutionException e) {
            throw new IllegalStateException("render failed: " + e.getCause(), e.getCause());
        }
    }

    /** Cancels the render and waits for its threads to stop. */
    @Override
    public void close() {
        cancel();
        try {
            result.handle((s, e) -> null).get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException e) {
            // handled above: cannot happen
        }
    }

    /** The film being filled (for tests in this package). */
    Film film() {
        return film;
    }

    private void run() {
        loop.run(this::elapsedSeconds, result);
    }
}
