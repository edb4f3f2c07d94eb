package dev.strahl.texture;

import dev.strahl.color.Srgb;
import java.util.Arrays;
import java.util.Objects;

/**
 * The pixels of a texture image: {@code channels} (1: grey, 2: grey and alpha, 3: RGB, 4: RGBA)
 * floats per texel, interleaved, rows from the BOTTOM of the image up (so v = 0 is row 0, see the
 * package documentation). Immutable once made; shared by every texture that reads the same file.
 *
 * <p>A bitmap is stored as the file gives it (linear for data textures); its sRGB-decoded twin for
 * colour use is made once, on first request ({@link #srgbDecoded}), and shared the same way.
 */
public final class Bitmap {
    private final String name;
    private final int width, height, channels;
    final float[] data;          // package-private for ImageTexture's lookups
    private final boolean decoded;
    private final long contentHash;
    private volatile Bitmap srgbDecoded;

    private Bitmap(String name, int width, int height, int channels, float[] data, boolean decoded) {
        this.name = Objects.requireNonNull(name, "name");
        if (width <= 0 || height <= 0 || channels < 1 || channels > 4) {
            throw new IllegalArgumentException("bitmap " + name + ": need a positive size and 1 to 4 channels, got " + width + "x" + height
                    + " with " + channels);
        }
        if (data.length != (long) width * height * channels) {
            throw new IllegalArgumentException("bitmap " + name + ": expected " + (long) width * height * channels + " samples, got " + data.length);
        }
        this.width = width;
        this.height = height;
        this.channels = channels;
        this.data = data;
        this.decoded = decoded;
        this.contentHash = hash(width, height, channels, data);
    }

    /** 64-bit FNV-1a over the size and every sample's bits: what identifies the pixels in a scene's digest. */
    private static long hash(int width, int height, int channels, float[] data) {
        long h = 0xcbf29ce484222325L;
        h = (h ^ width) * 0x100000001b3L;
        h = (h ^ height) * 0x100000001b3L;
        h = (h ^ channels) * 0x100000001b3L;
        for (float v : data) {
            h = (h ^ Float.floatToRawIntBits(v)) * 0x100000001b3L;
        }
        return h;
    }

    /**
     * A bitmap from samples stored top row first (as image readers return them); the rows are
     * flipped here. Takes no copy of {@code topDown} beyond the flip.
     *
     * @param name     for messages and statistics (the file name)
     * @param width    texels per row
     * @param height   rows
     * @param channels 1 to 4
     * @param topDown  width · height · channels samples, the top row first
     */
    public static Bitmap fromTopDown(String name, int width, int height, int channels, float[] topDown) {
        float[] data = new float[topDown.length];
        int row = width * channels;
        for (int y = 0; y < height; y++) {
            System.arraycopy(topDown, (height - 1 - y) * row, data, y * row, row);
        }
        return new Bitmap(name, width, height, channels, data, false);
    }

    /** The sRGB-decoded twin: colour channels through {@link Srgb#decode}, alpha as it is. Made once. */
    public Bitmap srgbDecoded() {
        if (decoded) {
            return this;
        }
        Bitmap d = srgbDecoded;
        if (d == null) {
            synchronized (this) {
                d = srgbDecoded;
                if (d == null) {
                    float[] out = Arrays.copyOf(data, data.length);
                    int colour = channels == 1 || channels == 2 ? 1 : 3;
                    for (int i = 0; i < out.length; i += channels) {
                        for (int c = 0; c < colour; c++) {
                            out[i + c] = Srgb.decode(out[i + c]);
                        }
                    }
                    d = new Bitmap(name, width, height, channels, out, true);
                    srgbDecoded = d;
                }
            }
        }
        return d;
    }

    public String name() {
        return name;
    }

    /**
     * A hash of the size and the samples: two bitmaps with other pixels differ in it (as far as
     * a 64-bit hash can tell), whatever their names; a checkpoint and a cluster job identify a
     * scene's textures by it.
     */
    public long contentHash() {
        return contentHash;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public int channels() {
        return channels;
    }

    /** Whether this is the decoded twin of an sRGB-encoded image. */
    public boolean isSrgbDecoded() {
        return decoded;
    }

    /** Bytes of the texel array. */
    public long byteSize() {
        return 4L * data.length;
    }

    /** One value of texel (x, y); see {@link Channel}. */
    double value(int x, int y, Channel channel) {
        int i = (y * width + x) * channels;
        boolean grey = channels <= 2;
        switch (channel) {
            case R:
                return data[i];
            case G:
                return grey ? data[i] : data[i + 1];
            case B:
                return grey ? data[i] : data[i + 2];
            case A:
                return channels == 2 ? data[i + 1] : channels == 4 ? data[i + 3] : 1;
            default:
                return grey ? data[i] : 0.2126 * data[i] + 0.7152 * data[i + 1] + 0.0722 * data[i + 2];
        }
    }

    @Override
    public String toString() {
        return "Bitmap[" + name + ", " + width + "x" + height + "x" + channels + (decoded ? ", sRGB decoded" : "") + "]";
    }
}
