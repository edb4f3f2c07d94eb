package dev.strahl.viewer;

import dev.strahl.color.DisplayEncoding;
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
 * through its data buffer by {@link DisplayEncoding}), published whole by one reference: the display never
 * sees half of one pass and half of the next. Changing the exposure or the tone curve
 * ({@link ToneMapping}: clamp, ACES, AgX, as {@code --tonemap} for PNGs) re-converts the last
 * frame and never restarts rendering.
 *
 * <p>With View → Denoise on ({@link #setDenoised}), a full-resolution job's frames are shown as
 * the {@link LiveDenoiser} hands them over denoised ({@link #acceptDenoised}): once the first
 * denoised frame of a job has come, the newest denoised one is shown, never again a noisy one of
 * that job; before it, and for previews, the noisy frames. Off, the noisy frames again.
 *
 * <p>With View → Noise on ({@link #setNoiseView}), a full-resolution frame is shown as the
 * {@link NoiseHeatMap} of its pixels' relative error, computed from its pass's buffers when it is
 * handed over (the film still holds that pass then); previews as they are.
 */
final class FramePresenter implements Consumer<RenderController.Frame>, AutoCloseable {

    /** Exposure range offered to the user, in stops. */
    static final double MIN_EXPOSURE = -10;
    static final double MAX_EXPOSURE = 10;

    /** A converted frame: what the image panel paints; {@code denoised} if it is the denoiser's output. */
    record Shown(BufferedImage image, RenderController.Frame frame, double exposure, ToneMapping curve, boolean denoised) {}

    /** The frame to show (or save), and whether it is the denoiser's output. */
    record Pick(RenderController.Frame frame, boolean denoised) {}

    private final ExecutorService worker = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "strahl-viewer-display");
        t.setDaemon(true);
        return t;
    });
    private final AtomicBoolean scheduled = new AtomicBoolean();
    private RenderController.Frame latest;     // guarded by this
    private RenderController.Frame latestDenoised;   // guarded by this
    private boolean denoise;                   // guarded by this: View → Denoise
    /** View → Noise: the scale of the heat map, or 0 when off (guarded by this). */
    private double noiseScale;
    /** The heat map of {@link #latest}, when View → Noise is on and it is no preview (guarded by this). */
    private BufferedImage latestHeat;
    private volatile double exposure;
    private volatile ToneMapping curve = ToneMapping.CLAMP;
    private volatile Shown shown;
    /** The heat map {@link #shown} shows, or null for the image (the presenter's thread only). */
    private BufferedImage shownHeat;
    private final List<Runnable> onShown = new CopyOnWriteArrayList<>();

    /** Hands a frame over (from a render thread); returns at once. */
    @Override
    public void accept(RenderController.Frame frame) {
        double scale;
        synchronized (this) {
            if (latest != null && frame.generation() < latest.generation()) {
                return;
            }
            scale = noiseScale;
        }
        BufferedImage heat = scale > 0 && !frame.preview()
                ? frame.buffers().get().map(b -> NoiseHeatMap.of(b.relativeError(), scale)).orElse(null) : null;
        synchronized (this) {
            if (latest != null && frame.generation() < latest.generation()) {
                return;
            }
            latest = frame;
            latestHeat = heat;
        }
        schedule();
    }

    /**
     * View → Noise: shows the heat map of the remaining relative error against {@code scale} (the
     * noise threshold, or {@link NoiseHeatMap#DEFAULT_SCALE}) from the next frame on, or (0) the image.
     */
    void setNoiseView(double scale) {
        RenderController.Frame f;
        synchronized (this) {
            noiseScale = scale;
            latestHeat = null;
            f = latest;
        }
        // a held or finished render's film still holds its last pass: its heat map at once
        BufferedImage heat = scale > 0 && f != null && !f.preview()
                ? f.buffers().get().map(b -> NoiseHeatMap.of(b.relativeError(), scale)).orElse(null) : null;
        synchronized (this) {
            if (latest == f && noiseScale == scale) {
                latestHeat = heat;
            }
        }
        schedule();
    }

    /** Whether the heat map is shown (for the status bar and tests). */
    synchronized boolean noiseView() {
        return noiseScale > 0;
    }

    /** Hands a denoised frame over (from the denoiser's thread); dropped if a newer job's frame has come. */
    void acceptDenoised(RenderController.Frame frame) {
        synchronized (this) {
            if (latest != null && frame.generation() < latest.generation()) {
                return;
            }
            latestDenoised = frame;
        }
        schedule();
    }

    /** Shows the denoised frames (when there are) or the noisy ones; re-converts at once. */
    void setDenoised(boolean on) {
        synchronized (this) {
            denoise = on;
        }
        schedule();
    }

    /**
     * What is to be shown: with Denoise on, the newest denoised frame if it is of the job whose
     * frames come in now and that job is no preview; else the newest frame.
     */
    synchronized Pick pick() {
        boolean useDenoised = denoise && latest != null && !latest.preview() && latestDenoised != null
                && latestDenoised.generation() == latest.generation();
        return latest == null ? null : new Pick(useDenoised ? latestDenoised : latest, useDenoised);
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
        Pick p = pick();
        double e = exposure;
        ToneMapping c = curve;
        Shown s = shown;
        BufferedImage heat;
        synchronized (this) {
            heat = p != null && p.frame() == latest ? latestHeat : null;
        }
        if (p == null || (s != null && s.frame() == p.frame() && s.exposure() == e && s.curve() == c && heat == shownHeat)) {
            return;
        }
        RenderController.Frame f = p.frame();
        shownHeat = heat;
        shown = new Shown(heat != null ? heat : DisplayEncoding.toBufferedImage(f.image(), e, c), f, e, c, p.denoised() && heat == null);
        onShown.forEach(Runnable::run);
    }

    @Override
    public void close() {
        worker.shutdownNow();
    }
}
