package dev.strahl.scene;

import dev.strahl.texture.TextureLookup;
import dev.strahl.image.Rgb;
import dev.strahl.texture.Bitmap;
import dev.strahl.texture.Channel;
import dev.strahl.texture.ConstantTexture;
import dev.strahl.texture.ImageTexture;
import dev.strahl.texture.ScaledTexture;
import dev.strahl.texture.UvTransform;
import dev.strahl.texture.Wrap;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;

/**
 * A material parameter that varies over a surface: an image (PNG, 8 or 16 bit, grey, RGB, RGBA or
 * palette; or JPEG) looked up at the surface's texture coordinates with bilinear filtering, or a
 * constant. Where a material takes a colour or a number, a texture may stand instead; it may be
 * multiplied by a factor ({@link #scaled}, {@link #times}), as glTF multiplies its textures by
 * its factors.
 *
 * <p>Texture coordinates (0, 0) are the image's bottom-left corner and (1, 1) its top-right one
 * (OBJ's convention); a {@link TriangleMesh} gives them per vertex, spheres have u = φ/2π and
 * v = 1 − θ/π about their y axis. They are scaled, rotated and offset ({@link #withUvScale},
 * {@link #withUvRotation}, {@link #withUvOffset}, in this order) and wrapped (repeating by default, or
 * {@link #clamped}, {@link #mirrored}) before the lookup.
 *
 * <p>Values: a colour texture (an albedo, a base colour) is decoded from sRGB to linear unless it is
 * declared {@link #linear()}; a number (roughness, metallic) reads a linear channel (the grey value,
 * or the luminance of a colour image, unless the material says which channel). An image file used
 * by many textures is read once. Immutable.
 *
 * <pre>{@code
 * Material wood = Material.diffuse("wood", Texture.image(Path.of("wood.png")).withUvScale(4, 4));
 * }</pre>
 */
public final class Texture {
    private final Path file;
    private final Bitmap bitmap;
    private final Rgb constant;
    private final boolean linear;
    private final UvTransform transform;
    private final Wrap wrap;
    /** The one channel the texture reads ({@link #alpha()}, {@link #channel(int)}), or null for all. */
    private final Channel channel;
    /** The factor of {@link #scaled} and {@link #times}, or null for none (a constant folds it in). */
    private final Rgb factor;

    private Texture(Path file, Bitmap bitmap, Rgb constant, boolean linear, UvTransform transform, Wrap wrap, Channel channel, Rgb factor) {
        this.file = file;
        this.bitmap = bitmap;
        this.constant = constant;
        this.linear = linear;
        this.transform = transform;
        this.wrap = wrap;
        this.channel = channel;
        this.factor = factor;
    }

    private static Texture of(Path file, Bitmap bitmap, Rgb constant, boolean linear) {
        return new Texture(file, bitmap, constant, linear, UvTransform.IDENTITY, Wrap.REPEAT, null, null);
    }

    private Texture withTransform(UvTransform t) {
        return new Texture(file, bitmap, constant, linear, t, wrap, channel, factor);
    }

    /**
     * An image texture from a PNG or JPEG file, read now (or taken from the images already read).
     *
     * @param file the image
     * @return the texture, repeating, coordinates as they are
     * @throws java.nio.file.NoSuchFileException if there is no such file
     * @throws IOException if the file cannot be read or is not a PNG or JPEG image (one line naming the file)
     */
    public static Texture image(Path file) throws IOException {
        Objects.requireNonNull(file, "file");
        return of(file, TextureFiles.load(file), null, false);
    }

    /**
     * The same colour everywhere.
     *
     * @param colour linear RGB
     * @return the texture
     */
    public static Texture constant(Rgb colour) {
        return of(null, null, Objects.requireNonNull(colour, "colour"), true);
    }

    /**
     * The same number everywhere.
     *
     * @param value the number
     * @return the texture
     */
    public static Texture constant(double value) {
        return constant(Rgb.gray(value));
    }

    /**
     * This image declared as storing linear colours (no sRGB decoding where a colour is read).
     *
     * @return a new texture
     */
    public Texture linear() {
        return new Texture(file, bitmap, constant, true, transform, wrap, channel, factor);
    }

    /**
     * The image's alpha channel as a scalar texture (linear; read as a grey value wherever a
     * colour is asked for): 1 where the image has none, and 1 for a constant. A factor given
     * before ({@link #scaled}, {@link #times}) is not carried over: it scales colours, not alpha.
     *
     * @return a new texture with this one's coordinates and wrap mode
     */
    public Texture alpha() {
        return channel(3);
    }

