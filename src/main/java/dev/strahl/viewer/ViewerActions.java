package dev.strahl.viewer;

import dev.strahl.render.IntegratorKind;
import dev.strahl.render.HemisphereSampling;
import java.awt.event.ActionEvent;
import java.awt.event.ActionListener;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import javax.swing.AbstractAction;
import javax.swing.AbstractButton;
import javax.swing.Action;
import javax.swing.Icon;
import javax.swing.InputMap;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JRootPane;
import javax.swing.JToggleButton;
import javax.swing.JToolBar;
import javax.swing.KeyStroke;

/**
 * Every command of the viewer as a Swing {@link Action} (name, icon, tooltip with its shortcut,
 * accelerator), and the menu bar and toolbar built from them: each control exists once and shows
 * in both places, in step.
 */
final class ViewerActions {
    static final List<Integer> STOP_AT = List.of(16, 64, 256, 1024, 4096, RenderController.UNLIMITED);
    static final List<Integer> DEPTHS = List.of(-1, 1, 2, 3, 4, 5, 8, 16);
    static final double EXPOSURE_STEP = 0.5;
    /** Depths in the menus: unbounded (−1) first, then ascending. */
    static final Comparator<Integer> DEPTH_ORDER = Comparator.comparingInt(d -> d < 0 ? Integer.MIN_VALUE : d);
    /** Stop-at counts ascending, "never" (0) last. */
    static final Comparator<Integer> STOP_AT_ORDER = Comparator.comparingInt(n -> n <= 0 ? Integer.MAX_VALUE : n);

    private final RenderController controller;
    private final FramePresenter presenter;
    private final LiveDenoiser denoiser;
    private final FileActions files;
    private final JRootPane root;

    final Action pause;
    final Action restart;
    final Action resetCamera;
    final Action brighter;
    final Action darker;
    final Action normalExposure;
    /** View → Denoise, a check box: its {@link Action#SELECTED_KEY} is the state. */
    final Action denoise;
    /** View → Noise, a check box: the heat map of the remaining relative error instead of the image. */
    final Action noiseView;
    /** The noise threshold of adaptive sampling (0: off). */
    final Choice<Double> noiseThreshold;
    final Action controls;
    final Action quit;
    final Choice<IntegratorKind> integrator;
    final Choice<Integer> maxDepth;
    final Choice<HemisphereSampling> hemisphere;
    final Choice<Integer> stopAt;
    private final JLabel exposureLabel = new JLabel(StatusBar.exposureText(0));

