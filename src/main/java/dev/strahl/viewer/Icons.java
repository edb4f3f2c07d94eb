package dev.strahl.viewer;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Component;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Arc2D;
import java.awt.geom.Path2D;
import java.awt.geom.RoundRectangle2D;
import java.util.function.Consumer;
import javax.swing.Icon;
import javax.swing.UIManager;

/**
 * The toolbar's icons, drawn as vector shapes in the theme's text colour: sharp at any HiDPI
 * scale, right in light and dark themes, and no image files to ship.
 */
final class Icons {
    static final int SIZE = 16;

    private Icons() {
    }

    /** An icon painted by {@code shape} on a 16×16 grid with a 1.5-unit pen. */
    private static Icon of(Consumer<Graphics2D> shape) {
        return new Icon() {
            @Override
            public void paintIcon(Component c, Graphics g, int x, int y) {
                Graphics2D g2 = (Graphics2D) g.create();
                try {
                    g2.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
                    g2.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
                    Color color = UIManager.getColor(c != null && !c.isEnabled() ? "Label.disabledForeground" : "Label.foreground");
                    g2.setColor(color != null ? color : Color.DARK_GRAY);
                    g2.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
                    g2.translate(x, y);
                    shape.accept(g2);
                } finally {
                    g2.dispose();
                }
            }

            @Override
            public int getIconWidth() {
                return SIZE;
            }

            @Override
            public int getIconHeight() {
                return SIZE;
            }
        };
    }

    /** The open path through the points (x0, y0, x1, y1, ...). */
    private static Path2D polyline(double... xy) {
        Path2D p = new Path2D.Double();
        p.moveTo(xy[0], xy[1]);
        for (int i = 2; i < xy.length; i += 2) {
            p.lineTo(xy[i], xy[i + 1]);
        }
        return p;
    }

    /** The closed path through the points (x0, y0, x1, y1, ...). */
    private static Path2D polygon(double... xy) {
        Path2D p = polyline(xy);
        p.closePath();
        return p;
    }

    static Icon pause() {
        return of(g -> {
            g.fill(new RoundRectangle2D.Double(3.5, 2.5, 3, 11, 1, 1));
            g.fill(new RoundRectangle2D.Double(9.5, 2.5, 3, 11, 1, 1));
        });
    }

    static Icon resume() {
        return of(g -> {
            g.fill(polygon(4, 2.5, 13.5, 8, 4, 13.5));
        });
    }

    static Icon restart() {
        return of(g -> {
            g.draw(new Arc2D.Double(2.5, 2.5, 11, 11, 60, 280, Arc2D.OPEN));
            g.fill(polygon(9.5, 0.8, 13.6, 3.2, 9.6, 6.2));
        });
    }

    static Icon open() {
        return of(g -> {
            g.draw(polyline(1.5, 13.5, 1.5, 3, 6, 3, 7.5, 4.5, 13, 4.5, 13, 6.5));
            g.draw(polygon(1.5, 13.5, 4, 7, 15, 7, 12.5, 13.5));
        });
    }

    static Icon save() {
        return of(g -> {
            g.draw(polygon(2, 2, 11.5, 2, 14, 4.5, 14, 14, 2, 14));
            g.draw(new java.awt.geom.Rectangle2D.Double(5, 2, 5, 3.5));
            g.draw(new java.awt.geom.Rectangle2D.Double(4.5, 9, 7, 5));
        });
    }

    static Icon home() {
        return of(g -> {
            g.draw(polyline(1.5, 8, 8, 2, 14.5, 8));
            g.draw(polyline(3.5, 7, 3.5, 14, 12.5, 14, 12.5, 7));
            g.draw(new java.awt.geom.Rectangle2D.Double(6.5, 9.5, 3, 4.5));
        });
    }

    static Icon darker() {
        return of(g -> {
            g.draw(new java.awt.geom.Ellipse2D.Double(2, 2, 12, 12));
            g.draw(new java.awt.geom.Line2D.Double(5, 8, 11, 8));
        });
    }

    static Icon brighter() {
        return of(g -> {
            g.draw(new java.awt.geom.Ellipse2D.Double(2, 2, 12, 12));
            g.draw(new java.awt.geom.Line2D.Double(5, 8, 11, 8));
            g.draw(new java.awt.geom.Line2D.Double(8, 5, 8, 11));
        });
    }
}
