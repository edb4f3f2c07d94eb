package dev.strahl.color;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Image;
import java.awt.image.BufferedImage;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class DisplayEncodingTest {

    /** The sRGB EOTF (IEC 61966-2-1), the inverse of the encoding: an independent check of it. */
    private static double srgbDecode(double v) {
        return v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4);
    }

    @Test
    void encodeHasTheStandardsEndpointsAndMidValues() {
        assertThat(Srgb.encode(0)).isEqualTo(0);
        assertThat(Srgb.encode(1)).isEqualTo(1);
        // sRGB 0.5 is linear 0.2140 (the textbook "middle grey of the display")
        assertThat(Srgb.encode(0.21404114048223255)).isCloseTo(0.5, within(1e-12));
        // linear segment: 12.92·x below the knee
        assertThat(Srgb.encode(0.001)).isCloseTo(0.01292, within(1e-15));
        assertThat(Srgb.encode(0.0031308)).isCloseTo(0.0031308 * 12.92, within(1e-15));
    }

    @Test
    void encodeIsInvertedByTheEotf() {
        SplittableRandom rnd = new SplittableRandom(1);
        for (int i = 0; i < 100_000; i++) {
            double x = Math.pow(10, -6 * rnd.nextDouble());   // log-uniform in [1e-6, 1]
            assertThat(srgbDecode(Srgb.encode(x))).isCloseTo(x, within(1e-12 * Math.max(x, 1e-3)));
        }
    }

    @Test
    void encodeIsContinuousAtTheKnee() {
        double knee = 0.0031308;
        double below = Srgb.encode(knee);
        double above = Srgb.encode(Math.nextUp(knee));
        // both branches meet within the ~1e-8 mismatch of the standard's rounded constants
        assertThat(above - below).isCloseTo(0, within(1e-7));
        assertThat(1.055 * Math.pow(knee, 1 / 2.4) - 0.055).isCloseTo(below, within(1e-7));
    }

    @Test
    void encodeIsMonotonic() {
        double prev = 0;
        for (int i = 0; i <= 1_000_000; i++) {
            double v = Srgb.encode(i * 1.2e-6);
            assertThat(v).isGreaterThanOrEqualTo(prev);
            prev = v;
        }
    }

    @Test
    void encodeClampsAndMapsNaNToZero() {
        assertThat(Srgb.encode(-0.5)).isEqualTo(0);
        assertThat(Srgb.encode(-0.0)).isEqualTo(0);
        assertThat(Srgb.encode(Double.NEGATIVE_INFINITY)).isEqualTo(0);
        assertThat(Srgb.encode(Double.NaN)).isEqualTo(0);
        assertThat(Srgb.encode(1.5)).isEqualTo(1);
        assertThat(Srgb.encode(Double.POSITIVE_INFINITY)).isEqualTo(1);
        assertThat(Srgb.encode(Math.nextDown(1.0))).isBetween(0.999, 1.0);
    }

    @Test
    void toSrgb8RoundsToTheNearestCode() {
        assertThat(DisplayEncoding.toSrgb8(0)).isEqualTo(0);
        assertThat(DisplayEncoding.toSrgb8(1)).isEqualTo(255);
        assertThat(DisplayEncoding.toSrgb8(0.5)).isEqualTo(188);     // 255·0.73536 = 187.52
        assertThat(DisplayEncoding.toSrgb8(0.18)).isEqualTo(118);    // 18 % grey: 255·0.46136 = 117.65
        assertThat(DisplayEncoding.toSrgb8(0.001)).isEqualTo(3);     // 255·0.01292 = 3.29
        assertThat(DisplayEncoding.toSrgb8(7)).isEqualTo(255);
        assertThat(DisplayEncoding.toSrgb8(-1)).isEqualTo(0);
        assertThat(DisplayEncoding.toSrgb8(Double.NaN)).isEqualTo(0);
        for (int k = 0; k < 255; k++) {                      // the code changes from k to k+1 at 255·V = k + ½
            double edge = srgbDecode((k + 0.5) / 255);
            assertThat(DisplayEncoding.toSrgb8(edge * (1 - 1e-9))).as("below edge %d", k).isEqualTo(k);
            assertThat(DisplayEncoding.toSrgb8(edge * (1 + 1e-9))).as("above edge %d", k).isEqualTo(k + 1);
        }
    }

    @Test
    void lookupEqualsTheReferenceAroundEveryTransition() {
        for (int k = 0; k < 255; k++) {
            double edge = srgbDecode((k + 0.5) / 255);
            double x = edge;
            for (int i = 0; i < 64; i++) {
                x = Math.nextDown(x);
            }
            boolean sawBelow = false;
            boolean sawAbove = false;
            for (int i = 0; i < 128; i++, x = Math.nextUp(x)) {
                int expected = DisplayEncoding.toSrgb8(x);
                assertThat(DisplayEncoding.encode8(x)).as("x = %s", x).isEqualTo(expected);
                sawBelow |= expected == k;
                sawAbove |= expected == k + 1;
            }
            assertThat(sawBelow && sawAbove).as("window around transition %d contains it", k).isTrue();
        }
    }

    @Test
    void lookupEqualsTheReferenceEverywhere() {
        double[] special = {0, -0.0, Double.MIN_VALUE, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
            -1, 0x1p-13, Math.nextDown(0x1p-13), Math.nextUp(0x1p-13), Math.nextDown(1.0), 1, Math.nextUp(1.0),
            0.0031308, Math.nextUp(0.0031308), Double.MAX_VALUE};
        for (double x : special) {
            assertThat(DisplayEncoding.encode8(x)).as("x = %s", x).isEqualTo(DisplayEncoding.toSrgb8(x));
        }
        SplittableRandom rnd = new SplittableRandom(2);
        for (int i = 0; i < 2_000_000; i++) {
            double uniform = 1.2 * rnd.nextDouble();
            double logUniform = Math.pow(2, -16 * rnd.nextDouble());
            float asFloat = (float) uniform;                       // pixels are floats
            assertThat(DisplayEncoding.encode8(uniform)).isEqualTo(DisplayEncoding.toSrgb8(uniform));
            assertThat(DisplayEncoding.encode8(logUniform)).isEqualTo(DisplayEncoding.toSrgb8(logUniform));
            assertThat(DisplayEncoding.encode8(asFloat)).isEqualTo(DisplayEncoding.toSrgb8(asFloat));
        }
    }

    @Test
    void bufferedImageIsTopDownRgbOfTheEncodedPixels() {
        float[] rgb = new float[3 * 3 * 2];
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = i / 17f;
        }
        Image img = new Image(3, 2, rgb);
        BufferedImage bi = DisplayEncoding.toBufferedImage(img, 0);
        assertThat(bi.getType()).isEqualTo(BufferedImage.TYPE_INT_RGB);
        assertThat(bi.getWidth()).isEqualTo(3);
        assertThat(bi.getHeight()).isEqualTo(2);
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 3; x++) {
                int expected = DisplayEncoding.toSrgb8(img.get(x, y, 0)) << 16
                        | DisplayEncoding.toSrgb8(img.get(x, y, 1)) << 8
                        | DisplayEncoding.toSrgb8(img.get(x, y, 2));
                assertThat(bi.getRGB(x, y) & 0xFFFFFF).as("pixel %d,%d", x, y).isEqualTo(expected);
            }
        }
    }

    @Test
    void exposureMultipliesRadianceByTwoToTheStops() {
        SplittableRandom rnd = new SplittableRandom(3);
        float[] rgb = new float[3 * 64 * 64];
        float[] doubled = new float[rgb.length];
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = (float) Math.pow(2, -12 * rnd.nextDouble());
            doubled[i] = 2 * rgb[i];
        }
        Image img = new Image(64, 64, rgb);
        assertThat(pixels(DisplayEncoding.toBufferedImage(img, 1))).isEqualTo(pixels(DisplayEncoding.toBufferedImage(new Image(64, 64, doubled), 0)));

        double stops = -0.7;
        BufferedImage bi = DisplayEncoding.toBufferedImage(img, stops);
        for (int y = 0; y < 64; y++) {
            for (int x = 0; x < 64; x++) {
                int r = DisplayEncoding.toSrgb8(img.get(x, y, 0) * Math.pow(2, stops));
                assertThat((bi.getRGB(x, y) >> 16) & 0xFF).isEqualTo(r);
            }
        }
    }

    @Test
    void rejectsNonFiniteExposure() {
        Image img = new Image(1, 1, new float[3]);
        assertThatThrownBy(() -> DisplayEncoding.toBufferedImage(img, Double.NaN)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> DisplayEncoding.toBufferedImage(img, Double.POSITIVE_INFINITY)).isInstanceOf(IllegalArgumentException.class);
    }

    private static int[] pixels(BufferedImage bi) {
        return bi.getRGB(0, 0, bi.getWidth(), bi.getHeight(), null, 0, bi.getWidth());
    }

    @Test
    void acesIsNarkowiczsFitClampedToOne() {
        assertThat(DisplayEncoding.aces(0)).isEqualTo(0.0);
        assertThat(DisplayEncoding.aces(-1)).isEqualTo(0.0);
        assertThat(DisplayEncoding.aces(Double.NaN)).isEqualTo(0.0);
        // x = 1: (2.51 + 0.03) / (2.43 + 0.59 + 0.14) = 2.54 / 3.16
        assertThat(DisplayEncoding.aces(1)).isCloseTo(2.54 / 3.16, within(1e-12));
        assertThat(DisplayEncoding.aces(1e6)).isEqualTo(1.0);
        double prev = 0;
        for (double x = 0.001; x < 100; x *= 1.1) {
            double v = DisplayEncoding.aces(x);
            assertThat(v).isGreaterThanOrEqualTo(prev).isLessThanOrEqualTo(1);
            prev = v;
        }
    }

    @Test
    void agxIsMonotoneOnGreysStaysInRangeAndDesaturatesHighlights() {
        double prev = -1;
        for (double x = 1e-4; x < 1000; x *= 1.2) {
            double[] c = {x, x, x};
            DisplayEncoding.agx(c);
            assertThat(c[0]).isGreaterThanOrEqualTo(prev).isBetween(0.0, 1.0);
            assertThat(c[1]).isCloseTo(c[0], within(1e-3));
            prev = c[0];
        }
        double[] black = {0, 0, Double.NaN};
        DisplayEncoding.agx(black);
        assertThat(black[0]).isBetween(0.0, 0.01);
        // a very bright saturated red comes out brighter in green and blue than a dim one: towards white
        double[] dim = {0.5, 0.05, 0.05}, bright = {50, 5, 5};
        DisplayEncoding.agx(dim);
        DisplayEncoding.agx(bright);
        assertThat(bright[1] / bright[0]).isGreaterThan(dim[1] / dim[0]);
    }

    @Test
    void clampIsTheDefaultCurveBitForBit() {
        float[] v = new float[3 * 64];
        for (int i = 0; i < v.length; i++) {
            v[i] = (float) Math.pow(1.1, i - 90);
        }
        Image img = new Image(8, 8, v);
        var a = DisplayEncoding.toBufferedImage(img, 0.5);
        var b = DisplayEncoding.toBufferedImage(img, 0.5, dev.strahl.image.ToneMapping.CLAMP);
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 8; x++) {
                assertThat(b.getRGB(x, y)).isEqualTo(a.getRGB(x, y));
            }
        }
    }
}
