package dev.strahl.scene;

import dev.strahl.image.Rgb;
import dev.strahl.texture.Bitmap;
import dev.strahl.texture.Channel;
import dev.strahl.texture.ConstantTexture;
import dev.strahl.texture.ImageTexture;
import dev.strahl.texture.UvTransform;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;

/**
 * A material parameter that varies over a surface: an image (PNG, 8 or 16 bit, grey, RGB, RGBA or
 * palette; or JPEG) looked up at the surface's texture coordinates with bilinear filtering, or a
 * constant. Where a material takes a colour or a number, a texture may stand instead.
 *
 * <p>Texture coordinates (0, 0) are the image's bottom-left corner and (1, 1) its top-right one
 * (OBJ's convention); a {@link TriangleMesh} gives them per vertex, spheres have u = φ/2π and
 * v = 1 − θ/π about their y axis. They are scaled and offset ({@link #withUvScale},
 * {@link #withUvOffset}) and wrapped ({@link #withWrap}, repeating by default) before the lookup.
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
    /** How texture coordinates outside [0, 1) read the image. */
    public enum Wrap {
        /** The image repeats (the default). */
        REPEAT,
        /** The border texels extend outwards. */
        CLAMP,
        /** The image repeats, mirrored every other time. */
        MIRRORED_REPEAT
    }

    private final Path file;
    private final Bitmap bitmap;
    private final Rgb constant;
    private final boolean linear;
    private final UvTransform transform;
    private final Wrap wrap;
    /** The one channel the texture reads ({@link #alpha()}), or null for all. */
    private final Channel channel;

    private Texture(Path file, Bitmap bitmap, Rgb constant, boolean linear, UvTransform transform, Wrap wrap) {
        this(file, bitmap, constant, linear, transform, wrap, null);
    }

    private Texture(Path file, Bitmap bitmap, Rgb constant, boolean linear, UvTransform transform, Wrap wrap, Channel channel) {
        this.file = file;
        this.bitmap = bitmap;
        this.constant = constant;
        this.linear = linear;
        this.transform = transform;
        this.wrap = wrap;
        this.channel = channel;
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
        return new Texture(file, TextureFiles.load(file), null, false, UvTransform.IDENTITY, Wrap.REPEAT);
    }

    /**
     * The same colour everywhere.
     *
     * @param colour linear RGB
     * @return the texture
     */
    public static Texture constant(Rgb colour) {
        return new Texture(null, null, Objects.requireNonNull(colour, "colour"), true, UvTransform.IDENTITY, Wrap.REPEAT);
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
        return new Texture(file, bitmap, constant, true, transform, wrap, channel);
    }

    /**
     * The image's alpha channel as a scalar texture (linear; read as a grey value wherever a
     * colour is asked for): 1 where the image has none, and 1 for a constant.
     *
     * @return a new texture with this one's coordinates and wrap mode
     */
    public Texture alpha() {
        if (constant != null) {
            return constant(1);
        }
        return new Texture(file, bitmap, null, true, transform, wrap, Channel.A);
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
        return new Texture(file, bitmap, constant, linear, new UvTransform(su, sv, transform.offsetU(), transform.offsetV(), 0), wrap, channel);
    }

    /**
     * This texture with its coordinates offset after scaling: u·su + ou, v·sv + ov.
     *
     * @param ou offset of u, finite
     * @param ov offset of v, finite
     * @return a new texture
     */
    public Texture withUvOffset(double ou, double ov) {
        return new Texture(file, bitmap, constant, linear, new UvTransform(transform.scaleU(), transform.scaleV(), ou, ov, 0), wrap, channel);
    }

    /**
     * This texture with another wrap mode.
     *
     * @param mode the wrap mode
     * @return a new texture
     */
    public Texture withWrap(Wrap mode) {
        return new Texture(file, bitmap, constant, linear, transform, Objects.requireNonNull(mode, "mode"), channel);
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

    /** The texture as a colour: sRGB-decoded texels unless linear (an {@link #alpha()} texture: its grey value). */
    dev.strahl.texture.Texture colour() {
        if (constant != null) {
            return dev.strahl.texture.Texture.of(constant);
        }
        if (channel != null) {
            return new ImageTexture(bitmap, wrap(), transform, channel);
        }
        return new ImageTexture(linear ? bitmap : bitmap.srgbDecoded(), wrap(), transform, Channel.LUMINANCE);
    }

    /** The texture as linear data (normal maps): the texels as stored, never sRGB-decoded. */
    dev.strahl.texture.Texture data() {
        if (constant != null) {
            return dev.strahl.texture.Texture.of(constant);
        }
        return new ImageTexture(bitmap, wrap(), transform, channel != null ? channel : Channel.LUMINANCE);
    }

    /** The texture as a number from a channel of the linear texels ({@link #alpha()}'s channel if it has one). */
    dev.strahl.texture.Texture scalar(Channel channel) {
        if (constant != null) {
            return new ConstantTexture(constant, channelOf(constant, channel));
        }
        return new ImageTexture(bitmap, wrap(), transform, this.channel != null ? this.channel : channel);
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

    private dev.strahl.texture.Wrap wrap() {
        return dev.strahl.texture.Wrap.valueOf(wrap.name());
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Texture t && Objects.equals(file, t.file) && t.bitmap == bitmap && Objects.equals(constant, t.constant)
                && linear == t.linear && transform.equals(t.transform) && wrap == t.wrap && channel == t.channel;
    }

    @Override
    public int hashCode() {
        return Objects.hash(file, constant, linear, transform, wrap, channel);
    }

    @Override
    public String toString() {
        if (constant != null) {
            return "Texture[" + constant + "]";
        }
        return "Texture[" + file + (channel != null ? ", alpha" : linear ? ", linear" : "") + (transform.isIdentity() ? "" : ", " + transform)
                + (wrap != Wrap.REPEAT ? ", " + wrap : "") + "]";
    }
}
