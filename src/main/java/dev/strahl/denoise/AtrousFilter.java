package dev.strahl.denoise;

import java.util.stream.IntStream;

/**
 * Edge-avoiding à-trous wavelet filtering guided by feature buffers and per-pixel variance: the
 * spatial filter of Dammertz et al. ("Edge-Avoiding À-Trous Wavelet Transform for fast Global
 * Illumination Filtering", HPG 2010) with the variance-guided luminance weight of Schied et al.
 * ("Spatiotemporal Variance-Guided Filtering", HPG 2017), on the radiance divided by the albedo.
 *
 * <p><b>Steps.</b>
 * <ol>
 *   <li>Demodulation: where an albedo is given, each channel is divided by max(albedo, {@value #MIN_ALBEDO});
 *       the variance by the square of that factor's luminance. Textures and colour edges thus
 *       leave the filtered signal (it is the light arriving, smooth over most surfaces) and come
 *       back unblurred when the result is multiplied by the same factor.</li>
 *   <li>{@value #LEVELS} passes of a 5×5 B3-spline kernel (1/16, 1/4, 3/8, 1/4, 1/16 per axis)
 *       whose taps lie 1, 2, 4, 8, 16 pixels apart, each tap weighted by
 *       <ul>
 *         <li>normals: max(0, n·n')^{@value #NORMAL_POWER};</li>
 *         <li>depth: exp(−|z − z'| / ({@value #SIGMA_DEPTH} · |∇z| · d + 10⁻³ z)), with |∇z| the
 *             larger of both pixels' gradients (each the smaller one-sided difference per axis) and
 *             d the tap's distance in pixels (|Δx| + |Δy|);</li>
 *         <li>albedo: exp(−|a − a'|² / {@value #SIGMA_ALBEDO}²);</li>
 *         <li>luminance: exp(−|l − l'| / ({@value #SIGMA_LUMINANCE} · √(v + v') + ε)), v and v' the 3×3 Gaussian
 *             of the variance at both pixels;</li>
 *       </ul>
 *       and the variance carried along as Σ w² var / (Σ w)², so that each pass sees how much noise
 *       is left.</li>
 *   <li>Remodulation by the same factor.</li>
 * </ol>
 * Pixels whose camera ray left the scene (normal zero) are filtered only with each other. The
 * weights are normalised and symmetric (what a pixel takes from a neighbour, the neighbour takes
 * from it), so a region keeps its mean: the filter blurs noise, it does not shift colours and does
 * not lose the energy of bright outliers. Without a variance (all zero), it is estimated from each pixel's 3×3
 * neighbourhood.
 *
 * <p>Rows are filtered in parallel on the common fork-join pool; every pixel's result depends
 * only on the input, so it is the same bits on any number of threads. The passes allocate their
 * buffers once; the per-pixel loops allocate nothing.
 */
public final class AtrousFilter {
    static final int LEVELS = 5;
    static final float MIN_ALBEDO = 0.01f;
    static final int NORMAL_POWER = 128;
    static final float SIGMA_DEPTH = 1f;
    static final float SIGMA_ALBEDO = 0.1f;
    static final float SIGMA_LUMINANCE = 4f;
    private static final float[] KERNEL = {1 / 16f, 1 / 4f, 3 / 8f, 1 / 4f, 1 / 16f};

    private final int w;
    private final int h;
    private final float[] nx, ny, nz, depth, gradient, ar, ag, ab;
    private final boolean[] miss;
    private final boolean hasNormal, hasDepth, hasAlbedo;

