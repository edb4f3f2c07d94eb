import dev.strahl.render.RenderSettings;
import dev.strahl.viewer.Theme;
import dev.strahl.viewer.Viewer;
import dev.strahl.viewer.ViewerOptions;
import java.awt.Color;
import java.awt.Component;
import java.awt.Container;
import java.awt.Frame;
import java.awt.Graphics2D;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.SwingUtilities;

/**
 * The viewer without and with View → Denoise, side by side, for docs/viewer.md. Under Xvfb:
 *
 *   Xvfb :99 -screen 0 1280x1024x24 &  DISPLAY=:99 java -cp target/strahl.jar docs/showcase/ViewerDenoiseShot.java OUT.png
 *
 * Shows the Cornell Box at 384x384, stopping at 16 spp: the window at 16 spp (noisy), then the
 * same after turning Denoise on (the render restarts with the albedo, normal and depth buffers and
 * is shown denoised, again at 16 spp).
 */
public class ViewerDenoiseShot {
    public static void main(String[] args) throws Exception {
        ViewerOptions o = ViewerOptions.defaults().withScene(Path.of("scenes/cornell-box.json"))
                .withSettings(RenderSettings.defaults().withSize(384, 384)).withStopAt(16).withTheme(Theme.LIGHT);
        Viewer viewer = Viewer.open(o, Viewer.FilmCheck.NONE);
        JFrame frame = onEdt(() -> {
            for (Frame f : Frame.getFrames()) {
                if (f instanceof JFrame j && f.isVisible()) {
                    return j;
                }
            }
            return null;
        });
        waitForStatus(frame, "Done", 60);
        Thread.sleep(800);
        BufferedImage noisy = new Robot().createScreenCapture(frame.getBounds());
        SwingUtilities.invokeAndWait(() -> {
            JMenu view = frame.getJMenuBar().getMenu(2);
            for (Component c : view.getMenuComponents()) {
                if (c instanceof JCheckBoxMenuItem item && item.getText().equals("Denoise")) {
                    item.doClick(0);
                }
            }
        });
        waitForStatus(frame, "denoised, 16 spp", 60);
        Thread.sleep(800);
        BufferedImage clean = new Robot().createScreenCapture(frame.getBounds());
        int gap = 16;
        BufferedImage both = new BufferedImage(noisy.getWidth() + gap + clean.getWidth(), Math.max(noisy.getHeight(), clean.getHeight()),
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = both.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, both.getWidth(), both.getHeight());
        g.drawImage(noisy, 0, 0, null);
        g.drawImage(clean, noisy.getWidth() + gap, 0, null);
        g.dispose();
        ImageIO.write(both, "png", new File(args[0]));
        viewer.close();
        System.exit(0);
    }

    static void waitForStatus(JFrame frame, String text, int seconds) throws Exception {
        long end = System.nanoTime() + seconds * 1_000_000_000L;
        while (System.nanoTime() < end) {
            if (onEdt(() -> contains(frame.getContentPane(), text))) {
                return;
            }
            Thread.sleep(100);
        }
        throw new IllegalStateException("no '" + text + "' in the window after " + seconds + " s");
    }

    static boolean contains(Container root, String text) {
        for (Component c : root.getComponents()) {
            if (c instanceof JLabel l && l.isShowing() && l.getText() != null && l.getText().equals(text)) {
                return true;
            }
            if (c instanceof Container inner && contains(inner, text)) {
                return true;
            }
        }
        return false;
    }

    static <T> T onEdt(java.util.concurrent.Callable<T> task) throws Exception {
        AtomicReference<T> result = new AtomicReference<>();
        AtomicReference<Exception> error = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                result.set(task.call());
            } catch (Exception e) {
                error.set(e);
            }
        });
        if (error.get() != null) {
            throw error.get();
        }
        return result.get();
    }
}
