package dev.strahl.texture;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import java.util.Objects;

/**
 * A texture times a factor, as glTF multiplies every texture by its factor (baseColorFactor ×
 * baseColorTexture, metallicFactor × the B channel, …): the colour is colourFactor ⊙ texture(u, v)
 * channel by channel, the number valueFactor × texture's value(u, v). The two factors are chosen
 * together by whoever reads the texture ({@code dev.strahl.scene.Texture}): the factor of the
 * channel a number is read from, or the colour factor's luminance for a luminance (exact for a grey
 * factor; for a coloured one it is the product of the luminances, an estimate that only weighs the
 * principled material's lobes). One lookup of the texture and three or one multiplications; no
 * allocation.
 *
 * @param texture      the texture scaled
 * @param colourFactor multiplies {@link #rgb}, channel by channel; not negative (an {@code Rgb} is finite)
 * @param valueFactor  multiplies {@link #value}; finite, not negative
 */
public record ScaledTexture(TextureLookup texture, Rgb colourFactor, double valueFactor) implements TextureLookup {

    /** Checks for nulls and that the factors are finite and not negative. */
    public ScaledTexture {
        Objects.requireNonNull(texture, "texture");
        Objects.requireNonNull(colourFactor, "colourFactor");
        if (!(colourFactor.r() >= 0 && colourFactor.g() >= 0 && colourFactor.b() >= 0) || !(valueFactor >= 0) || !Double.isFinite(valueFactor)) {
            throw new IllegalArgumentException("a texture's factor must be finite and not negative, got " + colourFactor + " and " + valueFactor);
        }
    }

    @Override
    public void rgb(double u, double v, MutableRgb dest) {
        texture.rgb(u, v, dest);
        dest.mul(colourFactor);
    }

    @Override
    public double value(double u, double v) {
        return valueFactor * texture.value(u, v);
    }

    @Override
    public boolean isConstant() {
        return texture.isConstant();
    }

    @Override
    public Rgb mean() {
        Rgb m = texture.mean();
        return new Rgb(m.r() * colourFactor.r(), m.g() * colourFactor.g(), m.b() * colourFactor.b());
    }

    @Override
    public Bitmap bitmap() {
        return texture.bitmap();
    }

    @Override
    public String toString() {
        return texture + " x " + colourFactor + (valueFactor != colourFactor.r() || colourFactor.r() != colourFactor.g() || colourFactor.g() != colourFactor.b()
                ? " (value x " + valueFactor + ")" : "");
    }
}