    ViewerActions(RenderController controller, FramePresenter presenter, LiveDenoiser denoiser, FileActions files, JRootPane root,
                  Runnable onQuit) {
        this.controller = controller;
        this.presenter = presenter;
        this.denoiser = denoiser;
        this.files = files;
        this.root = root;
        pause = action("Pause", Icons.pause(), "Pause or resume rendering; the samples so far are kept",
                KeyStroke.getKeyStroke(KeyEvent.VK_SPACE, 0), e -> controller.togglePause());
        restart = action("Restart", Icons.restart(), "Throw the samples away and render again",
                KeyStroke.getKeyStroke(KeyEvent.VK_R, 0), e -> controller.restart());
        resetCamera = action("Reset camera", Icons.home(), "Back to the scene's camera",
                KeyStroke.getKeyStroke(KeyEvent.VK_HOME, 0), e -> controller.resetCamera());
        brighter = action("Brighter", Icons.brighter(), "Display exposure +½ stop (display only, keeps rendering)",
                KeyStroke.getKeyStroke(KeyEvent.VK_EQUALS, 0), e -> exposureBy(EXPOSURE_STEP));
        darker = action("Darker", Icons.darker(), "Display exposure −½ stop (display only, keeps rendering)",
                KeyStroke.getKeyStroke(KeyEvent.VK_MINUS, 0), e -> exposureBy(-EXPOSURE_STEP));
        normalExposure = action("Normal exposure", null, "Display exposure back to 0",
                KeyStroke.getKeyStroke(KeyEvent.VK_0, 0), e -> presenter.setExposure(0));
        denoise = action("Denoise", null, "Show the render denoised as it goes on (restarts it once if it lacks the albedo,"
                + " normal and depth buffers)", KeyStroke.getKeyStroke(KeyEvent.VK_N, 0),
                e -> setDenoise(denoiseChecked()));
        denoise.putValue(Action.SELECTED_KEY, false);
        noiseView = action("Noise", null, "Show a heat map of each pixel's remaining relative error: blue to cyan has met the noise"
                + " threshold (or 1 % without one), yellow to red has not", KeyStroke.getKeyStroke(KeyEvent.VK_E, 0), e -> showNoise());
        noiseView.putValue(Action.SELECTED_KEY, false);
        controls = action("Controls", null, "Mouse and keyboard controls", KeyStroke.getKeyStroke(KeyEvent.VK_F1, 0),
                e -> JOptionPane.showMessageDialog(root, CONTROLS, "strahl viewer: controls", JOptionPane.PLAIN_MESSAGE));
        quit = action("Quit", null, "Close the viewer", KeyStroke.getKeyStroke(KeyEvent.VK_Q, menuMask()), e -> onQuit.run());

        integrator = new Choice<>(List.of(IntegratorKind.values()), controller.settings().transport().integrator(), null, IntegratorKind::id,
                i -> controller.change(s -> s.withIntegrator(i)));
        maxDepth = new Choice<>(DEPTHS, controller.settings().transport().maxDepth(), DEPTH_ORDER, StatusBar::depthText,
                d -> controller.change(s -> s.withMaxDepth(d)));
        hemisphere = new Choice<>(List.of(HemisphereSampling.values()), controller.settings().transport().hemisphere(), null,
                h -> h.name().toLowerCase(Locale.ROOT), h -> controller.change(s -> s.withHemisphere(h)));
        stopAt = new Choice<>(STOP_AT, controller.stopAt(), STOP_AT_ORDER,
                n -> n == RenderController.UNLIMITED ? "never" : n + " spp", controller::setStopAt);
        noiseThreshold = new Choice<>(THRESHOLDS, controller.settings().sampling().noiseThreshold(), THRESHOLD_ORDER,
                t -> t == 0 ? "off" : StatusBar.percent(t), t -> {
                    controller.change(s -> s.withNoiseThreshold(t));
                    showNoise();
                });
    }

    /** Noise thresholds offered, "off" first, then tighter and tighter. */
    static final List<Double> THRESHOLDS = List.of(0.0, 0.1, 0.05, 0.02, 0.01, 0.005);
    static final Comparator<Double> THRESHOLD_ORDER = Comparator.comparingDouble(t -> t == 0 ? Double.MAX_VALUE : -t);

    /** Shows the heat map (View → Noise) against the threshold in use, or the image. */
    private void showNoise() {
        double t = controller.settings().sampling().noiseThreshold();
        presenter.setNoiseView(Boolean.TRUE.equals(noiseView.getValue(Action.SELECTED_KEY)) ? (t > 0 ? t : NoiseHeatMap.DEFAULT_SCALE) : 0);
    }

    private static final String CONTROLS = """
            <html><table cellpadding=2>
            <tr><td><b>Left drag</b></td><td>orbit around the target</td></tr>
            <tr><td><b>Right / middle drag, Shift + left drag</b></td><td>pan</td></tr>
            <tr><td><b>Wheel</b></td><td>dolly (move closer or away)</td></tr>
            <tr><td><b>Space</b></td><td>pause / resume</td></tr>
            <tr><td><b>R</b></td><td>restart</td></tr>
            <tr><td><b>Home</b></td><td>reset camera</td></tr>
            <tr><td><b>I</b></td><td>next integrator</td></tr>
            <tr><td><b>D / Shift+D</b></td><td>next / previous max depth</td></tr>
            <tr><td><b>H</b></td><td>cosine / uniform hemisphere sampling</td></tr>
            <tr><td><b>T / Shift+T</b></td><td>next / previous stop-at count</td></tr>
            <tr><td><b>+ / − / 0</b></td><td>exposure up / down / back to 0 (display only)</td></tr>
            <tr><td><b>N</b></td><td>denoise on / off</td></tr>
            <tr><td><b>E</b></td><td>noise heat map on / off</td></tr>
            <tr><td><b>Ctrl+O / Ctrl+S / Ctrl+Q</b></td><td>open scene / save image / quit</td></tr>
            </table></html>""";

    /** The modifier of menu shortcuts: Ctrl, or Cmd on macOS. */
    static int menuMask() {
        try {
            return java.awt.Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();
        } catch (java.awt.HeadlessException e) {
            return InputEvent.CTRL_DOWN_MASK;
        }
    }

