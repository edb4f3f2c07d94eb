package dev.strahl.color;

import dev.strahl.image.Image;
import dev.strahl.image.ToneMapping;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;

/**
 * Display encoding of linear radiance: the sRGB transfer function, 8-bit quantisation, and the
 * conversion of an {@link Image} to a {@link BufferedImage} used by the PNG writer and the viewer,
 * with one of the tone curves of {@link ToneMapping} (clamping by default: values above 1 saturate
 * to white).
 */
public final class DisplayEncoding {

    // --- the 8-bit lookup behind encode8 -------------------------------------------------------
    // pow() per channel is too slow for the viewer. The code of x is the number of transitions
    // T[k] <= x, where T[k] is the smallest double whose toSrgb8 code exceeds k (found once by
    // bisection over the bits of positive doubles, which are ordered like their values). Doubles
    // in [2^-13, 1) are bucketed by exponent and the top MANTISSA_BITS bits of the mantissa; the
    // buckets are narrow enough (at most 0.88 codes wide, just below 1) to hold at most one
    // transition, so a bucket stores the code of its smallest value and that transition.
    // The result is identical to toSrgb8 for every input, not an approximation, and the lookup is
    // branch-free; DisplayEncodingTest checks it around every transition.

    private static final int MANTISSA_BITS = 7;
    private static final int SHIFT = 52 - MANTISSA_BITS;
    /** Below this every code is 0: the first transition is at 0.5 / (255 · 12.92) ≈ 1.52e-4. */
    private static final double LUT_MIN = 0x1p-13;
    private static final int LUT_BASE = (int) (Double.doubleToRawLongBits(LUT_MIN) >>> SHIFT);
    private static final byte[] BUCKET_CODE;
    /** Bits of the transition inside each bucket, or Long.MAX_VALUE (no transition). */
    private static final long[] BUCKET_STEP;