    /**
     * The guides of one image.
     *
     * @param width  width in pixels
     * @param height height in pixels
     * @param albedo interleaved r, g, b per pixel, or null
     * @param normal interleaved x, y, z per pixel, or null
     * @param depthRgb depth in the first of three interleaved channels per pixel, or null
     */
    public AtrousFilter(int width, int height, float[] albedo, float[] normal, float[] depthRgb) {
        this.w = width;
        this.h = height;
        int n = width * height;
        hasNormal = normal != null;
        hasDepth = depthRgb != null;
        hasAlbedo = albedo != null;
        nx = new float[n];
        ny = new float[n];
        nz = new float[n];
        miss = new boolean[n];
        depth = new float[n];
        gradient = new float[n];
        ar = new float[n];
        ag = new float[n];
        ab = new float[n];
        for (int p = 0; p < n; p++) {
            if (hasNormal) {
                float x = normal[3 * p], y = normal[3 * p + 1], z = normal[3 * p + 2];
                float len = (float) Math.sqrt(x * x + y * y + z * z);
                if (len > 1e-3f) {
                    nx[p] = x / len;
                    ny[p] = y / len;
                    nz[p] = z / len;
                } else {
                    miss[p] = true;
                }
            }
            if (hasAlbedo) {
                ar[p] = albedo[3 * p];
                ag[p] = albedo[3 * p + 1];
                ab[p] = albedo[3 * p + 2];
            }
            if (hasDepth) {
                depth[p] = depthRgb[3 * p];
            }
        }
        if (hasDepth) {
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int p = y * w + x;
                    float gx = Math.min(x > 0 ? Math.abs(depth[p] - depth[p - 1]) : Float.MAX_VALUE,
                            x < w - 1 ? Math.abs(depth[p + 1] - depth[p]) : Float.MAX_VALUE);
                    float gy = Math.min(y > 0 ? Math.abs(depth[p] - depth[p - w]) : Float.MAX_VALUE,
                            y < h - 1 ? Math.abs(depth[p + w] - depth[p]) : Float.MAX_VALUE);
                    gradient[p] = Math.max(gx == Float.MAX_VALUE ? 0 : gx, gy == Float.MAX_VALUE ? 0 : gy);
                }
            }
        }
    }

    /**
     * Filters an image.
     *
     * @param rgb      interleaved r, g, b per pixel (not changed)
     * @param variance the variance of each pixel's mean luminance, one value per pixel, or null
     *                 to estimate it from the image
     * @return the filtered image, interleaved r, g, b
     */
    public float[] filter(float[] rgb, float[] variance) {
        int n = w * h;
        float[] fr = new float[n], fg = new float[n], fb = new float[n];
        float[] cr = new float[n], cg = new float[n], cb = new float[n], var = new float[n];
        boolean estimate = variance == null || allZero(variance);
        for (int p = 0; p < n; p++) {
            float mr = 1, mg = 1, mb = 1;
            if (hasAlbedo) {
                mr = Math.max(ar[p], MIN_ALBEDO);
                mg = Math.max(ag[p], MIN_ALBEDO);
                mb = Math.max(ab[p], MIN_ALBEDO);
            }
            fr[p] = mr;
            fg[p] = mg;
            fb[p] = mb;
            cr[p] = rgb[3 * p] / mr;
            cg[p] = rgb[3 * p + 1] / mg;
            cb[p] = rgb[3 * p + 2] / mb;
            if (!estimate) {
                float ml = luminance(mr, mg, mb);
                var[p] = variance[p] / (ml * ml);
            }
        }
        if (estimate) {
            estimateVariance(cr, cg, cb, var);
        }
        float[] or = new float[n], og = new float[n], ob = new float[n], ovar = new float[n];
        float[] smooth = new float[n];
        float[] lum = new float[n];
        float[] weights = new float[25 * n];
        float[] total = new float[n];
        for (int level = 0; level < LEVELS; level++) {
            blurVariance(var, smooth);
            for (int p = 0; p < n; p++) {
                lum[p] = luminance(cr[p], cg[p], cb[p]);
            }
            int step = 1 << level;
            float[] inR = cr, inG = cg, inB = cb, inV = var, outR = or, outG = og, outB = ob, outV = ovar;
            IntStream.range(0, h).parallel().forEach(y -> weigh(y, step, lum, smooth, weights, total));
            IntStream.range(0, h).parallel().forEach(y -> gather(y, step, inR, inG, inB, inV, weights, total, outR, outG, outB, outV));
            float[] t;
            t = cr; cr = or; or = t;
            t = cg; cg = og; og = t;
            t = cb; cb = ob; ob = t;
            t = var; var = ovar; ovar = t;
        }
        float[] out = new float[3 * n];
        for (int p = 0; p < n; p++) {
            out[3 * p] = cr[p] * fr[p];
            out[3 * p + 1] = cg[p] * fg[p];
            out[3 * p + 2] = cb[p] * fb[p];
        }
        return out;
    }

    /**
     * The weights of every tap around the pixels of row y, centred there, into
     * {@code weights[25 p + k]} (k = 5 (j + 2) + (i + 2); zero outside the image), and their sum
     * into {@code total[p]}.
     */
    private void weigh(int y, int step, float[] lum, float[] smoothVar, float[] weights, float[] total) {
        for (int x = 0; x < w; x++) {
            int p = y * w + x;
            float l = lum[p];
            float lumScale = 1f / (SIGMA_LUMINANCE * (float) Math.sqrt(Math.max(0f, smoothVar[p])) + 1e-6f);
            float zFloor = 1e-3f * depth[p] + 1e-6f;
            float gradP = gradient[p];
            boolean m = miss[p];
            float pnx = nx[p], pny = ny[p], pnz = nz[p], par = ar[p], pag = ag[p], pab = ab[p], pz = depth[p];
            float sw = 0;
            int k = 25 * p;
            for (int j = -2; j <= 2; j++) {
                int yy = y + j * step;
                float kj = KERNEL[j + 2];
                for (int i = -2; i <= 2; i++, k++) {
                    int xx = x + i * step;
                    weights[k] = 0;
                    if (xx < 0 || xx >= w || yy < 0 || yy >= h) {
                        continue;
                    }
                    int q = yy * w + xx;
                    float wgt = kj * KERNEL[i + 2];
                    if (q != p) {
                        if (hasNormal) {
                            if (m != miss[q]) {
                                continue;
                            }
                            if (!m) {
                                float d = pnx * nx[q] + pny * ny[q] + pnz * nz[q];
                                if (d <= 0) {
                                    continue;
                                }
                                for (int r = 0; r < 7; r++) {    // d^128
                                    d *= d;
                                }
                                wgt *= d;
                            }
                        }
                        float e = Math.abs(l - lum[q]) * lumScale;
                        if (hasDepth) {
                            float zTolerance = SIGMA_DEPTH * Math.max(gradP, gradient[q]) * step * (Math.abs(i) + Math.abs(j));
                            e += Math.abs(pz - depth[q]) / (zTolerance + Math.max(zFloor, 1e-3f * depth[q] + 1e-6f));
                        }
                        if (hasAlbedo) {
                            float dr = par - ar[q], dg = pag - ag[q], db = pab - ab[q];
                            e += (dr * dr + dg * dg + db * db) * (1 / (SIGMA_ALBEDO * SIGMA_ALBEDO));
                        }
                        if (e > 20) {
                            continue;
                        }
                        wgt *= expNeg(e);
                    }
                    weights[k] = wgt;
                    sw += wgt;
                }
            }
            total[p] = sw;                                  // > 0: the centre tap always counts
        }
    }

    /** Row y of one pass: each pixel the weighted mean of its taps, the variance carried along as Σ w² v / (Σ w)². */
    private void gather(int y, int step, float[] inR, float[] inG, float[] inB, float[] inV, float[] weights, float[] total,
                         float[] outR, float[] outG, float[] outB, float[] outV) {
        for (int x = 0; x < w; x++) {
            int p = y * w + x;
            double sr = 0, sg = 0, sb = 0, sv = 0;
            int k = 0;
            for (int j = -2; j <= 2; j++) {
                int yy = y + j * step;
                for (int i = -2; i <= 2; i++, k++) {
                    int xx = x + i * step;
                    if (xx < 0 || xx >= w || yy < 0 || yy >= h) {
                        continue;
                    }
                    int q = yy * w + xx;
                    float share = weights[25 * p + k] / total[p];
                    if (share == 0) {
                        continue;
                    }
                    sr += share * inR[q];
                    sg += share * inG[q];
                    sb += share * inB[q];
                    sv += (double) share * share * inV[q];
                }
            }
            outR[p] = (float) sr;
            outG[p] = (float) sg;
            outB[p] = (float) sb;
            outV[p] = (float) sv;
        }
    }

    /**
     * e^−x for x in [0, 20], to about 10⁻⁵ relative: 2^(−x·log2 e) split into an integer power
     * (put into the float's exponent) and a quartic for 2^f on [0, 1). Math.exp costs several times
     * more, and the filter takes 25 weights per pixel and pass.
     */
    static float expNeg(float x) {
        float t = -x * 1.4426950f;
        float fi = (float) Math.floor(t);
        float f = t - fi;
        float p = 1 + f * (0.6931472f + f * (0.2402265f + f * (0.0555041f + f * 0.0096181f)));
        return Float.intBitsToFloat(Float.floatToRawIntBits(p) + ((int) fi << 23));
    }

    /** 3×3 Gaussian (1 2 1) of the variance, the luminance weight's noise level (Schied et al. 2017). */
    private void blurVariance(float[] var, float[] out) {
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double s = 0, sw = 0;
                for (int j = -1; j <= 1; j++) {
                    int yy = y + j;
                    if (yy < 0 || yy >= h) {
                        continue;
                    }
                    for (int i = -1; i <= 1; i++) {
                        int xx = x + i;
                        if (xx < 0 || xx >= w) {
                            continue;
                        }
                        double k = (2 - Math.abs(i)) * (2 - Math.abs(j));
                        s += k * var[yy * w + xx];
                        sw += k;
                    }
                }
                out[y * w + x] = (float) (s / sw);
            }
        }
    }

    /** Without a measured variance: the luminance variance over each pixel's 3×3 neighbourhood. */
    private void estimateVariance(float[] r, float[] g, float[] b, float[] out) {
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double s = 0, s2 = 0;
                int count = 0;
                for (int j = -1; j <= 1; j++) {
                    for (int i = -1; i <= 1; i++) {
                        int xx = x + i, yy = y + j;
                        if (xx >= 0 && xx < w && yy >= 0 && yy < h) {
                            int q = yy * w + xx;
                            double l = luminance(r[q], g[q], b[q]);
                            s += l;
                            s2 += l * l;
                            count++;
                        }
                    }
                }
                double mean = s / count;
                out[y * w + x] = (float) Math.max(0, s2 / count - mean * mean);
            }
        }
    }

    private static boolean allZero(float[] a) {
        for (float v : a) {
            if (v != 0) {
                return false;
            }
        }
        return true;
    }

    static float luminance(float r, float g, float b) {
        return 0.2126f * r + 0.7152f * g + 0.0722f * b;
    }
}
