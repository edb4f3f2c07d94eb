package dev.strahl.viewer;

import dev.strahl.film.Tonemap;
import dev.strahl.image.ToneMapping;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;

/**
 * Turns the controller's linear images into displayable ones on a thread of its own, so that
 * neither the render threads nor the event dispatch thread spend time on tone mapping. Frames are
 * coalesced: only the newest waiting frame is converted, older ones are dropped, and so are frames
 * of a job older than one already shown. Each result is a new {@link BufferedImage} (written
 * through its data buffer by {@link Tonemap}), published whole by one reference: the display never
 * sees half of one pass and half of the next. Changing the exposure or the tone curve
 * ({@link ToneMapping}: clamp, ACES, AgX, as {@code --tonemap} for PNGs) re-converts the last
 * frame and never restarts rendering.
 */
final class FramePresenter implements Consumer<RenderController.Frame>, AutoCloseable {

    /** Exposure range offered to the user, in stops. */
    static final double MIN_EXPOSURE = -10;
    static final double MAX_EXPOSURE = 10;

    /** A converted frame: what the image panel paints. */
    record Shown(BufferedImage image, RenderController.Frame frame, double exposure, ToneMapping curve) {}

    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "strahl-viewer-display");
        t.setDaemon(true);
        return t;
    });
    private final AtomicBoolean scheduled = new AtomicBoolean();
    private RenderController.Frame latest;     // guarded by this
    private volatile double exposure;
    private volatile ToneMapping curve = ToneMapping.CLAMP;
    private volatile Shown shown;
    private final List<Runnable> onShown = new CopyOnWriteArrayList<>();

    /** Hands a frame over (from a render thread); returns at once. */
    @Override
    public void accept(RenderController.Frame frame) {
        synchronized (this) {
            if (latest != null && frame.generation() < latest.generation()) {
                return;
            }
            latest = frame;
        }
        schedule();
    }

    /** Sets the display exposure in stops (each stop doubles the displayed radiance). */
    void setExposure(double stops) {
        if (!Double.isFinite(stops)) {
            throw new IllegalArgumentException("exposure must be finite, got " + stops);
        }
        exposure = Math.max(MIN_EXPOSURE, Math.min(MAX_EXPOSURE, stops));
        schedule();
    }

    double exposure() {
        return exposure;
    }

    /** Sets the display's tone curve (display only, as the exposure). */
    void setToneMapping(ToneMapping newCurve) {
        curve = java.util.Objects.requireNonNull(newCurve, "curve");
        schedule();
    }

    ToneMapping toneMapping() {
        return curve;
    }

    /** The last converted frame, or null before the first one. */
    Shown shown() {
        return shown;
    }

    /** The newest frame received (perhaps not yet converted), or null. */
    synchronized RenderController.Frame latest() {
        return latest;
    }

    /** Adds a task run on the presenter's thread after each new {@link #shown()} image (a repaint request). */
    void onShown(Runnable r) {
        onShown.add(r);
    }

    private void schedule() {
        if (scheduled.compareAndSet(false, true)) {
            try {
                worker.execute(this::convert);
            } catch (java.util.concurrent.RejectedExecutionException e) {
                scheduled.set(false);          // closed
            }
        }
    }

    private void convert() {
        scheduled.set(false);                  // a frame arriving from now on schedules another round
        RenderController.Frame f = latest();
        double e = exposure;
        ToneMapping c = curve;
        Shown s = shown;
        if (f == null || (s != null && s.frame() == f && s.exposure() == e && s.curve() == c)) {
            return;
        }
        shown = new Shown(Tonemap.toBufferedImage(f.image(), e, c), f, e, c);
        onShown.forEach(Runnable::run);
    }

    @Override
    public void close() {
        worker.shutdownNow();
    }
}
