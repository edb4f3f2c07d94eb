package dev.strahl.denoise.net;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorSpecies;

/**
 * {@link Conv3x3}'s path with the incubating Vector API: consecutive output pixels of a row
 * across the lanes, eight output channels by two vectors of pixels summed in 16 registers over
 * all input channels and taps (each input vector loaded once for the eight channels, each weight
 * broadcast once for the two vectors), then the ReLU and one store each. Every lane does the
 * scalar twin's fused multiply-adds in the scalar twin's order, so both give the same bits. A
 * row's last block ends at its last pixel (overlapping the block before when the width is no
 * multiple of two vectors); rows narrower than two vectors go to {@link Conv3x3#scalarPixels}.
 * Only loaded when the JVM has the module ({@link Conv3x3#LANES}).
 *
 * <p>Every vector a method is called on has its class checked against {@link #TYPE} first. On
 * JDK 17, C2 parses the Vector API's operations before it knows what class of vector they
 * return; a call on such a vector ({@code v.fma}, {@code r.intoArray}) is bound by the type
 * profile of the API's shared code, which other vector code in the JVM fills too (the BVH's
 * kernel: 128- and 256-bit floats). Seen with two classes, C2 compiles both and merges them, and
 * the accumulators are boxed at every multiply-add (54 MB per 32-channel 16x64 convolution,
 * 50x slower); with three, each store goes through a call. A failed class check would be a bug
 * of the JVM; C2 takes the check, which is never false, as proof of the class, binds the calls
 * from it and drops it.
 *
 * <p>Lanes: the platform's preferred width (512 bits with AVX-512), or 256 with
 * {@code -Dstrahl.denoise.lanes=256} (docs/denoising.md compares them). Eight channels by two
 * vectors measured 90-107 GFLOP/s per core on a 73- and a 128-channel layer, four by two 63-88.
 */
final class ConvLanes {
    private static final VectorSpecies<Float> S = "256".equals(System.getProperty("strahl.denoise.lanes"))
            ? FloatVector.SPECIES_256 : FloatVector.SPECIES_PREFERRED;
    private static final int L = S.length();
    /** The class of S's vectors. */
    private static final Class<?> TYPE = S.vectorType();

    private ConvLanes() {
    }

    /** Rows y0..y1 of every output channel. */
    static void rows(Conv3x3 conv, FeatureMap[] sources, FeatureMap dst, int y0, int y1) {
        int width = dst.width;
        for (int y = y0; y < y1; y++) {
            for (int o = 0; o < conv.outputs; o += 8) {
                int count = Math.min(8, conv.outputs - o);
                if (width < 2 * L) {
                    conv.scalarPixels(sources, dst, o, count, y, 0, width);
                    continue;
                }
                for (int x = 0; x < width; x += 2 * L) {
                    // The last block ends at the row's end, overlapping the one before: its pixels get the same bits again.
                    block(conv, sources, dst, o, count, y, Math.min(x, width - 2 * L));
                }
            }
        }
    }

