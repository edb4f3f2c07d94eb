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

    static Icon pause() {
        return of(g -> {
            g.fill(new RoundRectangle2D.Double(3.5, 2.5, 3, 11, 1, 1));
            g.fill(new RoundRectangle2D.Double(9.5, 2.5, 3, 11, 1, 1));
        });
    }

    static Icon resume() {
        return of(g -> {
            Path2D p = new Path2D.Double();
            p.moveTo(4, 2.5);
            p.lineTo(13.5, 8);
            p.lineTo(4, 13.5);
            p.closePath();
            g.fill(p);
        });
    }

    static Icon restart() {
        return of(g -> {
            g.draw(new Arc2D.Double(2.5, 2.5, 11, 11, 60, 280, Arc2D.OPEN));
            Path2D head = new Path2D.Double();
            head.moveTo(9.5, 0.8);
            head.lineTo(13.6, 3.2);
            head.lineTo(9.6, 6.2);
            head.closePath();
            g.fill(head);
        });
    }

    static Icon open() {
        return of(g -> {
            Path2D p = new Path2D.Double();
            p.moveTo(1.5, 13.5);
            p.lineTo(1.5, 3);
            p.lineTo(6, 3);
            p.lineTo(7.5, 4.5);
            p.lineTo(13, 4.5);
            p.lineTo(13, 6.5);
            g.draw(p);
            Path2D front = new Path2D.Double();
            front.moveTo(1.5, 13.5);
            front.lineTo(4, 7);
            front.lineTo(15, 7);
            front.lineTo(12.5, 13.5);
            front.closePath();
            g.draw(front);
        });
    }

    static Icon save() {
        return of(g -> {
            Path2D p = new Path2D.Double();
            p.moveTo(2, 2);
            p.lineTo(11.5, 2);
            p.lineTo(14, 4.5);
            p.lineTo(14, 14);
            p.lineTo(2, 14);
            p.closePath();
            g.draw(p);
            g.draw(new java.awt.geom.Rectangle2D.Double(5, 2, 5, 3.5));
            g.draw(new java.awt.geom.Rectangle2D.Double(4.5, 9, 7, 5));
        });
    }

    static Icon home() {
        return of(g -> {
            Path2D p = new Path2D.Double();
            p.moveTo(1.5, 8);
            p.lineTo(8, 2);
            p.lineTo(14.5, 8);
            g.draw(p);
            Path2D body = new Path2D.Double();
            body.moveTo(3.5, 7);
            body.lineTo(3.5, 14);
            body.lineTo(12.5, 14);
            body.lineTo(12.5, 7);
            g.draw(body);
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
