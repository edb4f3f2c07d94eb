package dev.strahl.viewer;

import java.awt.Cursor;
import java.awt.Point;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;

/**
 * Mouse navigation on the image: drag with the left button to orbit around the target, with the
 * right or middle button (or Shift + left) to pan, turn the wheel to dolly; Ctrl + click focuses
 * the thin lens on the surface under the cursor. A drag across the
 * image's full height turns the camera by 180°; panning keeps the point under the cursor at the
 * target's depth under the cursor; each wheel notch changes the distance by 10 %.
 */
final class CameraMouse extends MouseAdapter {
    static final double DOLLY_PER_NOTCH = 1.1;

    private final JComponent panel;
    private final RenderController controller;
    private Point last;
    private boolean panning;

    private CameraMouse(JComponent panel, RenderController controller) {
        this.panel = panel;
        this.controller = controller;
    }

    static void attach(ImagePanel panel, RenderController controller) {
        CameraMouse m = new CameraMouse(panel, controller);
        panel.addMouseListener(m);
        panel.addMouseMotionListener(m);
        panel.addMouseWheelListener(m);
    }

    @Override
    public void mousePressed(MouseEvent e) {
        panel.requestFocusInWindow();
        last = e.getPoint();
        panning = !SwingUtilities.isLeftMouseButton(e) || e.isShiftDown();
        panel.setCursor(Cursor.getPredefinedCursor(panning ? Cursor.MOVE_CURSOR : Cursor.HAND_CURSOR));
    }

    @Override
    public void mouseClicked(MouseEvent e) {
        if (SwingUtilities.isLeftMouseButton(e) && e.isControlDown()) {
            java.awt.Rectangle r = ((ImagePanel) panel).imageBounds();
            if (r.width > 0 && r.height > 0 && r.contains(e.getPoint())) {
                controller.focusAt((e.getX() - r.x + 0.5) / r.width, (e.getY() - r.y + 0.5) / r.height);
            }
        }
    }

    @Override
    public void mouseReleased(MouseEvent e) {
        last = null;
        panel.setCursor(Cursor.getDefaultCursor());
    }

    @Override
    public void mouseDragged(MouseEvent e) {
        if (last == null) {
            return;
        }
        int dx = e.getX() - last.x;
        int dy = e.getY() - last.y;
        last = e.getPoint();
        if (dx == 0 && dy == 0) {
            return;
        }
        double h = Math.max(1, ((ImagePanel) panel).imageBounds().height);
        if (panning) {
            controller.moveCamera(c -> c.pan(-dx / h, dy / h));
        } else {
            controller.moveCamera(c -> c.orbit(-Math.PI * dx / h, Math.PI * dy / h));
        }
    }

    @Override
    public void mouseWheelMoved(MouseWheelEvent e) {
        double notches = e.getPreciseWheelRotation();
        if (notches != 0) {
            controller.moveCamera(c -> c.dolly(Math.pow(DOLLY_PER_NOTCH, notches)));
        }
    }
}