    /** Output channels o..o+7 (the first {@code count} of them real) at pixels x..x+2L-1 of row y. */
    private static void block(Conv3x3 conv, FeatureMap[] sources, FeatureMap dst, int o, int count, int y, int x) {
        float[] b = conv.bias;
        FloatVector a00 = FloatVector.broadcast(S, b[o]);
        FloatVector a01 = FloatVector.broadcast(S, b[o]);
        FloatVector a10 = FloatVector.broadcast(S, count > 1 ? b[o + 1] : 0);
        FloatVector a11 = FloatVector.broadcast(S, count > 1 ? b[o + 1] : 0);
        FloatVector a20 = FloatVector.broadcast(S, count > 2 ? b[o + 2] : 0);
        FloatVector a21 = FloatVector.broadcast(S, count > 2 ? b[o + 2] : 0);
        FloatVector a30 = FloatVector.broadcast(S, count > 3 ? b[o + 3] : 0);
        FloatVector a31 = FloatVector.broadcast(S, count > 3 ? b[o + 3] : 0);
        FloatVector a40 = FloatVector.broadcast(S, count > 4 ? b[o + 4] : 0);
        FloatVector a41 = FloatVector.broadcast(S, count > 4 ? b[o + 4] : 0);
        FloatVector a50 = FloatVector.broadcast(S, count > 5 ? b[o + 5] : 0);
        FloatVector a51 = FloatVector.broadcast(S, count > 5 ? b[o + 5] : 0);
        FloatVector a60 = FloatVector.broadcast(S, count > 6 ? b[o + 6] : 0);
        FloatVector a61 = FloatVector.broadcast(S, count > 6 ? b[o + 6] : 0);
        FloatVector a70 = FloatVector.broadcast(S, count > 7 ? b[o + 7] : 0);
        FloatVector a71 = FloatVector.broadcast(S, count > 7 ? b[o + 7] : 0);
        float[] w = conv.blocked;
        int wi = (o / 8) * conv.inputs * 72;
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
                for (int kx = 0; kx < 3; kx++, wi += 8) {
                    FloatVector v0 = FloatVector.fromArray(S, d, r + kx);
                    FloatVector v1 = FloatVector.fromArray(S, d, r + kx + L);
                    if (v0.getClass() != TYPE || v1.getClass() != TYPE) {
                        throw notOwnClass();
                    }
                    FloatVector k = FloatVector.broadcast(S, w[wi]);
                    a00 = v0.fma(k, a00);
                    a01 = v1.fma(k, a01);
                    k = FloatVector.broadcast(S, w[wi + 1]);
                    a10 = v0.fma(k, a10);
                    a11 = v1.fma(k, a11);
                    k = FloatVector.broadcast(S, w[wi + 2]);
                    a20 = v0.fma(k, a20);
                    a21 = v1.fma(k, a21);
                    k = FloatVector.broadcast(S, w[wi + 3]);
                    a30 = v0.fma(k, a30);
                    a31 = v1.fma(k, a31);
                    k = FloatVector.broadcast(S, w[wi + 4]);
                    a40 = v0.fma(k, a40);
                    a41 = v1.fma(k, a41);
                    k = FloatVector.broadcast(S, w[wi + 5]);
                    a50 = v0.fma(k, a50);
                    a51 = v1.fma(k, a51);
                    k = FloatVector.broadcast(S, w[wi + 6]);
                    a60 = v0.fma(k, a60);
                    a61 = v1.fma(k, a61);
                    k = FloatVector.broadcast(S, w[wi + 7]);
                    a70 = v0.fma(k, a70);
                    a71 = v1.fma(k, a71);
                }
            }
        }
        // The stores written out: a helper taking vectors would box them when C2 does not inline it.
        FloatVector zero = FloatVector.zero(S), v;
        if (zero.getClass() != TYPE) {
            throw notOwnClass();
        }
        float[] out = dst.data;
        int at = dst.at(o, y, x);
        int p = dst.plane;
        if ((v = zero.max(a00)).getClass() != TYPE) {
            throw notOwnClass();
        }
        v.intoArray(out, at);
        if ((v = zero.max(a01)).getClass() != TYPE) {
            throw notOwnClass();
        }
        v.intoArray(out, at + L);
        if (count > 1) {
            if ((v = zero.max(a10)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + p);
            if ((v = zero.max(a11)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + p + L);
        }
        if (count > 2) {
            if ((v = zero.max(a20)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 2 * p);
            if ((v = zero.max(a21)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 2 * p + L);
        }
        if (count > 3) {
            if ((v = zero.max(a30)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 3 * p);
            if ((v = zero.max(a31)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 3 * p + L);
        }
        if (count > 4) {
            if ((v = zero.max(a40)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 4 * p);
            if ((v = zero.max(a41)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 4 * p + L);
        }
        if (count > 5) {
            if ((v = zero.max(a50)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 5 * p);
            if ((v = zero.max(a51)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 5 * p + L);
        }
        if (count > 6) {
            if ((v = zero.max(a60)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 6 * p);
            if ((v = zero.max(a61)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 6 * p + L);
        }
        if (count > 7) {
            if ((v = zero.max(a70)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 7 * p);
            if ((v = zero.max(a71)).getClass() != TYPE) {
                throw notOwnClass();
            }
            v.intoArray(out, at + 7 * p + L);
        }
    }

    private static IllegalStateException notOwnClass() {
        return new IllegalStateException("a vector of " + S + " is not of " + TYPE);
    }
}
