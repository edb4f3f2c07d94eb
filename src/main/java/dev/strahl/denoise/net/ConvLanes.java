package dev.strahl.denoise.net;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorSpecies;

/**
 * {@link Conv3x3}'s path with the incubating Vector API: consecutive output pixels of a row
 * across the lanes, four output channels by two vectors of pixels summed in registers over all
 * input channels and taps (weights broadcast, inputs loaded at the three column offsets), then
 * the ReLU and one store. Each lane does the scalar twin's fused multiply-adds in the scalar
 * twin's order, so both give the same bits; pixels at the end of a row that fill no vector go to
 * {@link Conv3x3#scalarPixels}. Only loaded when the JVM has the module ({@link Conv3x3#LANES}).
 *
 * <p>Lanes: the platform's preferred width (512 bits with AVX-512), or 256 with
 * {@code -Dstrahl.denoise.lanes=256} (docs/denoising.md compares them).
 */
final class ConvLanes {
    private static final VectorSpecies<Float> S = "256".equals(System.getProperty("strahl.denoise.lanes"))
            ? FloatVector.SPECIES_256 : FloatVector.SPECIES_PREFERRED;
    private static final int L = S.length();

    private ConvLanes() {
    }

    /** Rows y0..y1 of every output channel. */
    static void rows(Conv3x3 conv, FeatureMap[] sources, FeatureMap dst, int y0, int y1) {
        int width = dst.width;
        for (int y = y0; y < y1; y++) {
            for (int o = 0; o < conv.outputs; o += 4) {
                int count = Math.min(4, conv.outputs - o);
                int x = 0;
                for (; x + 2 * L <= width; x += 2 * L) {
                    two(conv, sources, dst, o, count, y, x);
                }
                if (x < width) {
                    conv.scalarPixels(sources, dst, o, count, y, x, width);
                }
            }
        }
    }

    /** Output channels o..o+3 (count of them real) at pixels x..x+2L-1 of row y. */
    private static void two(Conv3x3 conv, FeatureMap[] sources, FeatureMap dst, int o, int count, int y, int x) {
        float b0 = conv.bias[o];
        float b1 = count > 1 ? conv.bias[o + 1] : 0f;
        float b2 = count > 2 ? conv.bias[o + 2] : 0f;
        float b3 = count > 3 ? conv.bias[o + 3] : 0f;
        FloatVector a00 = FloatVector.broadcast(S, b0);
        FloatVector a01 = FloatVector.broadcast(S, b0);
        FloatVector a10 = FloatVector.broadcast(S, b1);
        FloatVector a11 = FloatVector.broadcast(S, b1);
        FloatVector a20 = FloatVector.broadcast(S, b2);
        FloatVector a21 = FloatVector.broadcast(S, b2);
        FloatVector a30 = FloatVector.broadcast(S, b3);
        FloatVector a31 = FloatVector.broadcast(S, b3);
        float[] w = conv.blocked;
        int wi = (o / 4) * conv.inputs * 36;
        // One loop over all input channels (a loop per source would keep C2 from holding the sums in registers).
        int source = 0;
        FeatureMap s = sources[0];
        int next = s.channels;
        float[] d = s.data;
        int stride = s.stride;
        int row = s.at(0, y - 1, x - 1);
        for (int c = 0; c < conv.inputs; c++, row += s.plane) {
            if (c == next) {                        // the next concatenated source
                s = sources[++source];
                next += s.channels;
                d = s.data;
                stride = s.stride;
                row = s.at(0, y - 1, x - 1);
            }
            for (int ky = 0; ky < 3; ky++) {
                int r = row + ky * stride;
                for (int kx = 0; kx < 3; kx++, wi += 4) {
                    FloatVector v0 = FloatVector.fromArray(S, d, r + kx);
                    FloatVector v1 = FloatVector.fromArray(S, d, r + kx + L);
                    FloatVector w0 = FloatVector.broadcast(S, w[wi]);
                    FloatVector w1 = FloatVector.broadcast(S, w[wi + 1]);
                    FloatVector w2 = FloatVector.broadcast(S, w[wi + 2]);
                    FloatVector w3 = FloatVector.broadcast(S, w[wi + 3]);
                    a00 = v0.fma(w0, a00);
                    a01 = v1.fma(w0, a01);
                    a10 = v0.fma(w1, a10);
                    a11 = v1.fma(w1, a11);
                    a20 = v0.fma(w2, a20);
                    a21 = v1.fma(w2, a21);
                    a30 = v0.fma(w3, a30);
                    a31 = v1.fma(w3, a31);
                }
            }
        }
        float[] out = dst.data;
        int at = dst.at(o, y, x);
        a00.max(0f).intoArray(out, at);
        a01.max(0f).intoArray(out, at + L);
        if (count > 1) {
            a10.max(0f).intoArray(out, at + dst.plane);
            a11.max(0f).intoArray(out, at + dst.plane + L);
        }
        if (count > 2) {
            a20.max(0f).intoArray(out, at + 2 * dst.plane);
            a21.max(0f).intoArray(out, at + 2 * dst.plane + L);
        }
        if (count > 3) {
            a30.max(0f).intoArray(out, at + 3 * dst.plane);
            a31.max(0f).intoArray(out, at + 3 * dst.plane + L);
        }
    }
}
