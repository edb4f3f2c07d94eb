package dev.strahl.viewer;

import dev.strahl.render.RenderSettings;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Frame;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.nio.file.Path;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.WindowConstants;

/**
 * The window: menu bar and toolbar on top, the image in the middle, the status bar below.
 * Created, used and disposed on the event dispatch thread.
 */
final class ViewerFrame {
    /** How often the status bar is refreshed. */
    static final int STATUS_MILLIS = 200;

    final JFrame frame;
    final ImagePanel image;
    final StatusBar status;
    final FileActions files;
    final ViewerActions actions;
    private final RenderController controller;
    private final FramePresenter presenter;
    private final LiveDenoiser denoiser;
    private final Timer timer;
    /** The film size the current scene asks for (its settings' size before the window fits it). */
    private int askedWidth;
    private int askedHeight;

    /**
     * The window for {@code opened}, which {@code controller} renders; {@code opener} loads the
     * scenes opened from the window (with the file chooser, from {@code recent} or dropped onto it).
     */
    ViewerFrame(RenderController controller, FramePresenter presenter, LiveDenoiser denoiser, SceneFiles.Opened opened,
                FileActions.Opener opener, RecentFiles recent, Runnable onClose) {
        assert SwingUtilities.isEventDispatchThread();
        this.controller = controller;
        this.presenter = presenter;
        this.denoiser = denoiser;
        askedWidth = opened.settings().output().width();
        askedHeight = opened.settings().output().height();
        frame = new JFrame(title(opened.file()));
        frame.setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                onClose.run();
            }
        });
        image = new ImagePanel(presenter, askedWidth, askedHeight);
        status = new StatusBar();
        files = new FileActions(frame, presenter, image::showMessage, opened.file(), opener, this::showScene, recent);
        SceneDrop drop = new SceneDrop(files::openScene);
        frame.setTransferHandler(drop);
        image.setTransferHandler(drop);
        actions = new ViewerActions(controller, presenter, denoiser, files, frame.getRootPane(), onClose);
        CameraMouse.attach(image, controller);

        frame.setJMenuBar(actions.menuBar());
        frame.add(actions.toolBar(), BorderLayout.NORTH);
        frame.add(image, BorderLayout.CENTER);
        frame.add(status, BorderLayout.SOUTH);
        frame.pack();
        frame.setLocationByPlatform(true);

        timer = new Timer(STATUS_MILLIS, e -> refreshStatus());
        timer.start();
        refreshStatus();
    }

    /** Shows the window; from then on the film follows the image area's size. */
    void show() {
        frame.setVisible(true);
        image.requestFocusInWindow();
        image.onFilmSize(controller::resize);
    }

    /**
     * Shows a scene opened from the window, with its settings. When it asks for another film size
     * than the scene before, the window is resized to show the film at that size (unless it is
     * maximised); otherwise the window keeps its size. Either way the film takes the new scene's
     * aspect, letterboxed in the window. With Denoise on, it renders the denoiser's guides too.
     */
    void showScene(SceneFiles.Opened opened) {
        RenderSettings s = opened.settings();
        if (denoiser.enabled()) {
            s = s.withAovs(LiveDenoiser.withGuides(s.output().aovs()));
        }
        boolean newSize = s.output().width() != askedWidth || s.output().height() != askedHeight;
        askedWidth = s.output().width();
        askedHeight = s.output().height();
        image.setFilm(s.output().width(), s.output().height());
        if (newSize && (frame.getExtendedState() & Frame.MAXIMIZED_BOTH) == 0) {
            frame.pack();
        }
        Dimension film = image.filmSize();
        controller.setScene(opened.scene(), film != null ? s.withSize(film.width, film.height) : s);
        frame.setTitle(title(opened.file()));
        refreshStatus();
    }

    void refreshStatus() {
        RenderController.Status s = controller.status();
        status.update(s);
        status.showDenoise(denoiser.enabled(), presenter.shown());
        actions.refresh(s);
    }

    void dispose() {
        timer.stop();
        frame.dispose();
    }

    static String title(Path sceneFile) {
        return "strahl — " + (sceneFile == null || sceneFile.getFileName() == null ? "scene" : sceneFile.getFileName());
    }
}
