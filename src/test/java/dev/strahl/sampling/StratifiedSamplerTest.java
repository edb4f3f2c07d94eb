package dev.strahl.sampling;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.testing.ChiSquare;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * The stratified sampler: each pair a pixel's samples are asked for together is a (0,m,2)-net,
 * pairs and pixels are independent, a dimension's value depends only on (seed, pixel, sample,
 * dimension), and after the stratified dimensions the stream of the sample goes on.
 */
class StratifiedSamplerTest {
    private static final int STRATIFIED = StratifiedSampler.STRATIFIED_DIMENSIONS;

    /** The pairs of one sample in the path tracer's first-vertex layout: pixel, get2D, (get1D, get1D), get2D. */
    private static double[][] vertexPairs(StratifiedSampler sampler, int px, int py, int index) {
        sampler.startPixelSample(px, py, index);
        Sample2D pixel = sampler.getPixel2D(new Sample2D());
        Sample2D light = sampler.get2D(new Sample2D());
        double uLight = sampler.get1D(), uLobe = sampler.get1D();
        Sample2D direction = sampler.get2D(new Sample2D());
        assertThat(sampler.dimension()).isEqualTo(STRATIFIED);
        return new double[][] {{pixel.u1, pixel.u2}, {light.u1, light.u2}, {uLight, uLobe}, {direction.u1, direction.u2}};
    }

    /** Every elementary interval of area 2^-m holds exactly one of the first 2^m points. */
    private static void assertNet(double[][] points, int m, String what) {
        int n = 1 << m;
        for (int k = 0; k <= m; k++) {
            boolean[] seen = new boolean[n];
            for (int s = 0; s < n; s++) {
                int cell = (int) (points[s][0] * (1 << k)) * (1 << (m - k)) + (int) (points[s][1] * (1 << (m - k)));
                assertThat(seen[cell]).as("%s, %d x %d grid", what, 1 << k, 1 << (m - k)).isFalse();
                seen[cell] = true;
            }
        }
    }

    @Test
    void everyPairOfAPixelsFirstPowerOfTwoSamplesIsAZeroMTwoNet() {
        int m = 8, n = 1 << m;
        StratifiedSampler sampler = new StratifiedSampler(5);
        for (int pixel = 0; pixel < 20; pixel++) {
            double[][][] pairs = new double[STRATIFIED / 2][n][];
            for (int s = 0; s < n; s++) {
                double[][] u = vertexPairs(sampler, pixel, 2 * pixel, s);
                for (int p = 0; p < u.length; p++) {
                    pairs[p][s] = u[p];
                }
            }
            for (int p = 0; p < pairs.length; p++) {
                for (int prefix = 0; prefix <= m; prefix += 2) {
                    assertNet(pairs[p], prefix, "pixel " + pixel + ", pair " + p + ", first " + (1 << prefix) + " samples");
                }
            }
        }
    }

    @Test
    void aGet2DAtAnOddDimensionTakesTheNextWholePair() {
        int m = 6, n = 1 << m;
        StratifiedSampler sampler = new StratifiedSampler(9);
        double[][] padded = new double[n][];
        for (int s = 0; s < n; s++) {
            sampler.startPixelSample(4, 7, s);
            sampler.get1D();                                   // dimension 2; 3 stays unused
            Sample2D u = sampler.get2D(new Sample2D());
            assertThat(sampler.dimension()).isEqualTo(6);
            padded[s] = new double[] {u.u1, u.u2};
            sampler.startPixelSample(4, 7, s);
            sampler.get2D(new Sample2D());
            Sample2D aligned = sampler.get2D(new Sample2D());
            assertThat(padded[s]).as("sample %d", s).containsExactly(aligned.u1, aligned.u2);
        }
        assertNet(padded, m, "the pair after one get1D");
        // At the last odd stratified dimension the pair goes to the stream, unpadded there.
        sampler.startPixelSample(4, 7, 3);
        for (int d = 2; d < STRATIFIED - 1; d++) {
            sampler.get1D();
        }
        sampler.get2D(new Sample2D());
        assertThat(sampler.dimension()).isEqualTo(STRATIFIED + 2);
        sampler.get1D();
        sampler.get2D(new Sample2D());
        assertThat(sampler.dimension()).as("no padding in the stream").isEqualTo(STRATIFIED + 5);
    }

    @Test
    void dimensionsAfterTheStratifiedOnesAreTheSamplesStream() {
        StratifiedSampler sampler = new StratifiedSampler(7);
        vertexPairs(sampler, 13, 21, 5);
        long stream = SplitMix64.streamSeed(7, 13, 21, 5);
        assertThat(sampler.get1D()).isEqualTo(SplitMix64.toUnit(SplitMix64.at(stream, 1)));
        Sample2D u = sampler.get2D(new Sample2D());
        assertThat(u.u1).isEqualTo(SplitMix64.toUnit(SplitMix64.at(stream, 2)));
        assertThat(u.u2).isEqualTo(SplitMix64.toUnit(SplitMix64.at(stream, 3)));
        assertThat(sampler.get1D()).isEqualTo(SplitMix64.toUnit(SplitMix64.at(stream, 4)));
    }

