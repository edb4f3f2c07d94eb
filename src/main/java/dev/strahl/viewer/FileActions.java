package dev.strahl.viewer;

import dev.strahl.io.ImageWriters;
import dev.strahl.scene.SceneException;
import java.awt.event.KeyEvent;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.ExecutionException;
import java.util.function.Consumer;
import javax.swing.Action;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.KeyStroke;
import javax.swing.SwingWorker;
import javax.swing.event.MenuEvent;
import javax.swing.event.MenuListener;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * Opening a scene (from the file chooser, File → Open Recent or a file dropped onto the window)
 * and saving the image. Files are read and written on background threads ({@link SwingWorker});
 * errors become a dialog with the one-line message, and a scene that fails to load (or asks for
 * settings that cannot be applied, or for a film the heap cannot hold) leaves the current one on
 * screen. Every scene opened goes to the front of the {@link RecentFiles}.
 *
 * <p>Saving writes what the window shows: the denoised image while View → Denoise shows one
 * (named "…-64spp-denoised.png", and the message says "denoised"), else the newest image of the
 * render. Either way the linear image, before the display's exposure and tone curve.
 */
final class FileActions {
    /** Loads a scene file with the settings it is to be shown with ({@link SceneFiles#open}). */
    interface Opener {
        SceneFiles.Opened open(Path file) throws SceneException;
    }

    private final JFrame frame;
    private final FramePresenter presenter;
    private final Consumer<String> status;
    private final Opener opener;
    private final Consumer<SceneFiles.Opened> onSceneOpened;
    final RecentFiles recent;
    private Path sceneFile;

    final Action open;
    final Action save;

    FileActions(JFrame frame, FramePresenter presenter, Consumer<String> status, Path sceneFile, Opener opener,
                Consumer<SceneFiles.Opened> onSceneOpened, RecentFiles recent) {
        this.frame = frame;
        this.recent = recent;
        this.presenter = presenter;
        this.status = status;
        this.sceneFile = sceneFile;
        this.opener = opener;
        this.onSceneOpened = onSceneOpened;
        open = ViewerActions.action("Open scene…", Icons.open(), "Open a scene file (.json, .obj or .ply)",
                KeyStroke.getKeyStroke(KeyEvent.VK_O, ViewerActions.menuMask()), e -> chooseScene());
        save = ViewerActions.action("Save image…", Icons.save(), "Save the image shown (denoised if it is) as PNG (sRGB) or PFM (linear)",
                KeyStroke.getKeyStroke(KeyEvent.VK_S, ViewerActions.menuMask()), e -> chooseImageFile());
    }

    private void chooseScene() {
        JFileChooser chooser = new JFileChooser(sceneFile != null && sceneFile.toAbsolutePath().getParent() != null
                ? sceneFile.toAbsolutePath().getParent().toFile() : new File("."));
        chooser.setDialogTitle("Open scene");
        chooser.setFileFilter(new FileNameExtensionFilter("Scenes (*.json, *.obj, *.ply)", "json", "obj", "ply"));
        if (chooser.showOpenDialog(frame) == JFileChooser.APPROVE_OPTION) {
            openScene(chooser.getSelectedFile().toPath());
        }
    }

