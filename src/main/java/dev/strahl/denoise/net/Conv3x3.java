package dev.strahl.denoise.net;

import java.util.Arrays;
import java.util.stream.IntStream;

/**
 * A 3x3 convolution with stride 1, zero padding and a ReLU, over one feature map or the
 * concatenation of several (their channels one after the other, as the U-Net's skip connections
 * join them). Each output value is the bias, then for every input channel c, row ky and column kx
 * in that order one fused multiply-add of weight and input — the same operations in the same
 * order on both paths and any thread count, so the result is the same bits everywhere:
 * <ul>
 *   <li>{@link ConvLanes} (with the Vector API, {@code --add-modules jdk.incubator.vector}): output
 *       pixels across the lanes, eight output channels by two vectors of pixels summed in
 *       registers;</li>
 *   <li>the scalar twin here: per strip of about 512 pixels (a piece of a row, or several rows of
 *       a small map), all output channels' sums in arrays, updated three taps at a time by loops
 *       that HotSpot vectorizes itself (every array indexed alike, so it can: the three shifted
 *       input rows are copied first).</li>
 * </ul>
 * Rows are split into bands on the common fork-join pool; a band's values depend only on the
 * input, never on which thread computes it.
 */
final class Conv3x3 {
    /** The Vector API is there and not switched off with {@code -Dstrahl.simd=false}. */
    static final boolean LANES = ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent()
            && !"false".equals(System.getProperty("strahl.simd"));
    /** Longest row strip of the scalar path (its sums: outputs x strip floats, in the L2 cache). */
    private static final int STRIP = 512;

    final String name;
    final int inputs;
    final int outputs;
    /** Weights in OIDN's order [output][input][ky][kx]. */
    final float[] weights;
    /** The same, blocked for {@link ConvLanes}: [output / 8][input][ky][kx][output % 8], zeros past the last output. */
    final float[] blocked;
    final float[] bias;

    Conv3x3(String name, int inputs, int outputs, float[] weights, float[] bias) {
        if (weights.length != outputs * inputs * 9 || bias.length != outputs) {
            throw new IllegalArgumentException(name + ": " + weights.length + " weights and " + bias.length + " biases for "
                    + inputs + " -> " + outputs + " channels");
        }
        this.name = name;
        this.inputs = inputs;
        this.outputs = outputs;
        this.weights = weights.clone();
        this.bias = bias.clone();
        blocked = new float[(outputs + 7) / 8 * inputs * 9 * 8];
        for (int o = 0; o < outputs; o++) {
            for (int i = 0; i < inputs * 9; i++) {
                blocked[((o / 8) * inputs * 9 + i) * 8 + o % 8] = weights[o * inputs * 9 + i];
            }
        }
    }

    /** The convolution of the sources' channels, one after the other, into a new map of the same size. */
    FeatureMap apply(FeatureMap... sources) {
        FeatureMap dst = new FeatureMap(outputs, sources[0].height, sources[0].width);
        apply(LANES, sources, dst);
        return dst;
    }

    void apply(boolean lanes, FeatureMap[] sources, FeatureMap dst) {
        int channels = 0;
        for (FeatureMap s : sources) {
            if (s.height != dst.height || s.width != dst.width) {
                throw new IllegalArgumentException(name + ": input " + s.width + "x" + s.height + ", output " + dst.width + "x" + dst.height);
            }
            channels += s.channels;
        }
        if (channels != inputs || dst.channels != outputs) {
            throw new IllegalArgumentException(name + ": " + channels + " -> " + dst.channels + " channels, expected " + inputs + " -> " + outputs);
        }
        int h = dst.height;
        // Bands of rows, at least 2048 pixels each (small maps are not worth a thread), 8 per processor at most.
        int bands = (int) Math.max(1, Math.min(Math.min(h, 8 * Runtime.getRuntime().availableProcessors()),
                (long) h * dst.width / 2048));
        IntStream.range(0, bands).parallel().forEach(b -> {
            int y0 = (int) ((long) b * h / bands);
            int y1 = (int) ((long) (b + 1) * h / bands);
            if (lanes) {
                ConvLanes.rows(this, sources, dst, y0, y1);
            } else {
                scalarRows(sources, dst, y0, y1);
            }
        });
    }

