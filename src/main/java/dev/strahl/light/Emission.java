package dev.strahl.light;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import dev.strahl.texture.TextureLookup;
import java.util.Objects;
import org.joml.Vector2dc;

/**
 * The radiance a material emits at texture coordinates (u, v): Le(u, v) = scale ⊙ texture(u, v)
 * (scale alone for a constant emitter), and black where the material's alpha cut-out removes the
 * surface (alpha(u, v) &lt; cutoff). One per material index; the world's one emission table, read
 * by shading (a hit emitter) and by light sampling (a sampled point). Immutable.
 *
 * <p>Light selection weighs an emitter by area × {@link #mean()}: the mean over the texture (the
 * cut-out is not taken into account), so the density per unit area stays a function of the
 * material alone and MIS sees the same pdf from either side.
 */
public final class Emission {
    /** No emission. */
    public static final Emission BLACK = new Emission(Rgb.BLACK, null, null, 0);

    private final Rgb scale;
    private final TextureLookup texture;
    private final TextureLookup alpha;
    private final double cutoff;
    private final Rgb mean;

    private Emission(Rgb scale, TextureLookup texture, TextureLookup alpha, double cutoff) {
        this.scale = Objects.requireNonNull(scale, "scale");
        this.texture = texture;
        this.alpha = alpha;
        this.cutoff = cutoff;
        this.mean = texture == null ? scale : product(scale, texture.mean());
    }

    /** A constant radiance (black: not a light). */
    public static Emission of(Rgb radiance) {
        return radiance.isBlack() ? BLACK : new Emission(radiance, null, null, 0);
    }

    /** A constant radiance per material (the tests' area lights). */
    static Emission[] constants(Rgb... radiance) {
        Emission[] out = new Emission[radiance.length];
        for (int m = 0; m < out.length; m++) {
            out[m] = of(radiance[m]);
        }
        return out;
    }

    /**
     * Radiance scale ⊙ texture(u, v), the texture's colour (already linear), masked where
     * {@code alpha}(u, v) &lt; {@code cutoff}; {@code texture} or {@code alpha} may be null.
     */
    public static Emission of(Rgb scale, TextureLookup texture, TextureLookup alpha, double cutoff) {
        if (scale.isBlack()) {
            return BLACK;
        }
        return new Emission(scale, texture, alpha, cutoff);
    }

    private static Rgb product(Rgb a, Rgb b) {
        return new Rgb(a.r() * b.r(), a.g() * b.g(), a.b() * b.b());
    }

    /** Whether the material emits nothing anywhere. */
    public boolean isBlack() {
        return mean.isBlack();
    }

    /** Whether Le is the same everywhere (no texture and no cut-out). */
    public boolean isConstant() {
        return texture == null && alpha == null;
    }

    /** The mean radiance over the texture (the constant for an untextured emitter): light selection weighs by it. */
    public Rgb mean() {
        return mean;
    }

    /** Le at (u, v), into {@code dest}. */
    public MutableRgb eval(Vector2dc uv, MutableRgb dest) {
        if (texture == null && alpha == null) {
            return dest.set(scale);
        }
        if (alpha != null && alpha.value(uv.x(), uv.y()) < cutoff) {
            return dest.setZero();
        }
        if (texture == null) {
            return dest.set(scale);
        }
        texture.rgb(uv.x(), uv.y(), dest);
        return dest.mul(scale);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Emission e && e.scale.equals(scale) && Objects.equals(e.texture, texture) && Objects.equals(e.alpha, alpha)
                && e.cutoff == cutoff;
    }

    @Override
    public int hashCode() {
        return Objects.hash(scale, texture, alpha, cutoff);
    }

    /** The constant's colour for an untextured emitter (as the materials' reports print it), else scale × texture. */
    @Override
    public String toString() {
        if (isConstant()) {
            return scale.toString();
        }
        return scale + (texture != null ? " x " + texture : "") + (alpha != null ? " where " + alpha + " >= " + cutoff : "");
    }
}
