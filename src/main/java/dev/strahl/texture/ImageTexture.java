package dev.strahl.texture;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import java.util.Objects;

/**
 * An image over the surface with bilinear filtering, as Mitsuba's {@code bitmap} texture does by
 * default: the coordinates go through the {@link UvTransform}, then p = (u·w − ½, v·h − ½) in texel
 * units; the four texels around p (indices through the {@link Wrap} mode) are weighted by
 * (1 − fx)(1 − fy), fx(1 − fy), (1 − fx)fy and fx·fy, with fx, fy the fractional parts of p.
 * With {@link Channel#LUMINANCE} {@link #rgb} gives the texels' colour; a texture of one channel
 * (R, G, B or A) is grey wherever a colour is asked for.
 *
 * @param bitmap    the texels (already sRGB-decoded for a colour texture)
 * @param wrap      the wrap mode
 * @param transform the texture-coordinate transform
 * @param channel   the channel {@link #value} reads
 */
public record ImageTexture(Bitmap bitmap, Wrap wrap, UvTransform transform, Channel channel) implements TextureLookup {

    /** Checks for nulls. */
    public ImageTexture {
        Objects.requireNonNull(bitmap, "bitmap");
        Objects.requireNonNull(wrap, "wrap");
        Objects.requireNonNull(transform, "transform");
        Objects.requireNonNull(channel, "channel");
    }

    @Override
    public void rgb(double u, double v, MutableRgb dest) {
        if (channel != Channel.LUMINANCE) {
            double a = value(u, v);                // a one-channel texture is grey wherever a colour is asked for
            dest.set(a, a, a);
            return;
        }
        bilinear(u, v, dest);
    }

    @Override
    public double value(double u, double v) {
        return bilinear(u, v, null);
    }

    /**
     * The bilinear lookup at (u, v): into {@code dest} the colour of the texels, or, with
     * {@code dest} null, the number of {@link #channel} (returned). Outside a finite p: black, 0.
     */
    private double bilinear(double u, double v, MutableRgb dest) {
        Bitmap b = bitmap;
        double su = transform.mapU(u, v) * b.width() - 0.5, sv = transform.mapV(u, v) * b.height() - 0.5;
        if (!Double.isFinite(su) || !Double.isFinite(sv)) {
            if (dest != null) {
                dest.setZero();
            }
            return 0;
        }
        double fx0 = Math.floor(su), fy0 = Math.floor(sv);
        double fx = su - fx0, fy = sv - fy0;
        int ix = (int) Math.max(Integer.MIN_VALUE / 4, Math.min(Integer.MAX_VALUE / 4, fx0));
        int iy = (int) Math.max(Integer.MIN_VALUE / 4, Math.min(Integer.MAX_VALUE / 4, fy0));
        int x0 = wrap.index(ix, b.width()), x1 = wrap.index(ix + 1, b.width());
        int y0 = wrap.index(iy, b.height()), y1 = wrap.index(iy + 1, b.height());
        if (dest == null) {
            return (1 - fx) * (1 - fy) * b.value(x0, y0, channel) + fx * (1 - fy) * b.value(x1, y0, channel)
                    + (1 - fx) * fy * b.value(x0, y1, channel) + fx * fy * b.value(x1, y1, channel);
        }
        double w00 = (1 - fx) * (1 - fy), w10 = fx * (1 - fy), w01 = (1 - fx) * fy, w11 = fx * fy;
        int n = b.channels();
        float[] d = b.data;
        int i00 = (y0 * b.width() + x0) * n, i10 = (y0 * b.width() + x1) * n;
        int i01 = (y1 * b.width() + x0) * n, i11 = (y1 * b.width() + x1) * n;
        double r = w00 * d[i00] + w10 * d[i10] + w01 * d[i01] + w11 * d[i11];
        if (n <= 2) {
            dest.set(r, r, r);
            return 0;
        }
        double g = w00 * d[i00 + 1] + w10 * d[i10 + 1] + w01 * d[i01 + 1] + w11 * d[i11 + 1];
        double bl = w00 * d[i00 + 2] + w10 * d[i10 + 2] + w01 * d[i01 + 2] + w11 * d[i11 + 2];
        dest.set(r, g, bl);
        return 0;
    }

    @Override
    public boolean isConstant() {
        return false;
    }

    @Override
    public Rgb mean() {
        double r = 0, g = 0, bl = 0;
        Bitmap b = bitmap;
        if (channel != Channel.LUMINANCE) {
            for (int y = 0; y < b.height(); y++) {
                for (int x = 0; x < b.width(); x++) {
                    r += b.value(x, y, channel);
                }
            }
            return Rgb.gray(r / ((double) b.width() * b.height()));
        }
        int n = b.channels();
        float[] d = b.data;
        for (int i = 0; i < d.length; i += n) {
            if (n <= 2) {
                r += d[i];
                g += d[i];
                bl += d[i];
            } else {
                r += d[i];
                g += d[i + 1];
                bl += d[i + 2];
            }
        }
        double count = (double) b.width() * b.height();
        return new Rgb(r / count, g / count, bl / count);
    }

    @Override
    public String toString() {
        return "ImageTexture[" + bitmap.name() + String.format("@%016x", bitmap.contentHash()) + (wrap != Wrap.REPEAT ? ", " + wrap : "") + (transform.isIdentity() ? "" : ", " + transform)
                + (channel != Channel.LUMINANCE ? ", " + channel : "") + "]";
    }
}