    /**
     * One channel of the image as a scalar texture, read linearly (never sRGB-decoded) and as a
     * grey value wherever a colour is asked for: 0 red, 1 green, 2 blue, 3 alpha (as glTF keeps
     * transmission in R and the specular factor in A). A grey image gives its grey value for 0 to
     * 2; an image without alpha gives 1 for 3. A factor given before ({@link #scaled},
     * {@link #times}) is not carried over; one given after multiplies the number.
     *
     * @param index 0, 1, 2 or 3
     * @return a new texture with this one's coordinates and wrap mode; for a constant, the
     *         constant's channel (1 for alpha)
     */
    public Texture channel(int index) {
        if (index < 0 || index > 3) {
            throw new IllegalArgumentException("a texture's channel is 0 (red), 1 (green), 2 (blue) or 3 (alpha), got " + index);
        }
        Channel c = Channel.values()[index];
        if (constant != null) {
            return constant(channelOf(constant, c));
        }
        return new Texture(file, bitmap, null, true, transform, wrap, c, null);
    }

    /**
     * This texture multiplied by a colour, channel by channel (glTF's baseColorFactor ×
     * baseColorTexture): colour(u, v) = factor ⊙ texel(u, v), the product taken in linear RGB
     * (after the sRGB decoding). A number read from one channel is multiplied by that channel's
     * factor (glTF's roughnessFactor × G, metallicFactor × B); a number read as luminance by the
     * factor's luminance (exact for a grey factor). Factors multiply: {@code t.scaled(a).scaled(b)}
     * is {@code t.scaled(a ⊙ b)}; {@code t.scaled(Rgb.WHITE)} is {@code t}. A constant becomes the
     * product constant.
     *
     * @param factor linear RGB, each channel not negative
     * @return a new texture
     */
    public Texture scaled(Rgb factor) {
        Objects.requireNonNull(factor, "factor");
        if (!(factor.r() >= 0 && factor.g() >= 0 && factor.b() >= 0)) {
            throw new IllegalArgumentException("a texture's factor must be finite and not negative, got " + factor);
        }
        if (factor.equals(Rgb.WHITE)) {
            return this;
        }
        if (constant != null) {
            return new Texture(file, bitmap, product(constant, factor), linear, transform, wrap, channel, null);
        }
        return new Texture(file, bitmap, null, linear, transform, wrap, channel, this.factor == null ? factor : product(this.factor, factor));
    }

    /**
     * This texture multiplied by a number, colour and value alike (glTF's transmissionFactor ×
     * transmissionTexture): {@code scaled(Rgb.gray(factor))}.
     *
     * @param factor finite, not negative
     * @return a new texture
     */
    public Texture times(double factor) {
        return scaled(Rgb.gray(factor));
    }

    private static Rgb product(Rgb a, Rgb b) {
        return new Rgb(a.r() * b.r(), a.g() * b.g(), a.b() * b.b());
    }

    /**
     * Whether the image has an alpha channel (grey + alpha or RGBA).
     *
     * @return false for a constant and for images without alpha
     */
    public boolean hasAlpha() {
        return bitmap != null && (bitmap.channels() == 2 || bitmap.channels() == 4);
    }

    /**
     * This texture with its coordinates scaled: u·su, v·sv (with the default wrap, the image
     * repeats su times across u).
     *
     * @param su scale of u, finite
     * @param sv scale of v, finite
     * @return a new texture
     */
    public Texture withUvScale(double su, double sv) {
        return withTransform(new UvTransform(su, sv, transform.offsetU(), transform.offsetV(), transform.rotation()));
    }

    /**
     * This texture with its coordinates offset after scaling (and rotating): u·su + ou, v·sv + ov.
     *
     * @param ou offset of u, finite
     * @param ov offset of v, finite
     * @return a new texture
     */
    public Texture withUvOffset(double ou, double ov) {
        return withTransform(new UvTransform(transform.scaleU(), transform.scaleV(), ou, ov, transform.rotation()));
    }

