package dev.strahl.viewer;

import dev.strahl.image.Image;
import dev.strahl.render.Aov;
import dev.strahl.render.Denoiser;
import dev.strahl.render.RenderBuffers;
import java.util.EnumSet;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.LongSupplier;

/**
 * View → Denoise: denoises the frames of the running render while it goes on, on a thread of its
 * own, and hands the results to the display. It sits between the {@link RenderController} and
 * the {@link FramePresenter}: every frame goes on to the presenter as it is, and while Denoise is
 * on, full-resolution frames (never previews) are denoised too.
 *
 * <ul>
 *   <li><b>The buffers of a pass</b> (image, variance, albedo, normal, depth) are copied from the
 *       job's film at the end of that pass, in the controller's call (on the job's coordinator
 *       thread, while the workers wait for it): {@link dev.strahl.render.RenderJob#snapshotBuffers()}.
 *       Only when a denoise is about to start, so the render pays for one copy per denoise, not
 *       per pass.</li>
 *   <li><b>One denoise at a time</b>, on the denoiser's thread (the network's rows on the common
 *       fork-join pool), never on the event dispatch thread or a render thread. Frames that arrive
 *       meanwhile are not queued: the newest one waits, the older ones are dropped; a result whose
 *       job has been replaced (a restart, a camera move) is dropped.</li>
 *   <li><b>Sharing the processors</b>: after a denoise of t seconds the next starts no sooner
 *       than {@value #REST_FACTOR}·t later, so the denoiser takes at most
 *       1/({@value #REST_FACTOR} + 1) of the time and the render keeps most of the machine. The
 *       rule scales with the denoiser: Open Image Denoise's network (about 1 s for 512x512 on two
 *       cores) gives a denoised frame every few seconds, as the faster filter did at smaller
 *       sizes.</li>
 *   <li><b>A held render</b> (stop-at reached, paused by a change) still gets its last pass
 *       denoised: the job then holds its film at that pass, and a waiting frame takes its buffers
 *       after the rest. A render paused by the user in the middle of a pass has no consistent
 *       buffers until it goes on; the last denoised frame stays on screen.</li>
 * </ul>
 */
final class LiveDenoiser implements Consumer<RenderController.Frame>, AutoCloseable {
    /** The pause after a denoise, as a multiple of how long it took. */
    static final int REST_FACTOR = 3;
    /** The feature buffers the denoiser is guided by (as {@code render --denoise} keeps them). */
    static final Set<Aov> GUIDES = Set.copyOf(EnumSet.allOf(Aov.class));

    private final FramePresenter presenter;
    private final Function<RenderBuffers, Image> filter;
    private final RenderJobs.Scheduler thread;
    private final LongSupplier nanoTime;

    // guarded by this
    private boolean on;
    private RenderController.Frame latest;
    /** A denoise is scheduled or running. */
    private boolean busy;
    /** The newest full-resolution frame not denoised, waiting for the denoiser to be free. */
    private RenderController.Frame waiting;
    /** A retry of {@link #waiting} is scheduled. */
    private boolean retry;
    /** When the next denoise may start ({@link #nanoTime}). */
    private long restUntil = Long.MIN_VALUE;
    private int denoised;

    /**
     * @param filter   the denoiser: a pass's buffers in, its denoised image out
     * @param thread   runs the denoises and the retries, one at a time
     * @param nanoTime the clock of the rests
     */
    LiveDenoiser(FramePresenter presenter, Function<RenderBuffers, Image> filter, RenderJobs.Scheduler thread, LongSupplier nanoTime) {
        this.presenter = presenter;
        this.filter = filter;
        this.thread = thread;
        this.nanoTime = nanoTime;
    }

    /** strahl's default {@link Denoiser} (Open Image Denoise's network) on a daemon thread "strahl-viewer-denoise". */
    static LiveDenoiser of(FramePresenter presenter) {
        return new LiveDenoiser(presenter, Denoiser.create()::denoise, RenderJobs.timer("strahl-viewer-denoise"), System::nanoTime);
    }