    @Test
    void aDimensionsValueDoesNotDependOnHowTheOnesBeforeItWereDrawn() {
        // Dimension d by get1D calls alone, and by get2D pairs (each starting on an even dimension).
        int dims = 24;
        StratifiedSampler sampler = new StratifiedSampler(3);
        for (int s = 0; s < 16; s++) {
            sampler.startPixelSample(s, 1, s);
            double[] ones = new double[dims];
            for (int d = 2; d < dims; d++) {
                ones[d] = sampler.get1D();
            }
            sampler.startPixelSample(s, 1, s);
            Sample2D u = new Sample2D();
            for (int d = 2; d < dims; d += 2) {
                sampler.get2D(u);
                assertThat(u.u1).as("sample %d, dimension %d", s, d).isEqualTo(ones[d]);
                assertThat(u.u2).as("sample %d, dimension %d", s, d + 1).isEqualTo(ones[d + 1]);
            }
        }
    }

    private static double[] dims(long seed, int px, int py, int sample, int count) {
        StratifiedSampler sampler = new StratifiedSampler(seed);
        sampler.startPixelSample(px, py, sample);
        Sample2D pixel = sampler.getPixel2D(new Sample2D());
        double[] u = new double[count];
        u[0] = pixel.u1;
        u[1] = pixel.u2;
        for (int i = 2; i < count; i++) {
            u[i] = sampler.get1D();
        }
        return u;
    }

    @Test
    void theNumbersAreAFunctionOfSeedPixelAndSampleAlone() {
        StratifiedSampler reused = new StratifiedSampler(7);
        reused.startPixelSample(3, 4, 5);
        reused.get1D();
        reused.get2D(new Sample2D());
        reused.startPixelSample(13, 21, 5);
        Sample2D pixel = reused.getPixel2D(new Sample2D());
        double[] again = new double[40];
        again[0] = pixel.u1;
        again[1] = pixel.u2;
        for (int i = 2; i < again.length; i++) {
            again[i] = reused.get1D();
        }
        assertThat(again).containsExactly(dims(7, 13, 21, 5, 40));
        double[] base = dims(7, 13, 21, 5, STRATIFIED + 4);
        for (double[] other : new double[][] {dims(8, 13, 21, 5, base.length), dims(7, 14, 21, 5, base.length),
            dims(7, 13, 22, 5, base.length), dims(7, 13, 21, 6, base.length), dims(7, 21, 13, 5, base.length)}) {
            for (int d = 0; d < base.length; d++) {
                assertThat(other[d]).as("dimension %d", d).isNotEqualTo(base[d]);
            }
        }
        StratifiedSampler twice = new StratifiedSampler(7);
        twice.startPixelSample(13, 21, 5);
        Sample2D first = twice.getPixel2D(new Sample2D()), second = twice.getPixel2D(new Sample2D());
        assertThat(second.u1).isEqualTo(first.u1);
        assertThat(twice.get1D()).as("getPixel2D draws no integrator dimension").isEqualTo(base[2]);
    }

    @Test
    void stratifiedDimensionsAreUniformAndUncorrelatedAcrossPixelsAndPairs() {
        // For one sample index, over many pixels: every dimension uniform (chi-square), the first
        // coordinates of different pairs uncorrelated, and so are neighbouring pixels.
        int width = 128, height = 128, n = width * height, bins = 32;
        double[][] u = new double[STRATIFIED][n], right = new double[STRATIFIED][n];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                double[] here = dims(3, x, y, 7, STRATIFIED), next = dims(3, x + 1, y, 7, STRATIFIED);
                for (int d = 0; d < STRATIFIED; d++) {
                    u[d][y * width + x] = here[d];
                    right[d][y * width + x] = next[d];
                }
            }
        }
        double bound = 5 / Math.sqrt(n);
        double[] expected = new double[bins];
        Arrays.fill(expected, (double) n / bins);
        for (int d = 0; d < STRATIFIED; d++) {
            long[] count = new long[bins];
            for (double v : u[d]) {
                assertThat(v).isGreaterThanOrEqualTo(0).isLessThan(1);
                count[(int) (v * bins)]++;
            }
            assertThat(ChiSquare.fromCounts(expected, count).pValue()).as("dimension %d", d).isGreaterThan(1e-5);
            assertThat(SplitMix64Test.correlation(u[d], right[d])).as("right neighbour, dimension %d", d).isCloseTo(0, within(bound));
            if (d >= 2) {
                assertThat(SplitMix64Test.correlation(u[d], u[d - 2])).as("dimensions %d and %d", d - 2, d).isCloseTo(0, within(bound));
            }
        }
    }

    @Test
    void stratificationLowersTheErrorOfAPixelEstimate() {
        // The mean of f(u1, u2) = (u1 + u2)² over 64 samples of a pixel, over 500 pixels: the
        // stratified pair's mean squared error is far below the independent one's (Var(f)/64).
        int pixels = 500, spp = 64;
        double exact = 7 / 6.0;
        double mseStratified = 0, mseIndependent = 0;
        Sampler stratified = new StratifiedSampler(1), independent = new IndependentSampler(1);
        Sample2D u = new Sample2D();
        for (int p = 0; p < pixels; p++) {
            double a = 0, b = 0;
            for (int s = 0; s < spp; s++) {
                stratified.startPixelSample(p, 0, s);
                stratified.get2D(u);
                a += (u.u1 + u.u2) * (u.u1 + u.u2);
                independent.startPixelSample(p, 0, s);
                independent.get2D(u);
                b += (u.u1 + u.u2) * (u.u1 + u.u2);
            }
            mseStratified += Math.pow(a / spp - exact, 2) / pixels;
            mseIndependent += Math.pow(b / spp - exact, 2) / pixels;
        }
        assertThat(mseStratified).isLessThan(mseIndependent / 20);
    }
}
