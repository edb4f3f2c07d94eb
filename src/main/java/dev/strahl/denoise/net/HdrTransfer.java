package dev.strahl.denoise.net;

/**
 * How OIDN's HDR networks see colour: the image is first scaled by an exposure that brings its
 * mean log luminance to middle grey ({@link #autoexposure}), then each channel goes through a
 * perceptually uniform ("PU") curve normalised so that half's largest value, 65504, maps to 1
 * ({@link #forward}); the network's output comes back through the inverse curve and the inverse
 * scale. The curve: linear near black, a power law in the middle, logarithmic above; its
 * constants are OIDN's (fitted to the PU encoding of Aydın et al. 2008).
 */
final class HdrTransfer {
    private static final float A = 1.41283765e+03f;
    private static final float B = 1.64593172e+00f;
    private static final float C = 4.31384981e-01f;
    private static final float D = -2.94139609e-03f;
    private static final float E = 1.92653254e-01f;
    private static final float F = 6.26026094e-03f;
    private static final float G = 9.98620152e-01f;
    private static final float Y0 = 1.57945760e-06f;
    private static final float Y1 = 3.22087631e-02f;
    private static final float X0 = 2.23151711e-03f;
    private static final float X1 = 3.70974749e-01f;
    /** The largest HDR value the curve is normalised to (half's largest finite value). */
    private static final float Y_MAX = 65504f;
    /** The curve's value at {@link #Y_MAX}, and its reciprocal: forward() maps [0, Y_MAX] to [0, 1]. */
    private static final float X_MAX = pu(Y_MAX);
    private static final float NORM = (float) (1.0 / X_MAX);

    /** Auto-exposure: the key (middle grey) the mean log luminance is brought to, bins of at most 16x16 pixels. */
    private static final float KEY = 0.18f;
    private static final int BIN = 16;
    private static final float EPS = 1e-8f;

    private HdrTransfer() {
    }

    private static float pu(float y) {
        if (y <= Y0) {
            return A * y;
        }
        if (y <= Y1) {
            return B * (float) Math.pow(y, C) + D;
        }
        return E * (float) Math.log(y + F) + G;
    }

    /** A scaled, sanitised (non-negative, finite) channel value to the network's input, in [0, ~5.8]. */
    static float forward(float y) {
        return pu(y) * NORM;
    }

    /** The network's output (sanitised: non-negative, finite) back to linear values. */
    static float inverse(float x) {
        float v = x * X_MAX;
        if (v <= X0) {
            return v / A;
        }
        if (v <= X1) {
            return (float) Math.pow((v - D) / B, 1.0f / C);
        }
        return (float) Math.exp((v - G) / E) - F;
    }

    /** NaN to 0, then clamped to [0, Float.MAX_VALUE] (as the network's inputs and outputs are). */
    static float sanitize(float v) {
        return v >= 0 ? Math.min(v, Float.MAX_VALUE) : 0;
    }

    /**
     * The exposure OIDN applies to HDR colour before the curve: the image is cut into bins of at
     * most 16x16 pixels; the mean luminance of each bin whose mean is above 1e-8 contributes
     * its log2; the scale brings 2^(mean of those) to 0.18. 1 if no bin is lit.
     *
     * @param rgb r, g, b per pixel, row by row
     */
    static float autoexposure(float[] rgb, int width, int height) {
        int binsY = (height + BIN - 1) / BIN;
        int binsX = (width + BIN - 1) / BIN;
        double sumLog = 0;
        int lit = 0;
        for (int i = 0; i < binsY; i++) {
            int y0 = (int) ((long) i * height / binsY);
            int y1 = (int) ((long) (i + 1) * height / binsY);
            for (int j = 0; j < binsX; j++) {
                int x0 = (int) ((long) j * width / binsX);
                int x1 = (int) ((long) (j + 1) * width / binsX);
                double sum = 0;
                for (int y = y0; y < y1; y++) {
                    for (int x = x0; x < x1; x++) {
                        int p = 3 * (y * width + x);
                        sum += luminance(sanitize(rgb[p]), sanitize(rgb[p + 1]), sanitize(rgb[p + 2]));
                    }
                }
                float mean = (float) (sum / ((y1 - y0) * (x1 - x0)));
                if (mean > EPS) {
                    sumLog += Math.log(mean) / Math.log(2);
                    lit++;
                }
            }
        }
        return lit > 0 ? (float) (KEY / Math.pow(2, sumLog / lit)) : 1f;
    }

    /** Rec. 709 luminance, OIDN's weights. */
    private static float luminance(float r, float g, float b) {
        return 0.212671f * r + 0.715160f * g + 0.072169f * b;
    }
}