    /**
     * This texture with its coordinates rotated counter-clockwise about (0, 0) after scaling and
     * before the offset: u' = cos r · su u − sin r · sv v + ou, v' = sin r · su u + cos r · sv v + ov
     * (glTF's KHR_texture_transform, Blender's Mapping node).
     *
     * @param radians the angle r, finite
     * @return a new texture
     */
    public Texture withUvRotation(double radians) {
        return withTransform(new UvTransform(transform.scaleU(), transform.scaleV(), transform.offsetU(), transform.offsetV(), radians));
    }

    /**
     * This texture with the image's border texels extended outwards where the coordinates leave
     * [0, 1) (glTF's CLAMP_TO_EDGE), instead of the image repeating.
     *
     * @return a new texture
     */
    public Texture clamped() {
        return withWrap(Wrap.CLAMP);
    }

    /**
     * This texture with the image repeating mirrored every other time (glTF's MIRRORED_REPEAT),
     * instead of repeating as it is.
     *
     * @return a new texture
     */
    public Texture mirrored() {
        return withWrap(Wrap.MIRRORED_REPEAT);
    }

    private Texture withWrap(Wrap mode) {
        return new Texture(file, bitmap, constant, linear, transform, mode, channel, factor);
    }

    /**
     * The image file.
     *
     * @return the file, or null for a constant
     */
    public Path file() {
        return file;
    }

    /**
     * Whether the texture is a constant.
     *
     * @return true for {@link #constant(Rgb)} and {@link #constant(double)}
     */
    public boolean isConstant() {
        return constant != null;
    }

    /** The constant's colour; null for an image. */
    Rgb constantColour() {
        return constant;
    }

    /** The texture as a colour: sRGB-decoded texels unless linear (a one-channel texture: its grey value), times the factor. */
    TextureLookup colour() {
        if (constant != null) {
            return TextureLookup.of(constant);
        }
        if (channel != null) {
            return withFactor(new ImageTexture(bitmap, wrap, transform, channel), Channel.LUMINANCE);
        }
        return withFactor(new ImageTexture(linear ? bitmap : bitmap.srgbDecoded(), wrap, transform, Channel.LUMINANCE), Channel.LUMINANCE);
    }

    /** The texture as linear data (normal maps): the texels as stored, never sRGB-decoded, times the factor. */
    TextureLookup data() {
        if (constant != null) {
            return TextureLookup.of(constant);
        }
        return withFactor(new ImageTexture(bitmap, wrap, transform, channel != null ? channel : Channel.LUMINANCE), Channel.LUMINANCE);
    }

    /** The texture as a number from a channel of the linear texels (its own channel if it has one), times the factor. */
    TextureLookup scalar(Channel channel) {
        if (constant != null) {
            return new ConstantTexture(constant, channelOf(constant, channel));
        }
        return withFactor(new ImageTexture(bitmap, wrap, transform, this.channel != null ? this.channel : channel), channel);
    }

    /**
     * {@code t} times the factor: colours channel by channel; a number read from {@code read} by
     * that channel's factor, or (a luminance, or a one-channel texture, whose number is its grey
     * value) by the factor's luminance.
     */
    private TextureLookup withFactor(TextureLookup t, Channel read) {
        if (factor == null) {
            return t;
        }
        boolean grey = factor.r() == factor.g() && factor.g() == factor.b();
        if (channel != null || read == Channel.LUMINANCE) {
            return new ScaledTexture(t, factor, grey ? factor.r() : factor.luminance());
        }
        return new ScaledTexture(t, factor, channelOf(factor, read));
    }

    private static double channelOf(Rgb c, Channel channel) {
        switch (channel) {
            case R:
                return c.r();
            case G:
                return c.g();
            case B:
                return c.b();
            case A:
                return 1;
            default:
                return c.luminance();
        }
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Texture t && Objects.equals(file, t.file) && t.bitmap == bitmap && Objects.equals(constant, t.constant)
                && linear == t.linear && transform.equals(t.transform) && wrap == t.wrap && channel == t.channel && Objects.equals(factor, t.factor);
    }

    @Override
    public int hashCode() {
        return Objects.hash(file, constant, linear, transform, wrap, channel, factor);
    }

    @Override
    public String toString() {
        if (constant != null) {
            return "Texture[" + constant + "]";
        }
        return "Texture[" + file + (channel == Channel.A ? ", alpha" : channel != null ? ", channel " + channel : linear ? ", linear" : "")
                + (transform.isIdentity() ? "" : ", " + transform) + (wrap != Wrap.REPEAT ? ", " + wrap : "") + (factor != null ? ", x " + factor : "") + "]";
    }
}
