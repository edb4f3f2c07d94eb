package dev.strahl.viewer;

import dev.strahl.scene.SceneException;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.lang.management.ManagementFactory;
import java.lang.reflect.InvocationTargetException;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import javax.swing.SwingUtilities;

/**
 * The interactive viewer: a window showing a scene converging pass by pass, with camera
 * navigation, render settings and saving. The command line's {@code strahl view} is
 * {@code Viewer.open(options).awaitClosed()}.
 *
 * <p>Threads: the render job's threads render and report passes to a {@link RenderController};
 * with View → Denoise on, a {@link LiveDenoiser} thread denoises passes now and then; a
 * {@link FramePresenter} thread tone-maps the newest pass; the event dispatch thread only paints
 * finished images and handles input, and never waits for rendering. Closing the window cancels the
 * render at once.
 *
 * <p>With the system property {@code strahl.viewer.trace=true} every displayed frame is logged to
 * stderr with its time since the JVM started (used to measure start-up and preview rates).
 */
public final class Viewer {
    private static final boolean TRACE = Boolean.getBoolean("strahl.viewer.trace");

    private final RenderController controller;
    private final FramePresenter presenter;
    private final LiveDenoiser denoiser;
    private final CountDownLatch closed = new CountDownLatch(1);
    private final AtomicBoolean closing = new AtomicBoolean();
    private volatile ViewerFrame ui;

    private Viewer(RenderController controller, FramePresenter presenter, LiveDenoiser denoiser) {
        this.controller = controller;
        this.presenter = presenter;
        this.denoiser = denoiser;
    }

    /**
     * Refuses a film size before the viewer allocates a film of it: at start-up and for every
     * scene opened from the window, with the size its settings ask for. {@code strahl view} passes
     * the heap check of the command line, so that the viewer refuses what {@code strahl render}
     * refuses.
     */
    @FunctionalInterface
    public interface FilmCheck {
        /** Accepts every size. */
        FilmCheck NONE = (width, height, features) -> { };

        /**
         * Returns if a film of this size may be rendered, with feature buffers (which the viewer
         * keeps to denoise, View → Denoise) or without.
         *
         * @throws IllegalArgumentException with the one-line reason if it may not
         */
        void check(int width, int height, boolean features);
    }

    /**
     * Loads the scene, starts rendering and opens the window, with no check of the film size
     * ({@link FilmCheck#NONE}).
     *
     * @throws SceneException    if the scene cannot be loaded or asks for an unknown integrator (nothing is opened then)
     * @throws HeadlessException if there is no display
     */
    public static Viewer open(ViewerOptions options) throws SceneException {
        return open(options, FilmCheck.NONE);
    }

    /**
     * Loads the scene, starts rendering and opens the window. Call from any thread but the event
     * dispatch thread. Every scene, the first and those opened from the window, passes
     * {@code filmCheck} with the film size its settings ask for before anything is rendered; a
     * scene opened from the window that fails it gives the error dialog and leaves the current one.
     *
     * @throws SceneException           if the scene cannot be loaded or asks for an unknown integrator (nothing is opened then)
     * @throws IllegalArgumentException if the film size fails {@code filmCheck} (nothing is opened then)
     * @throws HeadlessException        if there is no display
     */
    public static Viewer open(ViewerOptions options, FilmCheck filmCheck) throws SceneException {
        if (GraphicsEnvironment.isHeadless()) {
            throw new HeadlessException("the viewer needs a display (DISPLAY is not set, or java.awt.headless is true)");
        }
        if (SwingUtilities.isEventDispatchThread()) {
            throw new IllegalStateException("Viewer.open must not be called on the event dispatch thread");
        }
        mark("opening");
        SceneFiles.Opened opened = SceneFiles.open(options.scene(), options, filmCheck);
        FramePresenter presenter = new FramePresenter();
        LiveDenoiser denoiser = LiveDenoiser.of(presenter);
        RenderController controller = RenderController.rendering(opened.scene(), opened.settings(), options.stopAt(), denoiser);
        Viewer viewer = new Viewer(controller, presenter, denoiser);
        if (TRACE) {
            presenter.onShown(viewer::trace);
        }
        mark("scene loaded");
        controller.startBeforeDisplay();      // a first small image while the window is being built
        try {
            SwingUtilities.invokeAndWait(() -> viewer.createWindow(options, filmCheck, opened));
        } catch (InvocationTargetException e) {
            viewer.close();
            if (e.getCause() instanceof Error error) {
                throw error;                  // e.g. AWTError: cannot connect to the display
            }
            throw e.getCause() instanceof RuntimeException r ? r : new IllegalStateException(e.getCause());
        } catch (InterruptedException e) {
            viewer.close();
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while opening the window", e);
        }
        return viewer;
    }

