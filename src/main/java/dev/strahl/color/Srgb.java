package dev.strahl.texture;

/**
 * The sRGB transfer function undone by table (IEC 61966-2-1): linear = c / 12.92 for c ≤ 0.04045,
 * ((c + 0.055) / 1.055)^2.4 above. One table of 65536 entries serves 8- and 16-bit images alike: a
 * 16-bit sample k/65535 is entry k, an 8-bit sample k/255 is entry 257·k (exactly the same value).
 */
public final class Srgb {
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
}
