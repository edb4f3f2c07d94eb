package dev.strahl.render;

import dev.strahl.film.Film;
import dev.strahl.film.Image;
import dev.strahl.integrator.Integrator;
import dev.strahl.scene.Scene;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A render running in the background: passes over the whole image, each adding a few samples
 * per pixel, on a fixed pool of worker threads that take {@value Film#TILE}-pixel tiles from an
 * atomic counter. An integrator that {@linkplain Integrator#preparesEachSample prepares each
 * sample index} (the photon mapper) gets passes of one sample per pixel, each preceded by its
 * {@link Integrator#prepareSample} on the same threads. The random numbers of a sample depend only on (seed, pixel, sample index), and
 * each pixel adds its samples in index order, so the image is bit-identical for any thread count.
 *
 * <pre>{@code
 * try (RenderJob job = RenderJob.start(scene, RenderSettings.defaults().withSamplesPerPixel(64))) {
 *     Film film = job.awaitCompletion();
 *     ImageWriters.write(film, Path.of("out.png"));
 * }
 * }</pre>
 */
public final class RenderJob implements AutoCloseable {
    private static final int MAX_AUTO_PASS = 16;
    private static final AtomicInteger JOB_NUMBER = new AtomicInteger();

    private final RenderSettings settings;
    private final RenderListener listener;
    private final Film film;
    private final Integrator integrator;
    private final int threads;
    private final RenderWorkers workers;
    private final CompletableFuture<RenderStats> result = new CompletableFuture<>();
    private volatile int completedSpp;
    private volatile long restoredSamples;           // held by a resumed film before this job began
    /** The mean image at the end of the last completed pass: what {@link #snapshot()} returns. */
    private volatile Image lastPass;
    private final long startNanos;

    private RenderJob(Scene scene, RenderSettings settings, Integrator integrator, RenderListener listener, Film film) {
        this.settings = settings;
        this.listener = listener;
        this.film = film != null ? film : new Film(settings.width(), settings.height());
        this.integrator = integrator;
        this.threads = settings.effectiveThreads();
        this.workers = new RenderWorkers(this.film, scene.camera().rays(settings.width(), settings.height()), integrator,
                settings.seed(), threads, "strahl-render-" + JOB_NUMBER.incrementAndGet());
        this.startNanos = System.nanoTime();
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
        Objects.requireNonNull(settings, "settings");
        return start(scene, settings, integratorFor(scene, settings), listener);
    }

    /**
     * Starts rendering with a given integrator (made for this scene); the settings' integrator
     * choice is then ignored.
     * (internal: {@link Integrator} is not part of the stable API).
     *
     * @param scene      the scene, shared read-only
     * @param settings   how to render
     * @param integrator the integrator, made for this scene
     * @param listener   hears about every pass and the end
     * @return the running job
     */
    public static RenderJob start(Scene scene, RenderSettings settings, Integrator integrator, RenderListener listener) {
        Objects.requireNonNull(scene, "scene");
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(integrator, "integrator");
        Objects.requireNonNull(listener, "listener");
        return launch(new RenderJob(scene, settings, integrator, listener, null));
    }

    /**
     * Continues a render into {@code film}, which holds the state of an earlier one with the same
     * scene and settings (restored from a checkpoint, see {@link Film#restorePixel}). Each pixel
     * goes on from the sample index it has reached, and the samples of a pixel are added in index
     * order as always, so the result is bit-identical to a render that was never interrupted.
     * The listener may read {@code film} in {@link RenderListener#passCompleted}: no worker writes
     * to it until that returns. A new, empty film starts a render from the beginning.
     *
     * @param scene    the scene, shared read-only; the same as the earlier render's
     * @param settings how to render; the same as the earlier render's, except perhaps a higher
     *                 sample count, another thread count, pass size or time limit
     * @param film     the film to go on filling, of the settings' size
     * @param listener hears about every pass and the end
     * @return the running job
     * @throws IllegalArgumentException if the film's size is not the settings'
     */
    public static RenderJob resume(Scene scene, RenderSettings settings, Film film, RenderListener listener) {
        Objects.requireNonNull(scene, "scene");
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(film, "film");
        Objects.requireNonNull(listener, "listener");
        if (film.width() != settings.width() || film.height() != settings.height()) {
            throw new IllegalArgumentException("film " + film.width() + "x" + film.height() + " does not match the settings' "
                    + settings.width() + "x" + settings.height());
        }
        return launch(new RenderJob(scene, settings, integratorFor(scene, settings), listener, film));
    }

    /** The integrator the settings choose, with all its parameters. */
    private static Integrator integratorFor(Scene scene, RenderSettings settings) {
        return settings.integrator().create(scene, settings.maxDepth(), settings.hemisphere(), settings.cullBackFaces(),
                settings.lightSamples(), settings.photonParameters());
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
     * The film being filled. Read it when the job is done; while it renders, use {@link #snapshot()}.
     *
     * @return the film
     */
    public Film film() {
        return film;
    }

    /**
     * A consistent image of the render so far: the mean of all samples of the passes completed
     * up to now, every pixel with the same sample count (black before the first pass ends).
     * Safe to call from any thread at any time; the render goes on meanwhile. Use
     * {@link Image#rgb()} for linear float RGB and {@link Image#toBufferedImage()} for display.
     *
     * @return the image, immutable
     */
    public Image snapshot() {
        Image image = lastPass;
        return image != null ? image : new Image(settings.width(), settings.height(), new float[3 * settings.width() * settings.height()]);
    }

    /**
     * Samples per pixel of all completed passes.
     *
     * @return the count
     */
    public int completedSamplesPerPixel() {
        return completedSpp;
    }

    /**
     * Fraction of the requested samples taken.
     *
     * @return a number in [0, 1]
     */
    public double progress() {
        double total = (double) settings.samplesPerPixel() * settings.width() * settings.height();
        return Math.min(1, (restoredSamples + workers.samplesDone()) / total);
    }

    /**
     * Camera samples taken so far by this job (not counting those of a resumed film).
     *
     * @return the count
     */
    public long samplesDone() {
        return workers.samplesDone();
    }

    /**
     * Samples of this job whose radiance was NaN or infinite (added to the film as black).
     *
     * @return the count so far
     */
    public long invalidSamples() {
        return workers.invalidSamples();
    }

    /**
     * Time since the job started.
     *
     * @return seconds
     */
    public double elapsedSeconds() {
        return (System.nanoTime() - startNanos) * 1e-9;
    }

    /** Asks the workers to stop soon; {@link #awaitCompletion()} then returns the film as it is. */
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
     * Waits for the render to end and returns its film.
     *
     * @return the film
     * @throws InterruptedException if the waiting thread is interrupted
     */
    public Film awaitCompletion() throws InterruptedException {
        awaitStats();
        return film;
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

    private void run() {
        try {
            int spp = settings.samplesPerPixel();
            boolean prepares = integrator.preparesEachSample();
            int start = film.minSampleCount();             // 0, unless the film was restored
            completedSpp = Math.min(start, spp);
            restoredSamples = samplesIn(film);
            if (restoredSamples > 0) {
                lastPass = film.toImage();                 // what the restored film holds, until a pass ends
            }
            int pass = 0;
            while (start < spp && !workers.cancelled()) {
                int size = prepares ? 1 : settings.samplesPerPass() > 0 ? settings.samplesPerPass() : autoPassSize(pass);
                int end = Math.min(spp, start + size);
                if (prepares) {
                    integrator.prepareSample(settings.seed(), start, workers);
                    if (workers.cancelled()) {
                        break;
                    }
                }
                workers.renderPass(start, end);
                if (workers.cancelled()) {
                    break;
                }
                completedSpp = end;
                Image image = film.toImage();
                lastPass = image;
                double seconds = elapsedSeconds();
                listener.passFinished(new RenderListener.Pass(pass + 1, end, workers.samplesDone(), seconds), image);
                start = end;
                pass++;
                if (!settings.timeLimit().isZero() && elapsedSeconds() >= settings.timeLimit().toNanos() * 1e-9) {
                    break;                             // the pass that crossed the time limit is kept
                }
            }
            RenderStats stats = stats();
            listener.finished(stats);
            result.complete(stats);
        } catch (ExecutionException e) {
            result.completeExceptionally(e.getCause());    // what failed on a render thread, not its wrapper
        } catch (Throwable t) {
            result.completeExceptionally(t);
        } finally {
            workers.shutdown();
        }
    }

    static long samplesIn(Film film) {
        long n = 0;
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                n += film.sampleCount(x, y);
            }
        }
        return n;
    }

    /** Passes of 1, 1, 2, 4, 8 and then 16 samples per pixel: a first image at once, little overhead later. */
    static int autoPassSize(int pass) {
        return pass == 0 ? 1 : Math.min(MAX_AUTO_PASS, 1 << Math.min(pass - 1, 4));
    }

    private RenderStats stats() {
        return new RenderStats(elapsedSeconds(), workers.samplesDone(), workers.rayCount(), completedSpp, threads, workers.cancelled(),
                workers.invalidSamples());
    }
}
