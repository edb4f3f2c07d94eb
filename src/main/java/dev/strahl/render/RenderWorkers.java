package dev.strahl.render;

import dev.strahl.camera.CameraRays;
import dev.strahl.film.Film;
import dev.strahl.integrator.FeatureTracer;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.Parallel;
import dev.strahl.integrator.PathWavefront;
import dev.strahl.scene.Scene;
import dev.strahl.world.World;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * The threads of one render job and what each owns: a fixed pool whose workers take
 * {@value Film#TILE}-pixel tiles from an atomic counter (or, with the teaching option of stripes,
 * each renders one horizontal stripe) and add a pass's samples of each pixel in
 * index order, with the random numbers of (seed, pixel, sample index) alone; and the same
 * threads for an integrator's per-sample preparation ({@link Parallel}).
 *
 * <p>A gate between tiles (and between preparation chunks) lets the job hold the workers still:
 * {@link #hold()} (a pause, or a checkpoint taken while a pass runs) makes each worker wait there
 * before its next tile, and {@link #awaitStill()} returns once none is rendering, so that the film
 * can be read consistently: every pixel then holds whole samples.
 */
final class RenderWorkers implements Parallel, PassRunner {
    private final Film film;
    private final long seed;
    private final CameraRays cameraRays;
    private final ExecutorService pool;
    private final SampleLoop.WorkerState[] workers;
    private final Tally tally = new Tally();
    /** Summed over threads and passes: how long a thread that had finished its part of a pass waited for the last one. */
    private final AtomicLong idleNanos = new AtomicLong();
    /** Teaching option: one stripe per thread instead of tiles. */
    private final boolean stripes;
    private volatile boolean cancelled;
    /** Guards {@link #holds} and {@link #busy}; workers wait on it while a hold is on. */
    private final Object gate = new Object();
    private int holds;
    /** Workers running a task and not waiting at the gate. */
    private int busy;

    /**
     * The workers of a local render of {@code scene}: its camera's rays at the settings' size, the
     * settings' seed, threads and schedule, and the feature tracer when the settings keep feature buffers.
     */
    static RenderWorkers of(Scene scene, RenderSettings settings, Film film, Integrator integrator, String name) {
        World world = World.of(scene);
        boolean cull = settings.transport().cullBackFaces();
        return new RenderWorkers(film, CameraRays.of(scene.camera(), settings.output().width(), settings.output().height()), integrator,
                settings.output().keepsFeatures() ? () -> new FeatureTracer(world, cull) : null, settings.sampling().seed(),
                settings.execution().effectiveThreads(), settings.execution().stripes(), name, WavefrontLoop.batch());
    }

    /**
     * Workers of one job; they also trace the feature buffers of every camera sample when
     * {@code features} (else null) makes a tracer per thread (the film must then keep features).
     * With {@code wavefrontBatch} above 0 an integrator that has a wavefront renders batches of that
     * many paths ({@link WavefrontLoop}; the same bits).
     */
    RenderWorkers(Film film, CameraRays cameraRays, Integrator integrator, Supplier<FeatureTracer> features, long seed, int threads,
                  boolean stripes, String name, int wavefrontBatch) {
        if (features != null && !film.hasFeatures()) {
            throw new IllegalArgumentException("feature buffers need a film that keeps them");
        }
        this.seed = seed;
        this.film = film;
        this.cameraRays = cameraRays;
        this.stripes = stripes;
        boolean stratified = SampleLoop.stratifiedSampler();
        AtomicInteger workerNumber = new AtomicInteger();
        this.pool = Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, name + "-" + workerNumber.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        this.workers = new SampleLoop.WorkerState[threads];
        for (int i = 0; i < threads; i++) {
            PathWavefront wavefront = WavefrontLoop.of(integrator, wavefrontBatch, stratified, seed);
            workers[i] = new SampleLoop.WorkerState(i, wavefront != null ? wavefront.worker() : integrator.newWorker(),
                    SampleLoop.newSampler(stratified, seed), features != null ? features.get() : null, wavefront);
        }
    }

    @Override
    public Parallel parallel() {
        return this;
    }

    @Override
    public int threads() {
        return workers.length;
    }

    /** Asks the threads to stop after their current row or chunk. */
    @Override
    public void cancel() {
        synchronized (gate) {
            cancelled = true;
            gate.notifyAll();
        }
    }

    /** Makes every worker stop before its next tile until {@link #release()}; does not wait. */
    @Override
    public void hold() {
        synchronized (gate) {
            holds++;
        }
    }

    @Override
    public void release() {
        synchronized (gate) {
            holds--;
            gate.notifyAll();
        }
    }

    /** While a hold is on: waits until no worker is rendering (each has finished its tile). */
    @Override
    public void awaitStill() throws InterruptedException {
        synchronized (gate) {
            while (busy > 0 && !cancelled) {
                gate.wait();
            }
        }
    }

    /** Called by a worker between tiles: waits while a hold is on. */
    private void passGate() {
        synchronized (gate) {
            if (holds == 0) {
                return;
            }
            busy--;
            gate.notifyAll();
            try {
                while (holds > 0 && !cancelled) {
                    gate.wait();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                cancelled = true;
            } finally {
                busy++;
            }
        }
    }

    @Override
    public boolean cancelled() {
        return cancelled;
    }

    @Override
    public Tally tally() {
        return tally;
    }

    @Override
    public double idleSeconds() {
        return idleNanos.get() * 1e-9;
    }

    @Override
    public long rayCount() {
        long rays = 0;
        for (SampleLoop.WorkerState w : workers) {
            rays += w.integrator.rayCount() + (w.features != null ? w.features.rayCount() : 0);
        }
        return rays;
    }

    @Override
    public void shutdown() {
        pool.shutdownNow();
    }

    /** Renders samples [firstSample, endSample) of every pixel (or those {@code only} renders); returns when all threads are done with it. */
    @Override
    public void renderPass(int firstSample, int endSample, NoiseTarget only) throws InterruptedException, ExecutionException {
        AtomicInteger nextTile = new AtomicInteger();
        try {
            onEveryThread(w -> {
                if (stripes) {
                    renderStripe(w, firstSample, endSample, only);
                } else {
                    renderTiles(w, nextTile, firstSample, endSample, only);
                }
                w.finished = System.nanoTime();
            });
        } finally {
            // Idle time: each thread from its own end of the pass to the last thread's end.
            long last = 0;
            for (SampleLoop.WorkerState w : workers) {
                last = Math.max(last, w.finished);
            }
            long idle = 0;
            for (SampleLoop.WorkerState w : workers) {
                idle += last - w.finished;
            }
            idleNanos.addAndGet(idle);
        }
    }

    /**
     * Runs {@code body} once on every thread, each with its own worker, and waits for all. When
     * one fails, the others are told to stop (they look at {@code cancelled} between tiles and
     * chunks) and waited for too, so that no thread still writes into the film once the job has
     * ended; then the first failure is thrown.
     */
    private void onEveryThread(Consumer<SampleLoop.WorkerState> body) throws InterruptedException, ExecutionException {
        List<Future<?>> tasks = new ArrayList<>(workers.length);
        for (SampleLoop.WorkerState w : workers) {
            tasks.add(pool.submit(() -> {
                synchronized (gate) {
                    busy++;
                }
                try {
                    passGate();
                    body.accept(w);
                } finally {
                    synchronized (gate) {
                        busy--;
                        gate.notifyAll();
                    }
                }
            }));
        }
        ExecutionException first = null;
        for (Future<?> task : tasks) {
            try {
                task.get();
            } catch (ExecutionException e) {
                if (first == null) {
                    first = e;
                    cancelled = true;
                }
            }
        }
        if (first != null) {
            throw first;
        }
    }

    /** {@link Parallel} on the job's workers: chunks are taken from an atomic counter, each run with its thread's worker. */
    @Override
    public void forEach(int count, Parallel.Task task) {
        AtomicInteger next = new AtomicInteger();
        try {
            onEveryThread(w -> {
                for (int i = next.getAndIncrement(); i < count && !cancelled; i = next.getAndIncrement()) {
                    task.run(i, w.integrator);
                    passGate();
                }
            });
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            cancelled = true;
            throw new IllegalStateException("interrupted while preparing a pass", e);
        } catch (ExecutionException e) {
            if (e.getCause() instanceof RuntimeException r) {
                throw r;
            }
            if (e.getCause() instanceof Error err) {
                throw err;
            }
            throw new IllegalStateException(e.getCause());
        }
    }

    private void renderTiles(SampleLoop.WorkerState w, AtomicInteger nextTile, int firstSample, int endSample, NoiseTarget only) {
        int tilesX = film.tileCountX();
        int tileCount = tilesX * film.tileCountY();
        for (int tile = nextTile.getAndIncrement(); tile < tileCount && !cancelled; tile = nextTile.getAndIncrement()) {
            if (only != null && !only.rendersTile(tile)) {
                continue;                                  // every pixel of it has converged
            }
            int x0 = (tile % tilesX) * Film.TILE;
            int y0 = (tile / tilesX) * Film.TILE;
            renderRect(w, x0, y0, Math.min(x0 + Film.TILE, film.width()), Math.min(y0 + Film.TILE, film.height()), firstSample, endSample, only);
            passGate();
        }
    }

    /**
     * Teaching option with stripes (a teaching option: thread i of n renders rows [i·h/n, (i+1)·h/n)
     * and nothing else (it may hold still between rows, as between tiles).
     */
    private void renderStripe(SampleLoop.WorkerState w, int firstSample, int endSample, NoiseTarget only) {
        int n = workers.length, h = film.height();
        int y0 = (int) ((long) w.index * h / n), y1 = (int) ((long) (w.index + 1) * h / n);
        for (int y = y0; y < y1 && !cancelled; y++) {
            renderRect(w, 0, y, film.width(), y + 1, firstSample, endSample, only);
            passGate();
        }
    }

    /**
     * Samples [firstSample, endSample) of every pixel of the rectangle [x0, x1) × [y0, y1) (that {@code only} renders, if not null):
     * through the wavefront where this worker has one and every pixel renders (adaptive sampling's passes render one sample at a time).
     */
    private void renderRect(SampleLoop.WorkerState w, int x0, int y0, int x1, int y1, int firstSample, int endSample, NoiseTarget only) {
        if (w.wavefront != null && only == null) {
            long[] invalid = {0};
            tally.samples.addAndGet(WavefrontLoop.renderRect(w, cameraRays, seed, film, x0, y0, x1, y1, 0, 0, firstSample, endSample, invalid));
            if (invalid[0] > 0) {
                tally.invalid.addAndGet(invalid[0]);
            }
            return;
        }
        long invalid = 0;
        for (int y = y0; y < y1 && !cancelled; y++) {
            long rowSamples = 0;
            for (int x = x0; x < x1; x++) {
                int pixel = film.pixelIndex(x, y);
                if (only != null && !only.renders(pixel)) {
                    continue;
                }
                // a restored film may hold more samples in some pixels: they go on from there
                int s0 = Math.max(firstSample, film.sampleCountAt(pixel));
                rowSamples += Math.max(0, endSample - s0);
                invalid += SampleLoop.samplePixel(w, cameraRays, seed, film, pixel, x, y, s0, endSample);
            }
            tally.samples.addAndGet(rowSamples);
        }
        if (invalid > 0) {
            tally.invalid.addAndGet(invalid);
        }
    }
}