    /** An action with its tooltip ending in the shortcut, e.g. "Restart (R)". */
    static Action action(String name, Icon icon, String tooltip, KeyStroke key, ActionListener listener) {
        Action a = new AbstractAction(name, icon) {
            @Override
            public void actionPerformed(ActionEvent e) {
                listener.actionPerformed(e);
            }
        };
        a.putValue(Action.ACCELERATOR_KEY, key);
        a.putValue(Action.SHORT_DESCRIPTION, tooltip + " (" + keyText(key) + ")");
        return a;
    }

    static String keyText(KeyStroke key) {
        String mods = InputEvent.getModifiersExText(key.getModifiers());
        String k = KeyEvent.getKeyText(key.getKeyCode());
        if (key.getKeyCode() == KeyEvent.VK_EQUALS) {
            k = "+";
        }
        return mods.isEmpty() ? k : mods + "+" + k;
    }

    /**
     * Turns View → Denoise on or off. On, every full-resolution job keeps the denoiser's guides
     * (albedo, normal, depth); a render without them starts again with them (its samples are lost),
     * one that has them goes on and its last frame is denoised if it can still be. Off, the
     * buffers stay until a scene is opened; the noisy frames are shown again at once.
     */
    void setDenoise(boolean on) {
        denoise.putValue(Action.SELECTED_KEY, on);
        boolean restart = on && !controller.settings().output().aovs().containsAll(LiveDenoiser.GUIDES);
        if (restart) {
            controller.setAovs(LiveDenoiser.withGuides(controller.settings().output().aovs()));
        }
        denoiser.setEnabled(on, !restart);
    }

    /** The check box's state (the menu item or the toolbar button changes it before its action runs). */
    private boolean denoiseChecked() {
        return Boolean.TRUE.equals(denoise.getValue(Action.SELECTED_KEY));
    }

    private void exposureBy(double stops) {
        presenter.setExposure(presenter.exposure() + stops);
    }

    /**
     * Shows "Pause" or "Resume" as the state requires, the exposure, and the settings in use
     * (which opening a scene may have changed).
     */
    void refresh(RenderController.Status s) {
        integrator.show(s.integrator());
        maxDepth.show(s.maxDepth());
        hemisphere.show(s.hemisphere());
        exposureLabel.setText(StatusBar.exposureText(presenter.exposure()));
        boolean paused = s.state() == RenderController.State.PAUSED;
        pause.setEnabled(s.state() != RenderController.State.DONE);   // raise the stop-at count to go on
        String name = paused ? "Resume" : "Pause";
        if (!name.equals(pause.getValue(Action.NAME))) {
            pause.putValue(Action.NAME, name);
            pause.putValue(Action.SMALL_ICON, paused ? Icons.resume() : Icons.pause());
        }
    }

