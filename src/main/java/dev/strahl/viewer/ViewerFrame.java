package dev.strahl.viewer;

import java.awt.BorderLayout;
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
    private final Timer timer;

    ViewerFrame(RenderController controller, FramePresenter presenter, Path sceneFile, int filmWidth, int filmHeight, Runnable onClose) {
        assert SwingUtilities.isEventDispatchThread();
        this.controller = controller;
        frame = new JFrame(title(sceneFile));
        frame.setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                onClose.run();
            }
        });
        image = new ImagePanel(presenter, filmWidth, filmHeight);
        status = new StatusBar();
        files = new FileActions(frame, controller, presenter, image::showMessage, sceneFile, f -> frame.setTitle(title(f)));
        actions = new ViewerActions(controller, presenter, files, frame.getRootPane(), onClose);
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

    void refreshStatus() {
        RenderController.Status s = controller.status();
        status.update(s);
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
