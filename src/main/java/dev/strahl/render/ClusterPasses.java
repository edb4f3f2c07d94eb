package dev.strahl.render;

import dev.strahl.film.Film;
import dev.strahl.integrator.Parallel;
import dev.strahl.units.JobChannel;
import dev.strahl.units.WorkUnit;
import java.util.List;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The passes of a cluster render: each pass sends every tile as a work unit (its sample range and
 * the tile's state) through the job's {@link JobChannel}, and merges the rendered units into the
 * film by replacing the tile's state with theirs. The tiles of a pass are disjoint and a tile's
 * next unit is made only after its last one came back, so a pixel's sums grow exactly as in a
 * local render, whoever renders which unit: the image is the same bits.
 *
 * <p>At most a few units per member thread are out at once (so that a member that joins late
 * gets work and the state of the film stays small in flight). A hold (a pause, a checkpoint)
 * stops sending; {@link #awaitStill()} waits for the units out to come back. A cancel drops what
 * comes back afterwards: the film then holds whole samples of the units merged so far.
 */
final class ClusterPasses implements PassRunner {
    /** Units out per thread of the cluster: one rendering, one on the way. */
    private static final int UNITS_PER_THREAD = 2;
    /** The largest pass of a cluster render (see docs/cluster.md for the measurement behind it). */
    static final int MAX_PASS = 64;

    private final Film film;
    private final JobChannel channel;
    private final Object lock = new Object();
    private int holds;
    private int out;
    private boolean cancelled;
    private Throwable failure;
    private final Tally tally = new Tally();
    private final AtomicLong rays = new AtomicLong();

    ClusterPasses(Film film, JobChannel channel) {
        this.film = film;
        this.channel = channel;
    }

    @Override
    public List<RenderStats.Member> members() {
        return channel.figures(RenderStats.Member::new);
    }

    @Override
    public void renderPass(int firstSample, int endSample, NoiseTarget only) throws InterruptedException, ExecutionException {
        int tilesX = film.tileCountX();
        int tileCount = tilesX * film.tileCountY();
        for (int tile = 0; tile < tileCount; tile++) {
            if (only != null && !only.rendersTile(tile)) {
                continue;                                  // converged: not handed out again
            }
            WorkUnit unit;
            synchronized (lock) {
                while ((holds > 0 || out >= window()) && !cancelled && failure == null) {
                    lock.wait();
                }
                if (cancelled || failure != null) {
                    break;
                }
                unit = cut(tile, tilesX, firstSample, endSample, only);
                if (unit == null) {
                    continue;
                }
                out++;
            }
            long samples = unit.samples();
            channel.submit(unit).whenComplete((done, e) -> merge(done, e, samples));
        }
        synchronized (lock) {
            while (out > 0 && !cancelled && failure == null) {
                lock.wait();
            }
            if (failure != null && !cancelled) {
                throw new ExecutionException(failure);
            }
        }
    }

    private int window() {
        return Math.max(4, UNITS_PER_THREAD * channel.threads());
    }

    /**
     * The unit of one tile for samples [first, end) of its pixels (those {@code only} renders, if not
     * null), with the tile's state; null if every such pixel has them already.
     */
    private WorkUnit cut(int tile, int tilesX, int first, int end, NoiseTarget only) {
        int x0 = (tile % tilesX) * Film.TILE;
        int y0 = (tile / tilesX) * Film.TILE;
        int w = Math.min(Film.TILE, film.width() - x0);
        int h = Math.min(Film.TILE, film.height() - y0);
        int perPixel = film.stateSums();          // the film's whole per-pixel state: colour, variance, features
        int[] counts = new int[w * h];
        double[] sums = new double[perPixel * w * h];
        double[] state = new double[perPixel];
        boolean[] renders = only != null ? new boolean[w * h] : null;
        boolean any = false;
        for (int ty = 0; ty < h; ty++) {
            for (int tx = 0; tx < w; tx++) {
                int i = ty * w + tx;
                counts[i] = film.pixelState(x0 + tx, y0 + ty, state);
                System.arraycopy(state, 0, sums, perPixel * i, perPixel);
                boolean takes = only == null || only.renders(film.pixelIndex(x0 + tx, y0 + ty));
                if (renders != null) {
                    renders[i] = takes;
                }
                any |= takes && counts[i] < end;
            }
        }
        return any ? new WorkUnit(x0, y0, w, h, first, end, counts, sums, renders) : null;
    }

    private void merge(WorkUnit done, Throwable e, long samples) {
        synchronized (lock) {
            out--;
            lock.notifyAll();
            if (cancelled) {
                return;                            // the film stays as it was when the render was cancelled
            }
            if (e != null) {
                if (failure == null) {
                    failure = e instanceof CompletionException && e.getCause() != null ? e.getCause() : e;
                }
                return;
            }
            double[] sums = done.sums();
            int[] counts = done.counts();
            int perPixel = done.sumsPerPixel();
            double[] state = new double[perPixel];
            for (int ty = 0; ty < done.height(); ty++) {
                for (int tx = 0; tx < done.width(); tx++) {
                    int i = ty * done.width() + tx;
                    System.arraycopy(sums, perPixel * i, state, 0, perPixel);
                    film.restorePixel(done.x0() + tx, done.y0() + ty, counts[i], state);
                }
            }
            tally.samples.addAndGet(samples);
            tally.invalid.addAndGet(done.invalidSamples());
            rays.addAndGet(done.rays());
        }
    }

    @Override
    public Parallel parallel() {
        return null;
    }

    @Override
    public void cancel() {
        synchronized (lock) {
            cancelled = true;
            lock.notifyAll();
        }
    }

    @Override
    public boolean cancelled() {
        synchronized (lock) {
            return cancelled;
        }
    }

    @Override
    public void hold() {
        synchronized (lock) {
            holds++;
        }
    }

    @Override
    public void release() {
        synchronized (lock) {
            holds--;
            lock.notifyAll();
        }
    }

    @Override
    public void awaitStill() throws InterruptedException {
        synchronized (lock) {
            while (out > 0 && !cancelled && failure == null) {
                lock.wait();
            }
        }
    }

    @Override
    public Tally tally() {
        return tally;
    }

    @Override
    public long rayCount() {
        return rays.get();
    }

    @Override
    public int threads() {
        return channel.threads();
    }

    @Override
    public void shutdown() {
        channel.close();
    }

    /** Passes of 1, 4, 16, then {@value #MAX_PASS} samples per pixel: a first image soon, and units that outweigh their shipping. */
    @Override
    public int passSize(int pass) {
        return Math.min(MAX_PASS, 1 << (2 * Math.min(pass, 3)));
    }
}