    JMenuBar menuBar() {
        JMenuBar bar = new JMenuBar();
        JMenu file = new JMenu("File");
        file.setMnemonic(KeyEvent.VK_F);
        file.add(item(files.open));
        file.add(files.recentMenu());
        file.add(item(files.save));
        file.addSeparator();
        file.add(item(quit));
        bar.add(file);

        JMenu render = new JMenu("Render");
        render.setMnemonic(KeyEvent.VK_R);
        render.add(item(pause));
        render.add(item(restart));
        render.addSeparator();
        render.add(tip(integrator.menu("Integrator", KeyEvent.VK_I), "I cycles through the integrators"));
        render.add(tip(maxDepth.menu("Max depth", KeyEvent.VK_D), "D / Shift+D: next / previous max depth"));
        render.add(tip(hemisphere.menu("Hemisphere sampling", KeyEvent.VK_H), "H switches between cosine and uniform"));
        render.add(tip(stopAt.menu("Stop at", KeyEvent.VK_S), "T / Shift+T: next / previous stop-at count"));
        render.add(tip(noiseThreshold.menu("Noise threshold", KeyEvent.VK_N), "Adaptive sampling: each pixel renders until its relative"
                + " error meets it"));
        bar.add(render);

        JMenu view = new JMenu("View");
        view.setMnemonic(KeyEvent.VK_V);
        view.add(item(resetCamera));
        view.addSeparator();
        view.add(item(brighter));
        view.add(item(darker));
        view.add(item(normalExposure));
        view.add(ToneMenu.menu(presenter));
        view.addSeparator();
        JCheckBoxMenuItem denoiseItem = new JCheckBoxMenuItem(denoise);
        denoiseItem.setToolTipText(null);
        view.add(denoiseItem);
        JCheckBoxMenuItem noiseItem = new JCheckBoxMenuItem(noiseView);
        noiseItem.setToolTipText(null);
        view.add(noiseItem);
        bar.add(view);

        JMenu help = new JMenu("Help");
        help.setMnemonic(KeyEvent.VK_H);
        help.add(item(controls));
        bar.add(help);

        // Keys without a menu item of their own: keypad +/−/0, F5, and cycling through the choices.
        InputMap keys = root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW);
        bindExtra(keys, KeyStroke.getKeyStroke(KeyEvent.VK_ADD, 0), "brighter", brighter);
        bindExtra(keys, KeyStroke.getKeyStroke(KeyEvent.VK_PLUS, 0), "brighter", brighter);
        bindExtra(keys, KeyStroke.getKeyStroke(KeyEvent.VK_EQUALS, InputEvent.SHIFT_DOWN_MASK), "brighter", brighter);
        bindExtra(keys, KeyStroke.getKeyStroke(KeyEvent.VK_SUBTRACT, 0), "darker", darker);
        bindExtra(keys, KeyStroke.getKeyStroke(KeyEvent.VK_NUMPAD0, 0), "normalExposure", normalExposure);
        bindExtra(keys, KeyStroke.getKeyStroke(KeyEvent.VK_F5, 0), "restart", restart);
        bindCycle(keys, integrator, KeyEvent.VK_I, 0, 1);
        bindCycle(keys, maxDepth, KeyEvent.VK_D, 0, 1);
        bindCycle(keys, maxDepth, KeyEvent.VK_D, InputEvent.SHIFT_DOWN_MASK, -1);
        bindCycle(keys, hemisphere, KeyEvent.VK_H, 0, 1);
        bindCycle(keys, stopAt, KeyEvent.VK_T, 0, 1);
        bindCycle(keys, stopAt, KeyEvent.VK_T, InputEvent.SHIFT_DOWN_MASK, -1);
        return bar;
    }

    private void bindExtra(InputMap keys, KeyStroke key, String name, Action action) {
        keys.put(key, name);
        root.getActionMap().put(name, action);
    }

    private <T> void bindCycle(InputMap keys, Choice<T> choice, int keyCode, int modifiers, int step) {
        KeyStroke key = KeyStroke.getKeyStroke(keyCode, modifiers);
        String name = "cycle-" + keyText(key);
        bindExtra(keys, key, name, choice.cycle(name, name, key, step));
    }

    private static JMenu tip(JMenu menu, String tooltip) {
        menu.setToolTipText(tooltip);
        return menu;
    }

    private static JMenuItem item(Action a) {
        JMenuItem item = new JMenuItem(a);
        item.setToolTipText(null);           // menus show the accelerator already
        return item;
    }

    JToolBar toolBar() {
        JToolBar bar = new JToolBar();
        bar.setFloatable(false);
        bar.add(button(files.open));
        bar.add(button(files.save));
        bar.addSeparator();
        bar.add(button(pause));
        bar.add(button(restart));
        bar.add(button(resetCamera));
        bar.addSeparator();
        bar.add(integrator.comboBox("", "Integrator (I)"));
        bar.add(maxDepth.comboBox("depth ", "Max depth: path segments including the camera segment (D, Shift+D)"));
        bar.add(hemisphere.comboBox("", "Hemisphere sampling of diffuse bounces: cosine or uniform (H)"));
        bar.add(stopAt.comboBox("stop at ", "Hold rendering at this many samples per pixel (T, Shift+T)"));
        bar.add(noiseThreshold.comboBox("noise ", "Adaptive sampling: samples go where the noise is, and a pixel stops once the relative"
                + " standard error of it and its neighbours is at most this (off: every pixel alike)"));
        bar.addSeparator();
        bar.add(button(darker));
        exposureLabel.setToolTipText("Display exposure in stops: display only, rendering goes on (+, −, 0)");
        bar.add(exposureLabel);
        bar.add(button(brighter));
        bar.addSeparator();
        JToggleButton denoiseButton = new JToggleButton(denoise);
        denoiseButton.setFocusable(false);
        bar.add(denoiseButton);
        return bar;
    }

    private static AbstractButton button(Action a) {
        javax.swing.JButton b = new javax.swing.JButton(a);
        b.setHideActionText(true);
        b.setFocusable(false);
        return b;
    }
}
