package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import dev.strahl.render.RenderSettings;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.io.json.SceneSettings;
import java.awt.Dimension;
import java.awt.GraphicsEnvironment;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import javax.swing.JDialog;
import javax.swing.JOptionPane;
import javax.swing.SwingUtilities;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The viewer in a real window: it shows the Cornell Box converging, the status bar counts the
 * samples, a mouse drag orbits the camera and restarts accumulation, and closing the window stops
 * the render threads; a scene file's film and integrator settings are used, at start and when
 * another scene is opened, unless an option given explicitly overrides them. Needs a display; CI runs it under {@code xvfb-run}, elsewhere without a
 * display it is skipped.
 */
class ViewerEndToEndTest {
    static final int SIZE = 256;
    static final Pattern SPP = Pattern.compile("\\b(\\d+)(?: / \\d+)? spp\\b");

    @Test
    @Timeout(value = 60, unit = TimeUnit.SECONDS)
    void showsTheCornellBoxConvergingAndOrbitsOnADrag() throws Exception {
        assumeTrue(!GraphicsEnvironment.isHeadless(), "no display (headless): run under xvfb-run to include this test");

        List<RenderController.Frame> shown = new CopyOnWriteArrayList<>();
        ViewerOptions options = new ViewerOptions(Path.of("scenes", "cornell-box.json"), RenderSettings.defaults().withSize(SIZE, SIZE).withSeed(1),
                RenderController.UNLIMITED, Theme.LIGHT, Set.of(), SceneOverrides.NONE);
        Viewer viewer = Viewer.open(options);
        try {
            viewer.presenter().onShown(() -> shown.add(viewer.presenter().shown().frame()));
            ViewerFrame ui = viewer.ui();
            Robot robot = new Robot();

            // --- converges: >= 8 spp on screen and in the status bar -------------------------------
            waitFor("8 spp shown and in the status bar", 20,
                    () -> !shown.isEmpty() && last(shown).samplesPerPixel() >= 8 && statusSpp(ui) >= 8);
            robot.waitForIdle();
            robot.delay(300);                   // the repaint of the last frame reaches the screen
            BufferedImage before = capture(robot, ui);
            assertThat(statusSpp(ui)).isGreaterThanOrEqualTo(8);
            try {
                assertShowsTheCornellBox(before);
            } catch (AssertionError e) {
                Path file = Files.createTempFile("strahl-viewer-e2e-", ".png");
                ImageIO.write(before, "png", file.toFile());
                throw new AssertionError(e.getMessage() + "\n(the captured window is in " + file + ")", e);
            }

            // --- a left drag orbits: preview, then accumulation from zero at full resolution ---------
            long generation = viewer.controller().status().generation();
            int sppBefore = viewer.controller().status().samplesPerPixel();
            Rectangle r = onEdt(() -> screenBounds(ui));
            Point start = new Point(r.x + r.width / 2, r.y + r.height / 2);
            robot.mouseMove(start.x, start.y);
            robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
            for (int i = 1; i <= 12; i++) {
                robot.mouseMove(start.x + 6 * i, start.y);
                robot.delay(15);
            }
            robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);

            Vector3d eye = viewer.controller().camera().eye();
            Vector3d sceneEye = new Vector3d(viewer.controller().scene().camera().lookFrom());
            assertThat(eye.distance(sceneEye)).as("the camera orbited").isGreaterThan(0.5);
            assertThat(eye.distance(viewer.controller().camera().target())).as("at the same distance")
                    .isCloseTo(sceneEye.distance(viewer.controller().scene().camera().lookAt()), org.assertj.core.api.Assertions.within(1e-9));
            assertThat(viewer.controller().status().generation()).as("the render restarted").isGreaterThan(generation);
            waitFor("a full-resolution frame after the drag", 10, () -> {
                RenderController.Frame f = last(shown);
                return f.generation() > generation && !f.preview();
            });
            assertThat(shown).as("previews were shown while moving")
                    .anySatisfy(f -> assertThat(f.preview() && f.generation() > generation).isTrue());
            RenderController.Frame after = last(shown);
            assertThat(after.image().width()).isEqualTo(SIZE);
            assertThat(after.samplesPerPixel()).as("accumulation started again").isLessThan(Math.max(sppBefore, 8));
            robot.waitForIdle();
            robot.delay(200);
            assertThat(meanAbsDifference(before, capture(robot, ui))).as("the picture changed").isGreaterThan(10);

            // --- closing the window stops the render threads at once ---------------------------------
            SwingUtilities.invokeLater(() -> ui.frame.dispatchEvent(new WindowEvent(ui.frame, WindowEvent.WINDOW_CLOSING)));
            assertThat(viewer.awaitClosed(5, TimeUnit.SECONDS)).isTrue();
            waitFor("render threads gone", 2, () -> Thread.getAllStackTraces().keySet().stream()
                    .noneMatch(t -> t.isAlive() && t.getName().startsWith("strahl-render")));
        } finally {
            viewer.close();
        }
    }

    @Test
    @Timeout(value = 60, unit = TimeUnit.SECONDS)
    void usesTheSceneFilesSettingsAndThoseOfEachSceneOpened(@TempDir Path dir) throws Exception {
        assumeTrue(!GraphicsEnvironment.isHeadless(), "no display (headless): run under xvfb-run to include this test");
        Files.copy(Path.of("scenes", "cornell-box.obj"), dir.resolve("cornell-box.obj"));
        Files.copy(Path.of("scenes", "cornell-box.mtl"), dir.resolve("cornell-box.mtl"));
        Path a = scene(dir, "a.json", "\"film\": { \"width\": 96, \"height\": 48 },"
                + " \"integrator\": { \"type\": \"direct\", \"maxDepth\": 7, \"hemisphere\": \"uniform\" },");
        Path b = scene(dir, "b.json", "\"film\": { \"width\": 64, \"height\": 64 },"
                + " \"integrator\": { \"type\": \"whitted\", \"maxDepth\": 2, \"lightSamples\": 2 },");
        Path bad = scene(dir, "bad.json", "\"integrator\": { \"type\": \"bidir\" },");
        Path huge = scene(dir, "huge.json", "\"film\": { \"width\": 30000, \"height\": 30000 },");
        Viewer.FilmCheck atMost4k = (w, h, features) -> {          // stands in for the command line's heap check
            if (w > 4096 || h > 4096) {
                throw new IllegalArgumentException("a " + w + "x" + h + " image is too large");
            }
        };

        // As 'strahl view a.json --integrator path': the option given wins over both files
        ViewerOptions options = new ViewerOptions(a, RenderSettings.defaults().withSize(512, 512),
                RenderController.UNLIMITED, Theme.LIGHT, Set.of(SceneSettings.Setting.INTEGRATOR), SceneOverrides.NONE);
        Viewer viewer = Viewer.open(options, atMost4k);
        try {
            ViewerFrame ui = viewer.ui();
            RenderController c = viewer.controller();
            waitFor("a full-resolution pass of a.json", 20, () -> !c.status().preview() && c.status().samplesPerPixel() >= 1);
            RenderController.Status s = c.status();
            assertThat(new Dimension(s.width(), s.height())).as("a.json's film").isEqualTo(new Dimension(96, 48));
            assertThat(onEdt(ui.image::filmSize)).isEqualTo(new Dimension(96, 48));
            assertThat(s.integrator()).as("--integrator was given").isEqualTo(IntegratorKind.PATH);
            assertThat(s.maxDepth()).isEqualTo(7);
            assertThat(s.hemisphere()).isEqualTo(HemisphereSampling.UNIFORM);
            assertThat(onEdt(ui.actions.maxDepth::value)).as("the toolbar shows the file's depth").isEqualTo(7);
            assertThat(onEdt(ui.frame::getTitle)).endsWith("a.json");

            // --- another scene opened from the window brings its own settings -----------------------
            long generation = s.generation();
            SwingUtilities.invokeAndWait(() -> ui.files.openScene(b));
            waitFor("b.json rendering at full resolution", 20, () -> c.status().generation() > generation
                    && !c.status().preview() && c.status().samplesPerPixel() >= 1);
            s = c.status();
            assertThat(new Dimension(s.width(), s.height())).as("b.json's film: the window was resized").isEqualTo(new Dimension(64, 64));
            assertThat(onEdt(ui.image::filmSize)).isEqualTo(new Dimension(64, 64));
            assertThat(s.integrator()).as("--integrator still wins").isEqualTo(IntegratorKind.PATH);
            assertThat(s.maxDepth()).isEqualTo(2);
            assertThat(s.hemisphere()).as("b.json says nothing: the option's value, not a.json's").isEqualTo(HemisphereSampling.COSINE);
            assertThat(c.settings().transport().lightSamples()).isEqualTo(2);
            assertThat(onEdt(ui.actions.maxDepth::value)).isEqualTo(2);
            assertThat(onEdt(ui.actions.hemisphere::value)).isEqualTo(HemisphereSampling.COSINE);
            assertThat(onEdt(ui.frame::getTitle)).endsWith("b.json");

            // --- settings that cannot be applied: a dialog, and the scene on screen stays -----------
            var before = c.scene();
            assertThat(errorDialogOnOpening(ui, bad)).isEqualTo(bad + ":1: 'integrator.type': unknown integrator 'bidir' (known: "
                    + String.join(", ", Arrays.stream(IntegratorKind.values()).map(IntegratorKind::id).toList()) + ")");
            assertThat(c.scene()).isSameAs(before);
            assertThat(onEdt(ui.frame::getTitle)).endsWith("b.json");

            // --- a film that fails the film check: a dialog, nothing started, the scene stays --------
            long lastGeneration = c.status().generation();
            assertThat(errorDialogOnOpening(ui, huge)).isEqualTo(huge + ": a 30000x30000 image is too large");
            assertThat(c.scene()).isSameAs(before);
            assertThat(c.status().generation()).as("no job was started for huge.json").isEqualTo(lastGeneration);
            assertThat(new Dimension(c.status().width(), c.status().height())).isEqualTo(new Dimension(64, 64));
            assertThat(onEdt(ui.frame::getTitle)).endsWith("b.json");
        } finally {
            viewer.close();
        }
    }

    /**
     * View → Denoise with its key N: the render restarts with the denoiser's guides, the window
     * shows the denoised image (the status bar says so, at the stop-at count too, where the render
     * holds), far smoother than the noisy one and still the Cornell Box; saving writes that image;
     * N again shows the noisy image.
     */
    @Test
    @Timeout(value = 60, unit = TimeUnit.SECONDS)
    void theDenoiseToggleShowsAndSavesTheDenoisedImage(@TempDir Path dir) throws Exception {
        assumeTrue(!GraphicsEnvironment.isHeadless(), "no display (headless): run under xvfb-run to include this test");
        ViewerOptions options = new ViewerOptions(Path.of("scenes", "cornell-box.json"), RenderSettings.defaults().withSize(96, 96).withSeed(1),
                8, Theme.LIGHT, Set.of(), SceneOverrides.NONE);
        Viewer viewer = Viewer.open(options);
        try {
            ViewerFrame ui = viewer.ui();
            RenderController c = viewer.controller();
            Robot robot = new Robot();
            waitFor("a full-resolution pass", 20, () -> !c.status().preview() && c.status().samplesPerPixel() >= 1);
            long generation = c.status().generation();
            assertThat(c.settings().output().aovs()).isEmpty();

            pressKey(robot, ui, java.awt.event.KeyEvent.VK_N);
            waitFor("Denoise on", 5, () -> viewer.denoiser().enabled());
            assertThat(onEdt(() -> ui.actions.denoise.getValue(javax.swing.Action.SELECTED_KEY))).isEqualTo(true);
            assertThat(c.status().generation()).as("restarted with the guides").isGreaterThan(generation);
            assertThat(c.settings().output().aovs()).containsAll(LiveDenoiser.GUIDES);
            waitFor("the denoised image at the stop-at count, 8 spp", 30, () -> {
                FramePresenter.Shown s = viewer.presenter().shown();
                return s != null && s.denoised() && s.frame().samplesPerPixel() == 8;
            });
            waitFor("the status bar says so", 5, () -> statusText(ui).contains("denoised, 8 spp"));
            assertThat(c.status().state()).isEqualTo(RenderController.State.DONE);

            FramePresenter.Pick shown = viewer.presenter().pick();
            assertThat(shown.denoised()).isTrue();
            dev.strahl.image.Image noisy = viewer.presenter().latest().image();
            assertThat(roughness(shown.frame().image())).as("denoised: far smoother than the noisy image")
                    .isLessThan(0.5 * roughness(noisy));
            robot.waitForIdle();
            robot.delay(300);
            assertShowsTheCornellBox(capture(robot, ui));

            Path saved = dir.resolve("denoised.pfm");
            SwingUtilities.invokeAndWait(() -> ui.files.saveImage(viewer.presenter().pick(), saved));
            waitFor("the saved file", 10, () -> Files.exists(saved));
            assertThat(dev.strahl.codec.PfmReader.read(saved)).as("saving writes the denoised image").isEqualTo(shown.frame().image());

            pressKey(robot, ui, java.awt.event.KeyEvent.VK_N);
            waitFor("Denoise off", 5, () -> !viewer.denoiser().enabled());
            waitFor("the noisy image again", 5, () -> !viewer.presenter().shown().denoised());
            waitFor("the status bar says nothing of denoising", 5, () -> !statusText(ui).contains("denoised"));
        } finally {
            viewer.close();
        }
    }

    /** A key typed on the window (through the X server, as a user would). */
    static void pressKey(Robot robot, ViewerFrame ui, int key) throws Exception {
        SwingUtilities.invokeAndWait(() -> {
            ui.frame.toFront();
            ui.image.requestFocusInWindow();
        });
        robot.waitForIdle();
        robot.keyPress(key);
        robot.keyRelease(key);
        robot.waitForIdle();
    }

    static String statusText(ViewerFrame ui) {
        try {
            return onEdt(ui.status::text);
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    /** Mean absolute difference of the luminance of horizontally neighbouring pixels, over the back wall. */
    static double roughness(dev.strahl.image.Image img) {
        double s = 0;
        int n = 0;
        for (int y = (int) (0.3 * img.height()); y < 0.6 * img.height(); y++) {
            for (int x = (int) (0.35 * img.width()); x < 0.65 * img.width(); x++) {
                s += Math.abs(lum(img, x + 1, y) - lum(img, x, y));
                n++;
            }
        }
        return s / n;
    }

    static double lum(dev.strahl.image.Image img, int x, int y) {
        return 0.2126 * img.get(x, y, 0) + 0.7152 * img.get(x, y, 1) + 0.0722 * img.get(x, y, 2);
    }

    /** Opens {@code file} from the window, waits for the error dialog, closes it and returns its message. */
    private static String errorDialogOnOpening(ViewerFrame ui, Path file) throws Exception {
        SwingUtilities.invokeLater(() -> ui.files.openScene(file));
        AtomicReference<JDialog> dialog = new AtomicReference<>();
        waitFor("the error dialog for " + file.getFileName(), 10, () -> {
            for (Window w : Window.getWindows()) {
                if (w instanceof JDialog d && d.isShowing()) {
                    dialog.set(d);
                }
            }
            return dialog.get() != null;
        });
        String message = onEdt(() -> String.valueOf(find(dialog.get(), JOptionPane.class).getMessage()));
        SwingUtilities.invokeAndWait(dialog.get()::dispose);
        return message;
    }

    private static Path scene(Path dir, String name, String settings) throws Exception {
        return Files.writeString(dir.resolve(name), "{ " + settings + " \"shapes\": [ { \"type\": \"mesh\", \"file\": \"cornell-box.obj\" } ] }");
    }

    static <T> T find(java.awt.Container root, Class<T> type) {
        for (java.awt.Component child : root.getComponents()) {
            if (type.isInstance(child)) {
                return type.cast(child);
            }
            if (child instanceof java.awt.Container inner) {
                T found = find(inner, type);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }

    /** Red wall on the left, green on the right, the light bright at the top centre. */
    static void assertShowsTheCornellBox(BufferedImage img) {
        int w = img.getWidth();
        int h = img.getHeight();
        double[] left = mean(img, (int) (0.07 * w), (int) (0.45 * h), (int) (0.05 * w), (int) (0.1 * h));
        double[] right = mean(img, (int) (0.88 * w), (int) (0.45 * h), (int) (0.05 * w), (int) (0.1 * h));
        double[] light = mean(img, (int) (0.47 * w), (int) (0.15 * h), (int) (0.06 * w), (int) (0.02 * h));
        double[] wall = mean(img, (int) (0.45 * w), (int) (0.45 * h), (int) (0.1 * w), (int) (0.1 * h));
        // Albedos (0.63, 0.065, 0.05) and (0.14, 0.45, 0.091): after the sRGB curve the dominant
        // channel is still about 2.8 and 1.7 times the others.
        assertThat(left[0]).as("left wall red: %s", Arrays.toString(left)).isGreaterThan(1.3 * left[1]).isGreaterThan(1.3 * left[2]).isGreaterThan(60);
        assertThat(right[1]).as("right wall green: %s", Arrays.toString(right)).isGreaterThan(1.3 * right[0]).isGreaterThan(1.3 * right[2]).isGreaterThan(60);
        assertThat(Math.min(light[0], Math.min(light[1], light[2]))).as("light white at the top: %s", Arrays.toString(light)).isGreaterThan(240);
        assertThat(light[0] + light[1] + light[2]).as("light brighter than the back wall")
                .isGreaterThan(1.5 * (wall[0] + wall[1] + wall[2]));
    }

    static double[] mean(BufferedImage img, int x0, int y0, int w, int h) {
        double[] m = new double[3];
        for (int y = y0; y < y0 + h; y++) {
            for (int x = x0; x < x0 + w; x++) {
                int rgb = img.getRGB(x, y);
                m[0] += (rgb >> 16) & 0xFF;
                m[1] += (rgb >> 8) & 0xFF;
                m[2] += rgb & 0xFF;
            }
        }
        for (int c = 0; c < 3; c++) {
            m[c] /= (double) w * h;
        }
        return m;
    }

    static double meanAbsDifference(BufferedImage a, BufferedImage b) {
        double s = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                int p = a.getRGB(x, y);
                int q = b.getRGB(x, y);
                for (int shift = 0; shift <= 16; shift += 8) {
                    s += Math.abs(((p >> shift) & 0xFF) - ((q >> shift) & 0xFF));
                }
            }
        }
        return s / (3.0 * a.getWidth() * a.getHeight());
    }

    /** The image area of the window as the screen shows it. */
    static BufferedImage capture(Robot robot, ViewerFrame ui) throws Exception {
        return robot.createScreenCapture(onEdt(() -> screenBounds(ui)));
    }

    static Rectangle screenBounds(ViewerFrame ui) {
        Rectangle r = ui.image.imageBounds();
        Point p = ui.image.getLocationOnScreen();
        return new Rectangle(p.x + r.x, p.y + r.y, r.width, r.height);
    }

    static int statusSpp(ViewerFrame ui) {
        String text;
        try {
            text = onEdt(ui.status::text);
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
        Matcher m = SPP.matcher(text);
        return m.find() ? Integer.parseInt(m.group(1)) : -1;
    }

    static RenderController.Frame last(List<RenderController.Frame> frames) {
        return frames.get(frames.size() - 1);
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

    static void waitFor(String what, int seconds, BooleanSupplier condition) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out after " + seconds + " s waiting for: " + what);
            }
            Thread.sleep(20);
        }
    }
}
