package dev.strahl.texture;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;

/**
 * A texture as the BSDFs read it (the API's {@code dev.strahl.scene.Texture} describes one; its
 * {@code colour()}, {@code scalar()} and {@code data()} make this): a BSDF parameter over the surface, a colour ({@link #rgb}) or a number ({@link #value}) at texture
 * coordinates (u, v): a constant, an image, or one of them times a factor ({@link ScaledTexture}).
 * Immutable and shared between threads; lookups allocate nothing.
 */
public sealed interface TextureLookup permits ConstantTexture, ImageTexture, ScaledTexture {

    /** The linear RGB value at (u, v), into {@code dest}. */
    void rgb(double u, double v, MutableRgb dest);

    /** The scalar value at (u, v): a constant's number, an image's {@link Channel}. */
    double value(double u, double v);

    /** Whether the value is the same everywhere (a constant). */
    boolean isConstant();

    /** The mean colour over the texture (for lobe-selection weights and reports). */
    Rgb mean();

    /** The image behind the texture, or null for a constant. */
    default Bitmap bitmap() {
        return null;
    }

    /** A constant colour; its scalar value is the colour's mean. */
    static TextureLookup of(Rgb colour) {
        return new ConstantTexture(colour, (colour.r() + colour.g() + colour.b()) / 3);
    }

    /** A constant number (its colour is grey). */
    static TextureLookup of(double value) {
        return new ConstantTexture(Rgb.gray(value), value);
    }
}