    private static void mark(String what) {
        if (TRACE) {
            System.err.printf(Locale.ROOT, "strahl-viewer: t=%d ms %s%n",
                    System.currentTimeMillis() - ManagementFactory.getRuntimeMXBean().getStartTime(), what);
        }
    }

    private void createWindow(ViewerOptions options, FilmCheck filmCheck, SceneFiles.Opened opened) {
        mark("building the window");
        options.theme().install();
        mark("look and feel installed");
        RecentFiles recent = RecentFiles.user();
        if (options.scene() != null) {
            recent.add(options.scene());
        }
        ViewerFrame frame = new ViewerFrame(controller, presenter, denoiser, opened, file -> SceneFiles.open(file, options, filmCheck), recent,
                this::close);
        if (TRACE) {
            AtomicBoolean first = new AtomicBoolean(true);
            frame.image.onPainted(shown -> {
                if (first.getAndSet(false)) {
                    System.err.printf(Locale.ROOT, "strahl-viewer: t=%d ms epoch=%d first paint spp=%d preview=%b%n",
                            System.currentTimeMillis() - ManagementFactory.getRuntimeMXBean().getStartTime(),
                            System.currentTimeMillis(), shown.frame().samplesPerPixel(), shown.frame().preview());
                }
            });
        }
        ui = frame;
        mark("window built");
        frame.show();
        controller.displayReady();
        mark("window shown");
    }

    private void trace() {
        FramePresenter.Shown s = presenter.shown();
        long epoch = System.currentTimeMillis();
        long sinceStart = epoch - ManagementFactory.getRuntimeMXBean().getStartTime();
        RenderController.Status st = controller.status();
        double cpu = ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
                ? os.getProcessCpuTime() * 1e-9 : Double.NaN;
        System.err.printf(Locale.ROOT, "strahl-viewer: t=%d ms epoch=%d frame gen=%d spp=%d preview=%b %dx%d samples=%d seconds=%.3f cpu=%.3f%n",
                sinceStart, epoch, s.frame().generation(), s.frame().samplesPerPixel(), s.frame().preview(),
                s.image().getWidth(), s.image().getHeight(), st.samples(), st.seconds(), cpu);
    }

    /** Stops rendering at once and closes the window; safe to call more than once, from any thread. */
    public void close() {
        if (!closing.compareAndSet(false, true)) {
            return;
        }
        controller.close();
        denoiser.close();
        presenter.close();
        ViewerFrame frame = ui;
        if (frame != null) {
            if (SwingUtilities.isEventDispatchThread()) {
                frame.dispose();
            } else {
                SwingUtilities.invokeLater(frame::dispose);
            }
        }
        closed.countDown();
    }

    /** Waits until the window is closed. */
    public void awaitClosed() throws InterruptedException {
        closed.await();
    }

    /** Waits up to the given time for the window to close; returns whether it has. */
    public boolean awaitClosed(long timeout, TimeUnit unit) throws InterruptedException {
        return closed.await(timeout, unit);
    }

    RenderController controller() {
        return controller;
    }

    FramePresenter presenter() {
        return presenter;
    }

    LiveDenoiser denoiser() {
        return denoiser;
    }

    ViewerFrame ui() {
        return ui;
    }
}