    /** {@code aovs} with the denoiser's guides added. */
    static Set<Aov> withGuides(Set<Aov> aovs) {
        Set<Aov> all = EnumSet.copyOf(GUIDES);
        all.addAll(aovs);
        return all;
    }

    /** A frame from the controller (on the job's coordinator thread, at the end of its pass): shown, and denoised if on. */
    @Override
    public void accept(RenderController.Frame frame) {
        presenter.accept(frame);
        synchronized (this) {
            latest = frame;
            if (!on || frame.preview()) {
                waiting = null;
                return;
            }
            if (busy || restLeft() > 0) {
                waiting = frame;
                scheduleRetry();
                return;
            }
            waiting = null;
            busy = true;
        }
        // Still in the controller's call: the film holds this pass, the copy is of exactly this frame.
        start(frame, frame.buffers().get());
    }

    /**
     * View → Denoise. On: with {@code denoiseLast}, the last frame is denoised if its buffers can
     * still be had (a held render), else the next frame is; without (its job is being replaced),
     * the next frame is.
     */
    void setEnabled(boolean enabled, boolean denoiseLast) {
        synchronized (this) {
            on = enabled;
            waiting = enabled && denoiseLast && latest != null && !latest.preview() ? latest : null;
            if (waiting != null) {
                scheduleRetry();
            }
        }
        presenter.setDenoised(enabled);
    }

    synchronized boolean enabled() {
        return on;
    }

    /** Denoises done since the start (for tests and the trace). */
    synchronized int denoisedCount() {
        return denoised;
    }

    /** Schedules {@link #retryWaiting()} at the end of the rest, unless one is scheduled or a denoise will end and do it. */
    private void scheduleRetry() {
        if (!retry && !busy) {
            retry = true;
            thread.schedule(this::retryWaiting, (restLeft() + 999_999) / 1_000_000);
        }
    }

    /** Nanoseconds until the rest after the last denoise is over; 0 if it is. */
    private long restLeft() {
        long now = nanoTime.getAsLong();
        return now < restUntil ? restUntil - now : 0;
    }

    /**
     * On the denoiser's thread: the waiting frame, if its job's film still holds its pass (the
     * render is held there); otherwise the next frame starts the next denoise.
     */
    private void retryWaiting() {
        RenderController.Frame f;
        synchronized (this) {
            retry = false;
            f = waiting;
            if (!on || busy || f == null) {
                return;
            }
            if (restLeft() > 0) {
                scheduleRetry();
                return;
            }
            busy = true;
        }
        Optional<RenderBuffers> b = f.buffers().get();
        if (b.isPresent() && b.get().color().equals(f.image())) {      // the film still holds f's pass
            synchronized (this) {
                if (waiting == f) {
                    waiting = null;
                }
            }
            start(f, b);
        } else {
            synchronized (this) {
                busy = false;                  // the next frame (the render goes on) starts the next denoise
            }
        }
    }

    private void start(RenderController.Frame frame, Optional<RenderBuffers> buffers) {
        if (buffers.isEmpty()) {               // not expected at the end of a pass; the next frame tries again
            synchronized (this) {
                busy = false;
            }
            return;
        }
        thread.schedule(() -> denoise(frame, buffers.get()), 0);
    }

    /** On the denoiser's thread. */
    private void denoise(RenderController.Frame frame, RenderBuffers buffers) {
        long t0 = nanoTime.getAsLong();
        Image clean = null;
        try {
            clean = filter.apply(buffers);
        } finally {
            long t1 = nanoTime.getAsLong();
            boolean show;
            synchronized (this) {
                busy = false;
                restUntil = t1 + REST_FACTOR * (t1 - t0);
                show = clean != null && on && latest != null && latest.generation() == frame.generation();
                if (show) {
                    denoised++;
                }
                if (waiting != null) {
                    scheduleRetry();
                }
            }
            if (show) {
                presenter.acceptDenoised(new RenderController.Frame(clean, frame.samplesPerPixel(), false, frame.generation(),
                        frame.buffers()));
            }
        }
    }

    @Override
    public void close() {
        thread.shutdown();
    }
}