    static {
        double[] transition = new double[255];
        for (int k = 0; k < 255; k++) {
            long lo = Double.doubleToRawLongBits(0.0);   // toSrgb8 = 0 <= k
            long hi = Double.doubleToRawLongBits(1.0);   // toSrgb8 = 255 > k
            while (hi - lo > 1) {
                long mid = (lo + hi) >>> 1;
                if (toSrgb8(Double.longBitsToDouble(mid)) > k) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            transition[k] = Double.longBitsToDouble(hi);
        }
        int buckets = (int) ((Double.doubleToRawLongBits(1.0) >>> SHIFT) - LUT_BASE);
        BUCKET_CODE = new byte[buckets];
        BUCKET_STEP = new long[buckets];
        for (int b = 0; b < buckets; b++) {
            double lo = Double.longBitsToDouble((long) (LUT_BASE + b) << SHIFT);
            double hi = Double.longBitsToDouble((long) (LUT_BASE + b + 1) << SHIFT);
            int code = toSrgb8(lo);
            BUCKET_CODE[b] = (byte) code;
            BUCKET_STEP[b] = code < 255 && transition[code] < hi
                    ? Double.doubleToRawLongBits(transition[code]) : Long.MAX_VALUE;
            if (code < 254 && transition[code + 1] < hi) {
                throw new IllegalStateException("sRGB lookup: two transitions in bucket " + b);
            }
        }
        if (BUCKET_CODE[0] != 0 || BUCKET_STEP[0] != Long.MAX_VALUE) {
            throw new IllegalStateException("sRGB lookup: values below " + LUT_MIN + " must all have code 0");
        }
        if (BUCKET_CODE[buckets - 1] != (byte) 255 || BUCKET_STEP[buckets - 1] != Long.MAX_VALUE) {
            throw new IllegalStateException("sRGB lookup: the last bucket must have code 255 throughout");
        }
    }

    private DisplayEncoding() {
    }

    /**
     * The 8-bit sRGB code of a linear value: round(255 · {@link Srgb#encode}(linear)), rounding
     * halves up.
     *
     * @param linear linear radiance (1 = display white)
     * @return the code in [0, 255]
     */
    public static int toSrgb8(double linear) {
        return (int) Math.round(255 * Srgb.encode(linear));
    }

    /** Same result as {@link #toSrgb8} for every input, through the lookup table (no pow). */
    static int encode8(double linear) {
        if (linear != linear) {
            return 0;                        // NaN (rare, so this branch is well predicted)
        }
        // Branch-free from here, because noisy pixels make any data-dependent branch a coin flip.
        // Non-negative doubles compare like their bit patterns as longs, so all the work is on
        // integers: negative values (sign bit set) become +0; the bucket index is clamped so that
        // values below LUT_MIN fall into bucket 0 (code 0 throughout) and values >= 1 into the last
        // bucket (code 255 throughout). The shifted bits lie in [0, 2^18), so int suffices (and
        // Math.min/max(int) are intrinsics; the long versions are not on Java 17).
        long bits = Double.doubleToRawLongBits(linear);
        bits &= ~(bits >> 63);
        int b = Math.max(0, Math.min((int) (bits >> SHIFT) - LUT_BASE, BUCKET_CODE.length - 1));
        // + 1 iff bits >= BUCKET_STEP[b], i.e. the sign of (step − 1 − bits); no overflow as both are >= 0
        return (BUCKET_CODE[b] & 0xFF) + (int) ((BUCKET_STEP[b] - 1 - bits) >>> 63);
    }

    /**
     * Converts a linear image to an 8-bit sRGB image for display or PNG output. Each channel is
     * multiplied by 2^exposureStops (in double precision) and then encoded exactly as
     * {@link #toSrgb8} would. Pixel (x, y) of the result is pixel (x, y) of {@code img} (both
     * top-down).
     *
     * @param img           the linear image
     * @param exposureStops exposure in photographic stops: 0 leaves radiance unchanged, +1 doubles it
     * @return a new {@link BufferedImage#TYPE_INT_RGB} image of the same size
     * @throws IllegalArgumentException if exposureStops is NaN or infinite
     */
    public static BufferedImage toBufferedImage(Image img, double exposureStops) {
        return toBufferedImage(img, exposureStops, ToneMapping.CLAMP);
    }

    /**
     * Converts a linear image to an 8-bit sRGB image with a tone curve: each channel is
     * multiplied by 2^exposureStops, mapped by the curve to display-linear [0, 1] and encoded as
     * {@link #toSrgb8} would. With {@link ToneMapping#CLAMP} the result is that of
     * {@link #toBufferedImage(Image, double)}.
     *
     * @param img           the linear image
     * @param exposureStops exposure in photographic stops
     * @param curve         the tone curve
     * @return a new {@link BufferedImage#TYPE_INT_RGB} image of the same size
     * @throws IllegalArgumentException if exposureStops is NaN or infinite
     */
    public static BufferedImage toBufferedImage(Image img, double exposureStops, ToneMapping curve) {
        if (curve != ToneMapping.CLAMP) {
            return curved(img, exposureStops, curve);
        }
        if (!Double.isFinite(exposureStops)) {
            throw new IllegalArgumentException("exposure must be a finite number of stops, got " + exposureStops);
        }
        double scale = Math.pow(2, exposureStops);   // exact for integer stops
        int w = img.width();
        int h = img.height();
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] px = ((DataBufferInt) out.getRaster().getDataBuffer()).getData();
        int i = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++, i++) {
                px[i] = encode8(img.get(x, y, 0) * scale) << 16
                        | encode8(img.get(x, y, 1) * scale) << 8
                        | encode8(img.get(x, y, 2) * scale);
            }
        }
        return out;
    }

    private static BufferedImage curved(Image img, double exposureStops, ToneMapping curve) {
        if (!Double.isFinite(exposureStops)) {
            throw new IllegalArgumentException("exposure must be a finite number of stops, got " + exposureStops);
        }
        double scale = Math.pow(2, exposureStops);
        int w = img.width();
        int h = img.height();
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] px = ((DataBufferInt) out.getRaster().getDataBuffer()).getData();
        double[] c = new double[3];
        int i = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++, i++) {
                c[0] = img.get(x, y, 0) * scale;
                c[1] = img.get(x, y, 1) * scale;
                c[2] = img.get(x, y, 2) * scale;
                if (curve == ToneMapping.ACES) {
                    c[0] = aces(c[0]);
                    c[1] = aces(c[1]);
                    c[2] = aces(c[2]);
                } else {
                    agx(c);
                }
                px[i] = encode8(c[0]) << 16 | encode8(c[1]) << 8 | encode8(c[2]);
            }
        }
        return out;
    }

    /**
     * Narkowicz's ACES filmic fit ("ACES Filmic Tone Mapping Curve", 2016):
     * x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), clamped to [0, 1]; negatives and NaN give 0.
     *
     * @param x linear radiance after exposure
     * @return display-linear value in [0, 1]
     */
    public static double aces(double x) {
        if (!(x > 0)) {
            return 0;
        }
        double v = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
        return Math.min(1, v);
    }

    // AgX (Troy Sobotka, 2022) as Benjamin Wrensch's "Minimal AgX implementation" (2023) gives it:
    // the inset and outset matrices (here as rows acting on (r, g, b)), the log2 range, the
    // sixth-order polynomial fit of the default contrast curve, and the 2.2 display power.
    private static final double[] AGX_INSET = {
        0.842479062253094, 0.0784335999999992, 0.0792237451477643,
        0.0423282422610123, 0.878468636469772, 0.0791661274605434,
        0.0423756549057051, 0.0784336, 0.879142973793104};
    private static final double[] AGX_OUTSET = {
        1.19687900512017, -0.0980208811401368, -0.0990297440797205,
        -0.0528968517574562, 1.15190312990417, -0.0989611768448433,
        -0.0529716355144438, -0.0980434501171241, 1.15107367264116};
    private static final double AGX_MIN_EV = -12.47393;
    private static final double AGX_MAX_EV = 4.026069;

    /**
     * AgX in place: linear radiance after exposure in, display-linear values in [0, 1] out.
     *
     * @param c r, g, b
     */
    public static void agx(double[] c) {
        double r = AGX_INSET[0] * c[0] + AGX_INSET[1] * c[1] + AGX_INSET[2] * c[2];
        double g = AGX_INSET[3] * c[0] + AGX_INSET[4] * c[1] + AGX_INSET[5] * c[2];
        double b = AGX_INSET[6] * c[0] + AGX_INSET[7] * c[1] + AGX_INSET[8] * c[2];
        r = agxContrast(agxLog(r));
        g = agxContrast(agxLog(g));
        b = agxContrast(agxLog(b));
        double r2 = AGX_OUTSET[0] * r + AGX_OUTSET[1] * g + AGX_OUTSET[2] * b;
        double g2 = AGX_OUTSET[3] * r + AGX_OUTSET[4] * g + AGX_OUTSET[5] * b;
        double b2 = AGX_OUTSET[6] * r + AGX_OUTSET[7] * g + AGX_OUTSET[8] * b;
        c[0] = agxDisplay(r2);
        c[1] = agxDisplay(g2);
        c[2] = agxDisplay(b2);
    }

    /** log2 of the value, clamped to the range of AgX's log encoding and scaled to [0, 1]. */
    private static double agxLog(double v) {
        double ev = v > 0 ? Math.log(v) / Math.log(2) : AGX_MIN_EV;     // NaN and negatives: black
        ev = Math.max(AGX_MIN_EV, Math.min(AGX_MAX_EV, ev));
        return (ev - AGX_MIN_EV) / (AGX_MAX_EV - AGX_MIN_EV);
    }

    /** The sixth-order polynomial fit of AgX's default contrast sigmoid over [0, 1]. */
    private static double agxContrast(double x) {
        double x2 = x * x;
        double x4 = x2 * x2;
        return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
    }

    private static double agxDisplay(double v) {
        return v > 0 ? Math.min(1, Math.pow(v, 2.2)) : 0;
    }
}
