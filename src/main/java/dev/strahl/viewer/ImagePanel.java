package dev.strahl.viewer;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.GraphicsConfiguration;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.geom.AffineTransform;
import java.awt.image.BufferedImage;
import java.util.function.BiConsumer;
import javax.swing.JComponent;

/**
 * Shows the newest converted frame, letterboxed: the film keeps the aspect ratio of the size the
 * scene asks for ({@link #setFilm}), and the largest rectangle of that aspect that fits the panel
 * is filled, centred, with bars of the panel's background colour around it. The film size
 * follows that rectangle in DEVICE pixels (the panel size times the screen's scale factor), so on
 * a HiDPI screen one film pixel is one screen pixel. Reduced-resolution previews are scaled up
 * (bilinear where the graphics pipeline honours the hint); full-resolution frames are drawn one
 * to one.
 */
final class ImagePanel extends JComponent {
    /** The neutral dark grey around the image, in both themes (as in image editors). */
    static final Color SURROUND = new Color(0x3a3a3a);
    /** How long a message ("Saved …") stays over the image. */
    static final int MESSAGE_MILLIS = 5000;
    private final FramePresenter presenter;
    private double aspect;
    private BiConsumer<Integer, Integer> onFilmSize = (w, h) -> { };
    private java.util.function.Consumer<FramePresenter.Shown> onPainted = s -> { };
    private String message = "";
    private final javax.swing.Timer messageTimer = new javax.swing.Timer(MESSAGE_MILLIS, e -> {
        message = "";
        repaint();
    });

    ImagePanel(FramePresenter presenter, int filmWidth, int filmHeight) {
        this.presenter = presenter;
        setFilm(filmWidth, filmHeight);
        setOpaque(true);
        setFocusable(true);
        presenter.onShown(this::repaint);        // repaint() is thread-safe and coalesced by Swing
        addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                reportFilmSize();
            }
        });
        addPropertyChangeListener("graphicsConfiguration", e -> reportFilmSize());   // moved to a screen of another scale
    }

    /**
     * The film size the scene asks for: from now on the film has its aspect, and the panel's
     * preferred size shows it at one film pixel per device pixel.
     */
    void setFilm(int filmWidth, int filmHeight) {
        aspect = (double) filmWidth / filmHeight;
        GraphicsConfiguration gc = getGraphicsConfiguration();
        if (gc == null && !GraphicsEnvironment.isHeadless()) {
            gc = GraphicsEnvironment.getLocalGraphicsEnvironment().getDefaultScreenDevice().getDefaultConfiguration();
        }
        double scale = scale(gc);
        setPreferredSize(new Dimension((int) Math.ceil(filmWidth / scale), (int) Math.ceil(filmHeight / scale)));
        repaint();
    }

    /** Tells {@code listener} the film size (device pixels) whenever the panel's size or screen changes. */
    void onFilmSize(BiConsumer<Integer, Integer> listener) {
        onFilmSize = listener;
    }

    /** Shows a short message over the bottom left of the image for a few seconds (event dispatch thread). */
    void showMessage(String text) {
        message = text;
        messageTimer.setRepeats(false);
        messageTimer.restart();
        repaint();
    }

    String message() {
        return message;
    }

    /** Tells {@code listener} (on the event dispatch thread) each time a frame has been painted. */
    void onPainted(java.util.function.Consumer<FramePresenter.Shown> listener) {
        onPainted = listener;
    }

    private void reportFilmSize() {
        Dimension film = filmSize();
        if (film != null) {
            onFilmSize.accept(film.width, film.height);
        }
    }

    /** The film size (device pixels) for the panel's size and the film's aspect; null while the panel has no size. */
    Dimension filmSize() {
        if (getWidth() <= 0 || getHeight() <= 0) {
            return null;
        }
        double s = scale(getGraphicsConfiguration());
        return fit((int) Math.round(getWidth() * s), (int) Math.round(getHeight() * s), aspect);
    }

    private static double scale(GraphicsConfiguration gc) {
        if (gc == null) {
            return 1;
        }
        AffineTransform t = gc.getDefaultTransform();
        return Math.max(1e-3, t.getScaleX());
    }

    /** The largest size of the given aspect (width / height) within {@code width} × {@code height}, at least 1×1. */
    static Dimension fit(int width, int height, double aspect) {
        if ((double) width / height > aspect) {
            return new Dimension(Math.max(1, (int) Math.round(height * aspect)), Math.max(1, height));
        }
        return new Dimension(Math.max(1, width), Math.max(1, (int) Math.round(width / aspect)));
    }

    /** Where the image goes in panel (user-space) coordinates. */
    Rectangle imageBounds() {
        Dimension d = fit(getWidth(), getHeight(), aspect);
        return new Rectangle((getWidth() - d.width) / 2, (getHeight() - d.height) / 2, d.width, d.height);
    }

    private void paintMessage(Graphics2D g2) {
        if (message.isEmpty()) {
            return;
        }
        g2.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g2.setFont(getFont() != null ? getFont() : g2.getFont());
        java.awt.FontMetrics fm = g2.getFontMetrics();
        int pad = 6;
        int w = fm.stringWidth(message) + 2 * pad;
        int h = fm.getHeight() + pad;
        int x = 8;
        int y = getHeight() - h - 8;
        g2.setColor(new Color(0, 0, 0, 170));
        g2.fillRoundRect(x, y, w, h, 8, 8);
        g2.setColor(Color.WHITE);
        g2.drawString(message, x + pad, y + pad / 2 + fm.getAscent());
    }

    @Override
    protected void paintComponent(Graphics g) {
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            g2.setColor(SURROUND);
            g2.fillRect(0, 0, getWidth(), getHeight());
            FramePresenter.Shown shown = presenter.shown();
            Rectangle r = imageBounds();
            if (shown == null) {
                g2.setColor(Color.BLACK);
                g2.fill(r);
                paintMessage(g2);
                return;
            }
            BufferedImage img = shown.image();
            double deviceWidth = r.width * g2.getTransform().getScaleX();
            boolean oneToOne = Math.abs(deviceWidth - img.getWidth()) < 0.5;
            g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, oneToOne
                    ? RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR : RenderingHints.VALUE_INTERPOLATION_BILINEAR);
            g2.drawImage(img, r.x, r.y, r.width, r.height, null);
            onPainted.accept(shown);
            paintMessage(g2);
        } finally {
            g2.dispose();
        }
    }
}
