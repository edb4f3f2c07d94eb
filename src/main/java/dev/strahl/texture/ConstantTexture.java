package dev.strahl.texture;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import java.util.Objects;

/**
 * The same colour and number everywhere: what every untextured BSDF parameter is.
 *
 * @param colour the colour, linear RGB
 * @param number the scalar value
 */
public record ConstantTexture(Rgb colour, double number) implements TextureLookup {

    /** Checks that the colour is given and the number finite. */
    public ConstantTexture {
        Objects.requireNonNull(colour, "colour");
        if (!Double.isFinite(number)) {
            throw new IllegalArgumentException("a constant texture needs a finite value, got " + number);
        }
    }

    @Override
    public void rgb(double u, double v, MutableRgb dest) {
        dest.set(colour);
    }

    @Override
    public double value(double u, double v) {
        return number;
    }

    @Override
    public boolean isConstant() {
        return true;
    }

    @Override
    public Rgb mean() {
        return colour;
    }

    @Override
    public String toString() {
        return colour.r() == colour.g() && colour.g() == colour.b() && colour.r() == number ? Double.toString(number) : colour.toString();
    }
}
