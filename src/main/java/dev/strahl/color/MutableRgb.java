package dev.strahl.color;

import dev.strahl.image.Rgb;

/** A mutable RGB accumulator; methods return {@code this} for chaining. */
public final class MutableRgb {
    /** The components, public for the hot loops. */
    public double r, g, b;

    /** Black. */
    public MutableRgb() {}

    /**
     * A given colour.
     *
     * @param r red
     * @param g green
     * @param b blue
     */
    public MutableRgb(double r, double g, double b) {
        set(r, g, b);
    }

    /**
     * Sets all components.
     *
     * @param r red
     * @param g green
     * @param b blue
     * @return this
     */
    public MutableRgb set(double r, double g, double b) {
        this.r = r;
        this.g = g;
        this.b = b;
        return this;
    }

    /**
     * Copies an immutable colour.
     *
     * @param c the colour
     * @return this
     */
    public MutableRgb set(Rgb c) {
        return set(c.r(), c.g(), c.b());
    }

    /**
     * Copies another accumulator.
     *
     * @param c the colour
     * @return this
     */
    public MutableRgb set(MutableRgb c) {
        return set(c.r, c.g, c.b);
    }

    /**
     * Sets black.
     *
     * @return this
     */
    public MutableRgb setZero() {
        return set(0, 0, 0);
    }

    /**
     * Multiplies component-wise.
     *
     * @param c the factor
     * @return this
     */
    public MutableRgb mul(MutableRgb c) {
        r *= c.r;
        g *= c.g;
        b *= c.b;
        return this;
    }

    /**
     * Multiplies component-wise.
     *
     * @param c the factor
     * @return this
     */
    public MutableRgb mul(Rgb c) {
        r *= c.r();
        g *= c.g();
        b *= c.b();
        return this;
    }

    /**
     * Multiplies every component.
     *
     * @param s the factor
     * @return this
     */
    public MutableRgb mul(double s) {
        r *= s;
        g *= s;
        b *= s;
        return this;
    }

    /**
     * this += a * c * s, component-wise.
     *
     * @param a first factor
     * @param c second factor
     * @param s scalar factor
     * @return this
     */
    public MutableRgb addProduct(MutableRgb a, Rgb c, double s) {
        r += a.r * c.r() * s;
        g += a.g * c.g() * s;
        b += a.b * c.b() * s;
        return this;
    }

    /**
     * this += a * c * s, component-wise.
     *
     * @param a first factor
     * @param c second factor
     * @param s scalar factor
     * @return this
     */
    public MutableRgb addProduct(MutableRgb a, MutableRgb c, double s) {
        r += a.r * c.r * s;
        g += a.g * c.g * s;
        b += a.b * c.b * s;
        return this;
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
     * Whether all components are zero.
     *
     * @return true for black
     */
    public boolean isBlack() {
        return r == 0 && g == 0 && b == 0;
    }

    /**
     * Whether no component is NaN or infinite.
     *
     * @return true if all are finite
     */
    public boolean isFinite() {
        return Double.isFinite(r) && Double.isFinite(g) && Double.isFinite(b);
    }

    /**
     * An immutable copy.
     *
     * @return the colour
     */
    public Rgb toRgb() {
        return new Rgb(r, g, b);
    }

    @Override
    public String toString() {
        return "(" + r + ", " + g + ", " + b + ")";
    }
}
