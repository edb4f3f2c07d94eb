package dev.strahl.color;

/**
 * The sRGB transfer function both ways (IEC 61966-2-1). Encoding ({@link #encode}: display and PNG
 * output, through {@link DisplayEncoding}'s 8-bit table) and decoding ({@link #toLinear}: texture
 * images): linear = c / 12.92 for c ≤ 0.04045, ((c + 0.055) / 1.055)^2.4 above, by table
 * ({@link #decode}). One table of 65536 entries serves 8- and 16-bit images alike: a 16-bit sample
 * k/65535 is entry k, an 8-bit sample k/255 is entry 257·k (exactly the same value).
 */
public final class Srgb {
    /** Linear value below which the sRGB OETF is the straight line 12.92·x. */
    private static final double KNEE = 0.0031308;
    private static final float[] TABLE = new float[65536];

    static {
        for (int k = 0; k < TABLE.length; k++) {
            TABLE[k] = (float) toLinear(k / 65535.0);
        }
    }

    private Srgb() {}

    /** The formula, for any c in [0, 1] (values outside are clamped). */
    public static double toLinear(double c) {
        c = Math.min(1, Math.max(0, c));
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    /** The table lookup for an encoded sample in [0, 1] (an integer sample divided by 255 or 65535). */
    public static float decode(float c) {
        if (!(c > 0)) {
            return 0;
        }
        if (c >= 1) {
            return TABLE[65535];
        }
        return TABLE[Math.round(c * 65535f)];
    }

    /**
     * The sRGB opto-electronic transfer function (IEC 61966-2-1): V = 12.92·L for L ≤ 0.0031308,
     * else V = 1.055·L^(1/2.4) − 0.055, with L clamped to [0, 1] first.
     *
     * @param linear linear radiance (1 = display white)
     * @return the encoded value in [0, 1]; 0 for NaN and for negative input, 1 for L ≥ 1
     */
    public static double encode(double linear) {
        if (!(linear > 0)) {
            return 0;                        // NaN, negatives, −0
        }
        if (linear >= 1) {
            return 1;
        }
        double v = linear <= KNEE ? 12.92 * linear : 1.055 * Math.pow(linear, 1 / 2.4) - 0.055;
        return Math.min(1.0, v);            // 1.055 − 0.055 may round a hair above 1
    }
}
