package dev.strahl.math;

/**
 * A linear RGB triple (Rec.709 primaries), immutable. Hot loops use {@link Mutable}, which
 * is reused per thread so that shading allocates nothing.
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

    /** A mutable RGB accumulator; methods return {@code this} for chaining. */
    public static final class Mutable {
        /** The components, public for the hot loops. */
        public double r, g, b;

        /** Black. */
        public Mutable() {}

        /**
         * A given colour.
         *
         * @param r red
         * @param g green
         * @param b blue
         */
        public Mutable(double r, double g, double b) {
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
        public Mutable set(double r, double g, double b) {
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
        public Mutable set(Rgb c) {
            return set(c.r(), c.g(), c.b());
        }

        /**
         * Copies another accumulator.
         *
         * @param c the colour
         * @return this
         */
        public Mutable set(Mutable c) {
            return set(c.r, c.g, c.b);
        }

        /**
         * Sets black.
         *
         * @return this
         */
        public Mutable setZero() {
            return set(0, 0, 0);
        }

        /**
         * Multiplies component-wise.
         *
         * @param c the factor
         * @return this
         */
        public Mutable mul(Mutable c) {
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
        public Mutable mul(Rgb c) {
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
        public Mutable mul(double s) {
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
        public Mutable addProduct(Mutable a, Rgb c, double s) {
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
        public Mutable addProduct(Mutable a, Mutable c, double s) {
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
}
