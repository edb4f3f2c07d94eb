package dev.strahl.math;

/**
 * A linear RGB triple (Rec.709 primaries), immutable. Hot loops use {@link Mutable}, which
 * is reused per thread so that shading allocates nothing.
 */
public record Rgb(double r, double g, double b) {

    public static final Rgb BLACK = new Rgb(0, 0, 0);
    public static final Rgb WHITE = new Rgb(1, 1, 1);

    public Rgb {
        if (!Double.isFinite(r) || !Double.isFinite(g) || !Double.isFinite(b)) {
            throw new IllegalArgumentException("colour components must be finite, got " + r + ", " + g + ", " + b);
        }
    }

    public static Rgb gray(double v) {
        return new Rgb(v, v, v);
    }

    public boolean isBlack() {
        return r == 0 && g == 0 && b == 0;
    }

    public double max() {
        return Math.max(r, Math.max(g, b));
    }

    /** Luminance with Rec.709 weights. */
    public double luminance() {
        return 0.2126 * r + 0.7152 * g + 0.0722 * b;
    }

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
        public double r, g, b;

        public Mutable() {}

        public Mutable(double r, double g, double b) {
            set(r, g, b);
        }

        public Mutable set(double r, double g, double b) {
            this.r = r;
            this.g = g;
            this.b = b;
            return this;
        }

        public Mutable set(Rgb c) {
            return set(c.r(), c.g(), c.b());
        }

        public Mutable set(Mutable c) {
            return set(c.r, c.g, c.b);
        }

        public Mutable setZero() {
            return set(0, 0, 0);
        }

        public Mutable mul(Mutable c) {
            r *= c.r;
            g *= c.g;
            b *= c.b;
            return this;
        }

        public Mutable mul(Rgb c) {
            r *= c.r();
            g *= c.g();
            b *= c.b();
            return this;
        }

        public Mutable mul(double s) {
            r *= s;
            g *= s;
            b *= s;
            return this;
        }

        /** this += a * b * s, component-wise. */
        public Mutable addProduct(Mutable a, Rgb c, double s) {
            r += a.r * c.r() * s;
            g += a.g * c.g() * s;
            b += a.b * c.b() * s;
            return this;
        }

        /** this += a * c * s, component-wise. */
        public Mutable addProduct(Mutable a, Mutable c, double s) {
            r += a.r * c.r * s;
            g += a.g * c.g * s;
            b += a.b * c.b * s;
            return this;
        }

        public double max() {
            return Math.max(r, Math.max(g, b));
        }

        public boolean isBlack() {
            return r == 0 && g == 0 && b == 0;
        }

        public boolean isFinite() {
            return Double.isFinite(r) && Double.isFinite(g) && Double.isFinite(b);
        }

        public Rgb toRgb() {
            return new Rgb(r, g, b);
        }

        @Override
        public String toString() {
            return "(" + r + ", " + g + ", " + b + ")";
        }
    }
}