    /**
     * Loads {@code file} in the background and shows it with its settings; on failure shows the
     * error and keeps the current scene.
     */
    void openScene(Path file) {
        status.accept("Loading " + file.getFileName() + "…");
        new SwingWorker<SceneFiles.Opened, Void>() {
            @Override
            protected SceneFiles.Opened doInBackground() throws SceneException {
                return opener.open(file);
            }

            @Override
            protected void done() {
                try {
                    SceneFiles.Opened opened = get();
                    sceneFile = file;
                    recent.add(file);
                    onSceneOpened.accept(opened);
                    status.accept("Opened " + file.getFileName());
                } catch (ExecutionException e) {
                    Throwable cause = e.getCause();
                    String text = cause instanceof SceneException ? cause.getMessage()
                            : cause instanceof IllegalArgumentException ? file + ": " + cause.getMessage()   // e.g. a film too large for the heap
                            : file + ": " + cause;
                    status.accept("Could not open " + file.getFileName());
                    if (!Files.exists(file)) {
                        recent.remove(file);
                    }
                    JOptionPane.showMessageDialog(frame, text, "Cannot open scene", JOptionPane.ERROR_MESSAGE);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }.execute();
    }

    /**
     * File → Open Recent: the {@link RecentFiles}, newest first, read again each time the menu
     * opens (another window may have added some), and Clear.
     */
    JMenu recentMenu() {
        JMenu menu = new JMenu("Open Recent");
        menu.setMnemonic(KeyEvent.VK_R);
        menu.addMenuListener(new MenuListener() {
            @Override
            public void menuSelected(MenuEvent e) {
                fillRecent(menu);
            }

            @Override
            public void menuDeselected(MenuEvent e) {
            }

            @Override
            public void menuCanceled(MenuEvent e) {
            }
        });
        fillRecent(menu);
        return menu;
    }

    void fillRecent(JMenu menu) {
        menu.removeAll();
        int n = 0;
        for (Path file : recent.list()) {
            n++;
            JMenuItem item = new JMenuItem(n + "  " + file.getFileName());
            if (n <= 9) {
                item.setMnemonic(KeyEvent.VK_0 + n);
            }
            item.setToolTipText(file.toString());
            item.addActionListener(e -> openScene(file));
            menu.add(item);
        }
        if (n == 0) {
            JMenuItem none = new JMenuItem("No recent scenes");
            none.setEnabled(false);
            menu.add(none);
        }
        menu.addSeparator();
        JMenuItem clear = new JMenuItem("Clear Recent");
        clear.setEnabled(n > 0);
        clear.addActionListener(e -> recent.clear());
        menu.add(clear);
    }

    private void chooseImageFile() {
        FramePresenter.Pick shot = presenter.pick();
        if (shot == null) {
            status.accept("Nothing to save yet");
            return;
        }
        FileNameExtensionFilter png = new FileNameExtensionFilter("PNG image, sRGB 8 bit (*.png)", "png");
        FileNameExtensionFilter pfm = new FileNameExtensionFilter("PFM image, linear float (*.pfm)", "pfm");
        JFileChooser chooser = new JFileChooser(new File("."));
        chooser.setDialogTitle("Save image");
        chooser.addChoosableFileFilter(png);
        chooser.addChoosableFileFilter(pfm);
        chooser.setFileFilter(png);
        chooser.setSelectedFile(new File(defaultName(sceneFile, shot.frame().samplesPerPixel(), shot.denoised())));
        if (chooser.showSaveDialog(frame) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path out = withExtension(chooser.getSelectedFile().toPath(), chooser.getFileFilter() == pfm ? "pfm" : "png");
        if (Files.exists(out) && JOptionPane.showConfirmDialog(frame, out + " exists. Replace it?", "Save image",
                JOptionPane.OK_CANCEL_OPTION, JOptionPane.WARNING_MESSAGE) != JOptionPane.OK_OPTION) {
            return;
        }
        saveImage(presenter.pick(), out);   // the newest image shown, not the one from when the dialog opened
    }

    /** Writes the linear image of {@code shot} to {@code out} in the background (atomically, by {@link ImageWriters}). */
    void saveImage(FramePresenter.Pick shot, Path out) {
        new SwingWorker<Void, Void>() {
            @Override
            protected Void doInBackground() throws Exception {
                ImageWriters.write(shot.frame().image(), out);
                return null;
            }

            @Override
            protected void done() {
                try {
                    get();
                    status.accept(savedText(out, shot));
                } catch (ExecutionException e) {
                    JOptionPane.showMessageDialog(frame, "Cannot write " + out + ": " + e.getCause().getMessage(),
                            "Cannot save image", JOptionPane.ERROR_MESSAGE);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }.execute();
    }

    /** "Saved x.png (64 spp, denoised)": what was saved. */
    static String savedText(Path out, FramePresenter.Pick shot) {
        return "Saved " + out.getFileName() + " (" + shot.frame().samplesPerPixel() + " spp"
                + (shot.frame().preview() ? ", preview" : "") + (shot.denoised() ? ", denoised" : "") + ")";
    }

    /** "cornell-box-64spp.png" for the scene file and sample count. */
    static String defaultName(Path scene, int spp) {
        return defaultName(scene, spp, false);
    }

    /** "cornell-box-64spp.png", or "cornell-box-64spp-denoised.png" for a denoised image. */
    static String defaultName(Path scene, int spp, boolean denoised) {
        String base = scene == null || scene.getFileName() == null ? "strahl" : scene.getFileName().toString();
        int dot = base.lastIndexOf('.');
        return (dot > 0 ? base.substring(0, dot) : base) + "-" + spp + "spp" + (denoised ? "-denoised" : "") + ".png";
    }

    /** {@code file} itself if it names a .png or .pfm, else with {@code ext} appended. */
    static Path withExtension(Path file, String ext) {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".png") || name.endsWith(".pfm")) {
            return file;
        }
        return file.resolveSibling(file.getFileName() + "." + ext);
    }
}
