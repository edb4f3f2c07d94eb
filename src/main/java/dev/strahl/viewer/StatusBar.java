package dev.strahl.viewer;

import dev.strahl.render.IntegratorKind;
import dev.strahl.render.HemisphereSampling;
import java.awt.FlowLayout;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSeparator;
import javax.swing.SwingConstants;
import javax.swing.UIManager;

/**
 * The line under the image: state, samples per pixel, render time, samples per second, film
 * resolution, and the integrator with its max depth and sampling; with a noise threshold, the share of
 * pixels that met it; with View → Denoise on, whether the image shown is denoised and at how many
 * samples per pixel. Updated on the event dispatch thread by the viewer's timer.
 */
final class StatusBar extends JPanel {
    private final JLabel state = label("Starting");
    private final JLabel spp = label("0 spp");
    private final JLabel time = label("0:00.0");
    private final JLabel rate = label("–");
    private final JLabel size = label("");
    private final JLabel integrator = label("");
    private final JLabel noise = label("");
    private final JLabel denoise = label("");
    private final JSeparator denoiseSeparator;
    private final JSeparator noiseSeparator;

    StatusBar() {
        super(new FlowLayout(FlowLayout.LEADING, 8, 2));
        setBorder(BorderFactory.createMatteBorder(1, 0, 0, 0, UIManager.getColor("Separator.foreground")));
        JLabel[] parts = {state, spp, time, rate, size, integrator, noise, denoise};
        JSeparator[] before = new JSeparator[parts.length];
        for (int i = 0; i < parts.length; i++) {
            if (i > 0) {
                before[i] = new JSeparator(SwingConstants.VERTICAL) {
                    @Override
                    public java.awt.Dimension getPreferredSize() {
                        return new java.awt.Dimension(1, 14);
                    }
                };
                add(before[i]);
            }
            add(parts[i]);
        }
        noiseSeparator = before[6];
        denoiseSeparator = before[7];
        for (JComponent hidden : new JComponent[] {noise, noiseSeparator, denoise, denoiseSeparator}) {
            hidden.setVisible(false);
        }
        state.setToolTipText("Rendering, paused, done (reached the stop-at count) or previewing a camera move");
        spp.setToolTipText("Samples per pixel accumulated (and the stop-at count)");
        time.setToolTipText("Render time of this image, pauses excluded");
        rate.setToolTipText("Camera samples per second");
        size.setToolTipText("Film resolution in pixels");
        integrator.setToolTipText("Integrator, max depth and hemisphere sampling");
        noise.setToolTipText("Adaptive sampling: the noise threshold, and the share of pixels whose relative error met it (they take no more samples)");
        denoise.setToolTipText("View → Denoise (N): whether the image shown is denoised, and its samples per pixel");
    }

    private static JLabel label(String text) {
        return new JLabel(text);
    }

    void update(RenderController.Status s) {
        state.setText(stateText(s));
        spp.setText(sppText(s.samplesPerPixel(), s.stopAt()));
        time.setText(timeText(s.seconds()));
        rate.setText(rateText(s.samplesPerSecond()));
        size.setText(s.width() + " × " + s.height());
        integrator.setText(integratorText(s.integrator(), s.maxDepth(), s.hemisphere()));
        boolean adaptive = s.noiseThreshold() > 0 && !s.preview();
        noise.setText(adaptive ? noiseText(s.converged()) : "");
        noise.setVisible(adaptive);
        noiseSeparator.setVisible(adaptive);
    }

    /** With Denoise on, says whether the image {@code shown} is denoised; off, says nothing. */
    void showDenoise(boolean on, FramePresenter.Shown shown) {
        denoise.setText(on ? denoiseText(shown) : "");
        denoise.setVisible(on);
        denoiseSeparator.setVisible(on);
    }

    /** The whole line as text, as a user reads it. */
    String text() {
        StringBuilder b = new StringBuilder();
        for (JLabel l : new JLabel[] {state, spp, time, rate, size, integrator, noise, denoise}) {
            if (l.isVisible() && !l.getText().isEmpty()) {
                b.append(b.length() > 0 ? " | " : "").append(l.getText());
            }
        }
        return b.toString();
    }

    static String stateText(RenderController.Status s) {
        if (s.state() == RenderController.State.RUNNING && s.preview()) {
            return "Preview";
        }
        return switch (s.state()) {
            case RUNNING -> "Rendering";
            case PAUSED -> "Paused";
            case DONE -> s.ended() ? "Converged" : "Done";
            case CLOSED -> "Closed";
        };
    }

    /** "denoised, 16 spp" when the image shown is the denoiser's, else "not denoised yet" (previews never are). */
    static String denoiseText(FramePresenter.Shown shown) {
        if (shown != null && shown.denoised()) {
            return "denoised, " + shown.frame().samplesPerPixel() + " spp";
        }
        return shown != null && shown.frame().preview() ? "preview not denoised" : "not denoised yet";
    }

    /** "63.2 % converged" (never rounded up to all while a pixel is left); the threshold is in the toolbar. */
    static String noiseText(double converged) {
        return percent(Math.floor(converged * 1000) / 1000) + " converged";
    }

    /** 0.02 as "2 %", 0.005 as "0.5 %". */
    static String percent(double fraction) {
        String p = String.format(Locale.ROOT, "%.1f", fraction * 100);
        return (p.endsWith(".0") ? p.substring(0, p.length() - 2) : p) + " %";
    }

    static String sppText(int spp, int stopAt) {
        return stopAt == RenderController.UNLIMITED ? spp + " spp" : spp + " / " + stopAt + " spp";
    }

    static String timeText(double seconds) {
        long tenths = (long) Math.floor(seconds * 10);
        long minutes = tenths / 600;
        return String.format(Locale.ROOT, "%d:%02d.%d", minutes, (tenths / 10) % 60, tenths % 10);
    }

    static String rateText(double samplesPerSecond) {
        if (samplesPerSecond <= 0) {
            return "– samples/s";
        }
        if (samplesPerSecond >= 1e6) {
            return String.format(Locale.ROOT, "%.2f M samples/s", samplesPerSecond / 1e6);
        }
        return String.format(Locale.ROOT, "%.0f k samples/s", samplesPerSecond / 1e3);
    }

    static String integratorText(IntegratorKind integrator, int maxDepth, HemisphereSampling hemisphere) {
        return integrator.id() + " · depth " + depthText(maxDepth) + " · " + hemisphere.name().toLowerCase(Locale.ROOT);
    }

    static String depthText(int maxDepth) {
        return maxDepth < 0 ? "∞" : Integer.toString(maxDepth);
    }

    static String exposureText(double stops) {
        return String.format(Locale.ROOT, "EV %+.1f", stops);
    }
}
