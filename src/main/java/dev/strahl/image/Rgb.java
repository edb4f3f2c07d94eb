package dev.strahl.image;

/**
 * A linear RGB triple (Rec.709 primaries), immutable.
 *
 * @param r red
 * @param g green
 * @param b blue
 */
public record Rgb(double r, double g, double b) {

    /** No light: (0, 0, 0). */
    public static final Rgb BLACK = new Rgb(0, 0, 0);
    /** (1, 1, 1). */
    public static final Rgb WHITE = new Rgb(1, 1, 1);

    /**
     * Checks that every component is finite.
     *
     * @param r red
     * @param g green
     * @param b blue
     */
    public Rgb {
        if (!Double.isFinite(r) || !Double.isFinite(g) || !Double.isFinite(b)) {
            throw new IllegalArgumentException("colour components must be finite, got " + r + ", " + g + ", " + b);
        }
    }

    /**
     * A grey.
     *
     * @param v the value of all three components
     * @return (v, v, v)
     */
    public static Rgb gray(double v) {
        return new Rgb(v, v, v);
    }

    /**
     * Whether all components are zero.
     *
     * @return true for black
     */
    public boolean isBlack() {
        return r == 0 && g == 0 && b == 0;
    }

    /**
     * The largest component.
     *
     * @return max(r, g, b)
     */
    public double max() {
        return Math.max(r, Math.max(g, b));
    }

    /**
     * Luminance with Rec.709 weights.
     *
     * @return 0.2126 r + 0.7152 g + 0.0722 b
     */
    public double luminance() {
        return 0.2126 * r + 0.7152 * g + 0.0722 * b;
    }

    /**
     * This colour times a factor.
     *
     * @param s the factor
     * @return (r·s, g·s, b·s)
     */
    public Rgb scale(double s) {
        return new Rgb(r * s, g * s, b * s);
    }

    /** "(r, g, b)", as a user would write the colour. */
    @Override
    public String toString() {
        return "(" + r + ", " + g + ", " + b + ")";
    }
}