    /**
     * The scalar twin: rows y0..y1 in strips of about {@link #STRIP} pixels: a piece of one row
     * if the map is wider, else several whole rows one after the other (long loops vectorize
     * well; short ones also spoil the code HotSpot compiles for the long ones).
     */
    void scalarRows(FeatureMap[] sources, FeatureMap dst, int y0, int y1) {
        int piece = Math.min(STRIP, dst.width);
        int rowsPerStrip = Math.max(1, Math.min(STRIP / dst.width, y1 - y0));
        int strip = piece * rowsPerStrip;
        float[][] sums = new float[outputs][strip];
        float[] left = new float[strip];
        float[] centre = new float[strip];
        float[] right = new float[strip];
        for (int y = y0; y < y1; y += rowsPerStrip) {
            int rows = Math.min(rowsPerStrip, y1 - y);
            for (int x0 = 0; x0 < dst.width; x0 += piece) {
                int n = Math.min(piece, dst.width - x0);
                int total = rows * n;
                for (int o = 0; o < outputs; o++) {
                    Arrays.fill(sums[o], 0, total, bias[o]);
                }
                int c = 0;
                for (FeatureMap s : sources) {
                    for (int sc = 0; sc < s.channels; sc++, c++) {
                        for (int ky = 0; ky < 3; ky++) {
                            for (int r = 0; r < rows; r++) {
                                int at = s.at(sc, y + r + ky - 1, x0 - 1);
                                System.arraycopy(s.data, at, left, r * n, n);
                                System.arraycopy(s.data, at + 1, centre, r * n, n);
                                System.arraycopy(s.data, at + 2, right, r * n, n);
                            }
                            for (int o = 0; o < outputs; o++) {
                                int w = ((o * inputs + c) * 3 + ky) * 3;
                                taps(sums[o], left, centre, right, weights[w], weights[w + 1], weights[w + 2], total);
                            }
                        }
                    }
                }
                for (int o = 0; o < outputs; o++) {
                    float[] sum = sums[o];
                    for (int r = 0; r < rows; r++) {
                        int at = dst.at(o, y + r, x0);
                        for (int x = 0; x < n; x++) {
                            dst.data[at + x] = Math.max(sum[r * n + x], 0f);
                        }
                    }
                }
            }
        }
    }

    /** One row of one input channel's three taps: every array indexed by x alone, so HotSpot vectorizes it. */
    private static void taps(float[] sum, float[] left, float[] centre, float[] right, float w0, float w1, float w2, int n) {
        for (int x = 0; x < n; x++) {
            sum[x] = Math.fma(w2, right[x], Math.fma(w1, centre[x], Math.fma(w0, left[x], sum[x])));
        }
    }

    /** Output channels o..o+count-1 at pixels x0..x1-1 of row y, one at a time (the lanes path's ragged end). */
    void scalarPixels(FeatureMap[] sources, FeatureMap dst, int o0, int count, int y, int x0, int x1) {
        for (int o = o0; o < o0 + count; o++) {
            for (int x = x0; x < x1; x++) {
                float sum = bias[o];
                int c = 0;
                for (FeatureMap s : sources) {
                    for (int sc = 0; sc < s.channels; sc++, c++) {
                        int w = (o * inputs + c) * 9;
                        for (int ky = 0; ky < 3; ky++) {
                            int at = s.at(sc, y + ky - 1, x - 1);
                            sum = Math.fma(weights[w + 3 * ky], s.data[at], sum);
                            sum = Math.fma(weights[w + 3 * ky + 1], s.data[at + 1], sum);
                            sum = Math.fma(weights[w + 3 * ky + 2], s.data[at + 2], sum);
                        }
                    }
                }
                dst.set(o, y, x, Math.max(sum, 0f));
            }
        }
    }
}
