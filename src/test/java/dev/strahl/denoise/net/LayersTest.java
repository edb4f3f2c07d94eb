package dev.strahl.denoise.net;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The network's layers against plain loops written from their definitions. */
class LayersTest {

    static FeatureMap random(int channels, int h, int w, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        FeatureMap m = new FeatureMap(channels, h, w);
        for (int c = 0; c < channels; c++) {
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    m.set(c, y, x, (float) r.nextDouble(-1, 2));
                }
            }
        }
        return m;
    }

    static Conv3x3 randomConv(int in, int out, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        float[] w = new float[out * in * 9];
        float[] b = new float[out];
        for (int i = 0; i < w.length; i++) {
            w[i] = (float) r.nextDouble(-0.5, 0.5);
        }
        for (int i = 0; i < b.length; i++) {
            b[i] = (float) r.nextDouble(-0.2, 0.2);
        }
        return new Conv3x3("test", in, out, w, b);
    }

    /**
     * The definition in double precision: bias + the sum over input channels c and taps of
     * w[o][c][ky][kx] · in[c][y + ky - 1][x + kx - 1] (zero outside), then max(0, ·).
     */
    static double reference(Conv3x3 conv, FeatureMap[] sources, int o, int y, int x) {
        double sum = conv.bias[o];
        int c = 0;
        for (FeatureMap s : sources) {
            for (int sc = 0; sc < s.channels; sc++, c++) {
                for (int ky = 0; ky < 3; ky++) {
                    for (int kx = 0; kx < 3; kx++) {
                        int yy = y + ky - 1;
                        int xx = x + kx - 1;
                        if (yy >= 0 && yy < s.height && xx >= 0 && xx < s.width) {
                            sum += (double) conv.weights[((o * conv.inputs + c) * 3 + ky) * 3 + kx] * s.get(sc, yy, xx);
                        }
                    }
                }
            }
        }
        return Math.max(sum, 0);
    }

    /** Sizes that fill whole vectors, end raggedly, or have no whole vector at all; 3 outputs (a part block). */
    @ParameterizedTest(name = "{0}+{1} -> {2} channels, {3}x{4}")
    @CsvSource({"9, 0, 32, 40, 5", "16, 16, 20, 37, 6", "5, 3, 3, 7, 9", "32, 0, 64, 64, 3", "3, 0, 8, 1, 4", "7, 2, 11, 600, 3"})
    void convolutionFollowsItsDefinitionOnBothPaths(int in1, int in2, int out, int w, int h) {
        FeatureMap[] sources = in2 == 0 ? new FeatureMap[] {random(in1, h, w, 1)}
                : new FeatureMap[] {random(in1, h, w, 1), random(in2, h, w, 2)};
        Conv3x3 conv = randomConv(in1 + in2, out, 3);
        FeatureMap scalar = new FeatureMap(out, h, w);
        conv.apply(false, sources, scalar);
        for (int o = 0; o < out; o++) {
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    assertThat((double) scalar.get(o, y, x)).as("o %d y %d x %d", o, y, x).isCloseTo(reference(conv, sources, o, y, x), within(2e-5));
                }
            }
        }
        assertThat(scalar.data).as("the frame stays zero").satisfies(d -> {
            for (int o = 0; o < out; o++) {
                for (int x = -1; x <= w; x++) {
                    assertThat(d[scalar.at(o, -1, x)]).isZero();
                    assertThat(d[scalar.at(o, h, x)]).isZero();
                }
            }
        });
        if (Conv3x3.LANES) {                           // the tests run with the Vector API module
            FeatureMap lanes = new FeatureMap(out, h, w);
            conv.apply(true, sources, lanes);
            assertThat(lanes.data).as("the Vector API path gives the scalar twin's bits").isEqualTo(scalar.data);
        }
    }

    @Test
    void theTestsRunBothPaths() {
        assertThat(Conv3x3.LANES).as("surefire adds jdk.incubator.vector").isTrue();
    }

    @Test
    void convolutionRefusesMismatchedShapes() {
        Conv3x3 conv = randomConv(4, 8, 1);
        assertThatThrownBy(() -> conv.apply(random(3, 4, 4, 1))).hasMessageContaining("3 -> 8 channels, expected 4 -> 8");
        assertThatThrownBy(() -> conv.apply(random(2, 4, 4, 1), random(2, 4, 6, 1))).hasMessageContaining("input 6x4");
        assertThatThrownBy(() -> new Conv3x3("x", 4, 8, new float[10], new float[8])).hasMessageContaining("10 weights");
    }

    @Test
    void poolingTakesTheLargestOfEach2x2Block() {
        FeatureMap src = random(3, 6, 10, 4);
        FeatureMap dst = Resample.pool(src);
        assertThat(dst.channels).isEqualTo(3);
        assertThat(dst.height).isEqualTo(3);
        assertThat(dst.width).isEqualTo(5);
        for (int c = 0; c < 3; c++) {
            for (int y = 0; y < 3; y++) {
                for (int x = 0; x < 5; x++) {
                    float max = Float.NEGATIVE_INFINITY;
                    for (int k = 0; k < 4; k++) {
                        max = Math.max(max, src.get(c, 2 * y + k / 2, 2 * x + k % 2));
                    }
                    assertThat(dst.get(c, y, x)).isEqualTo(max);
                }
            }
        }
        assertThatThrownBy(() -> Resample.pool(random(1, 3, 4, 1))).hasMessageContaining("even size");
    }

    @Test
    void upsamplingRepeatsEachPixelIntoA2x2Block() {
        FeatureMap src = random(2, 3, 5, 5);
        FeatureMap dst = Resample.upsample(src);
        assertThat(dst.height).isEqualTo(6);
        assertThat(dst.width).isEqualTo(10);
        for (int c = 0; c < 2; c++) {
            for (int y = 0; y < 6; y++) {
                for (int x = 0; x < 10; x++) {
                    assertThat(dst.get(c, y, x)).isEqualTo(src.get(c, y / 2, x / 2));
                }
            }
        }
        assertThat(Resample.pool(dst).data).as("pooling undoes it").isEqualTo(src.data);
    }

    @Test
    void puCurveIsNormalisedMonotoneAndInvertible() {
        assertThat(HdrTransfer.forward(0)).isZero();
        assertThat(HdrTransfer.forward(65504f)).isCloseTo(1f, within(1e-6f));
        float previous = -1;
        for (double y = 1e-9; y < 1e6; y *= 1.01) {
            float x = HdrTransfer.forward((float) y);
            assertThat(x).as("monotone at %g", y).isGreaterThanOrEqualTo(previous);
            previous = x;
            assertThat((double) HdrTransfer.inverse(x)).as("round trip at %g", y).isCloseTo(y, within(2e-5 * y + 1e-9));
        }
        for (float knee : new float[] {1.57945760e-06f, 3.22087631e-02f}) {   // the pieces meet: no jump at the knees
            assertThat(HdrTransfer.forward(Math.nextUp(knee)) - HdrTransfer.forward(knee)).isLessThan(1e-6f);
        }
    }

    @Test
    void sanitizingMakesEveryValueFiniteAndNonNegative() {
        assertThat(HdrTransfer.sanitize(Float.NaN)).isZero();
        assertThat(HdrTransfer.sanitize(-3)).isZero();
        assertThat(HdrTransfer.sanitize(Float.POSITIVE_INFINITY)).isEqualTo(Float.MAX_VALUE);
        assertThat(HdrTransfer.sanitize(2.5f)).isEqualTo(2.5f);
        assertThat(HdrTransfer.forward(Float.MAX_VALUE)).isFinite();
    }

    @Test
    void autoexposureBringsTheMeanLogLuminanceToMiddleGrey() {
        int w = 40, h = 20;                            // 3 x 2 bins of at most 16x16 pixels
        float[] grey = new float[3 * w * h];
        java.util.Arrays.fill(grey, 0.5f);
        assertThat(HdrTransfer.autoexposure(grey, w, h)).isCloseTo(0.36f, within(1e-5f));
        assertThat(HdrTransfer.autoexposure(new float[3 * w * h], w, h)).as("black").isEqualTo(1f);
        float[] half = grey.clone();                  // the left bins (x < 13) at 2, the rest at 0.5: log2 means 1, -1
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < 13; x++) {
                for (int c = 0; c < 3; c++) {
                    half[3 * (y * w + x) + c] = 2;
                }
            }
        }
        assertThat(HdrTransfer.autoexposure(half, w, h)).isCloseTo((float) (0.18 / Math.pow(2, -1.0 / 3)), within(1e-5f));
        half[0] = Float.NaN;                          // sanitised: a NaN counts as 0
        half[3] = Float.POSITIVE_INFINITY;            // and infinity as the largest float
        assertThat(HdrTransfer.autoexposure(half, w, h)).isFinite().isPositive();
    }
}
