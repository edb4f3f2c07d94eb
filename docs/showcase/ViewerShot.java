import dev.strahl.render.RenderSettings;
import dev.strahl.viewer.SceneOverrides;
import dev.strahl.viewer.Theme;
import dev.strahl.viewer.Viewer;
import dev.strahl.viewer.ViewerOptions;
import java.awt.Frame;
import java.awt.Rectangle;
import java.awt.Robot;
import java.io.File;
import java.nio.file.Path;
import java.util.prefs.Preferences;
import javax.imageio.ImageIO;
import javax.swing.JFrame;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.MenuElement;
import javax.swing.MenuSelectionManager;
import javax.swing.SwingUtilities;

/**
 * A screenshot of the viewer with File → Open Recent open, for docs/viewer.md. Under Xvfb:
 *
 *   Xvfb :99 -screen 0 1024x768x24 &  DISPLAY=:99 java -cp target/strahl.jar docs/showcase/ViewerShot.java OUT.png SECONDS
 *
 * Shows scenes/showcase-depth.json at 384x256 with the lens given as view's --aperture 0.12
 * --focus-distance 4.3 would; a few recent files are put into the preferences first.
 */
public class ViewerShot {
    public static void main(String[] args) throws Exception {
        Preferences recent = Preferences.userRoot().node("dev/strahl/viewer");
        String[] files = {"scenes/cornell-box.json", "scenes/showcase-spheres.json", "docs/showcase/materials-grid.json"};
        for (int i = 0; i < files.length; i++) {
            recent.put("recent." + i, Path.of(files[files.length - 1 - i]).toAbsolutePath().toString());
        }
        recent.flush();
        ViewerOptions o = ViewerOptions.defaults().withScene(Path.of("scenes/showcase-depth.json"))
                .withSettings(RenderSettings.defaults().withSize(384, 256)).withStopAt(0).withTheme(Theme.LIGHT)
                .withOverrides(new SceneOverrides(null, 0.12, 4.3));
        Viewer viewer = Viewer.open(o, Viewer.FilmCheck.NONE);
        Thread.sleep(Long.parseLong(args[1]) * 1000);
        JFrame[] frame = new JFrame[1];
        SwingUtilities.invokeAndWait(() -> {
            for (Frame f : Frame.getFrames()) {
                if (f instanceof JFrame j && f.isVisible()) {
                    frame[0] = j;
                }
            }
            JMenuBar bar = frame[0].getJMenuBar();
            JMenu file = bar.getMenu(0);
            JMenu open = (JMenu) file.getItem(1);
            file.doClick(0);
            MenuSelectionManager.defaultManager().setSelectedPath(new MenuElement[] {bar, file, file.getPopupMenu(), open, open.getPopupMenu()});
        });
        Thread.sleep(1500);
        Rectangle r = frame[0].getBounds();
        r.width += 260;                     // the submenu reaches past the window
        ImageIO.write(new Robot().createScreenCapture(r), "png", new File(args[0]));
        viewer.close();
        System.exit(0);
    }
}
