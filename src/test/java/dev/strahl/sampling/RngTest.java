package dev.strahl.sampling;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The per-sample random streams: deterministic, distinct for neighbours, uniform and uncorrelated. */
class RngTest {

    private static long[] stream(long seed, int px, int py, long sample, int length) {
        Rng rng = new Rng(Rng.streamSeed(seed, px, py, sample));
        long[] values = new long[length];
        for (int i = 0; i < length; i++) {
            values[i] = rng.nextLong();
        }
        return values;
    }

    @Test
    void sameSeedPixelAndSampleGiveTheSameStream() {
        assertThat(stream(7, 13, 21, 5, 100)).containsExactly(stream(7, 13, 21, 5, 100));
        Rng reused = new Rng(123);
        reused.nextLong();
        reused.seed(Rng.streamSeed(7, 13, 21, 5));
        assertThat(reused.nextLong()).isEqualTo(stream(7, 13, 21, 5, 1)[0]);
    }

    @Test
    void neighbouringPixelsSamplesAndSeedsGiveDifferentStreams() {
        long[] base = stream(7, 13, 21, 5, 4);
        long[][] neighbours = {
            stream(8, 13, 21, 5, 4), stream(6, 13, 21, 5, 4),
            stream(7, 14, 21, 5, 4), stream(7, 12, 21, 5, 4),
            stream(7, 13, 22, 5, 4), stream(7, 13, 20, 5, 4),
            stream(7, 13, 21, 6, 4), stream(7, 13, 21, 4, 4),
            stream(7, 21, 13, 5, 4),                       // transposed pixel
        };
        for (long[] other : neighbours) {
            for (int i = 0; i < base.length; i++) {
                assertThat(other[i]).isNotEqualTo(base[i]);
            }
        }
    }

    @Test
    void streamsOfNeighbouringPixelsAndSamplesDoNotOverlap() {
        // SplitMix64 streams are Weyl sequences: two streams whose seeds differ by a small multiple
        // of the increment would repeat each other shifted. No value may occur twice among the
        // first 32 draws of the 8 x 8 pixels x 8 samples x 2 seeds here (2^15 random 64-bit values
        // collide by chance with probability ~2^-35).
        Set<Long> seen = new HashSet<>();
        int count = 0;
        for (long seed = 0; seed < 2; seed++) {
            for (int py = 0; py < 8; py++) {
                for (int px = 0; px < 8; px++) {
                    for (int s = 0; s < 8; s++) {
                        for (long v : stream(seed, px, py, s, 32)) {
                            seen.add(v);
                            count++;
                        }
                    }
                }
            }
        }
        assertThat(seen).hasSize(count);
    }

    @Test
    void streamSeedsDoNotCollideOverAnImageOfSamples() {
        Set<Long> seen = new HashSet<>();
        int count = 0;
        for (long seed = 0; seed < 3; seed++) {
            for (int py = -2; py < 64; py++) {
                for (int px = -2; px < 64; px++) {
                    for (int s = 0; s < 16; s++) {
                        seen.add(Rng.streamSeed(seed, px, py, s));
                        count++;
                    }
                }
            }
        }
        assertThat(seen).hasSize(count);
    }

    @Test
    void nextDoubleIsInTheHalfOpenUnitInterval() {
        Rng rng = new Rng(Rng.streamSeed(1, 0, 0, 0));
        for (int i = 0; i < 1_000_000; i++) {
            assertThat(rng.nextDouble()).isGreaterThanOrEqualTo(0).isLessThan(1);
        }
        // The extreme outputs: a state whose next output is all ones gives the largest double, below 1.
        assertThat(new Rng(stateBefore(-1L)).nextDouble()).isEqualTo(Math.nextDown(1.0));
        assertThat(new Rng(stateBefore(0L)).nextDouble()).isZero();
    }

    @Test
    void nextDoubleHasTheMomentsOfTheUniformDistribution() {
        int pixels = 1000, draws = 1000;
        long n = (long) pixels * draws;
        double sum = 0, sumSq = 0;
        Rng rng = new Rng();
        for (int p = 0; p < pixels; p++) {
            rng.seed(Rng.streamSeed(42, p % 40, p / 40, 0));
            for (int i = 0; i < draws; i++) {
                double u = rng.nextDouble();
                sum += u;
                sumSq += (u - 0.5) * (u - 0.5);
            }
        }
        // mean: sd 1/sqrt(12 n); variance about 1/2: sd sqrt(Var[(u-1/2)^2] / n) = sqrt((1/80 - 1/144) / n).
        assertThat(sum / n).isCloseTo(0.5, within(5 / Math.sqrt(12.0 * n)));
        assertThat(sumSq / n).isCloseTo(1 / 12.0, within(5 * Math.sqrt((1 / 80.0 - 1 / 144.0) / n)));
    }

    @Test
    void streamsOfAdjacentPixelsSamplesAndSeedsAreUncorrelated() {
        // For the k-th draw, correlate pixel (x, y) with its right neighbour, its lower neighbour,
        // the next sample index and the next seed, over many pixels. Under independence the sample
        // correlation is about normal with sd 1/sqrt(n).
        int width = 128, height = 128, draws = 8;
        int n = width * height;
        double bound = 5 / Math.sqrt(n);
        double[][] here = new double[draws][n], right = new double[draws][n], below = new double[draws][n];
        double[][] nextSample = new double[draws][n], nextSeed = new double[draws][n];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int i = y * width + x;
                fill(here, i, new Rng(Rng.streamSeed(3, x, y, 0)));
                fill(right, i, new Rng(Rng.streamSeed(3, x + 1, y, 0)));
                fill(below, i, new Rng(Rng.streamSeed(3, x, y + 1, 0)));
                fill(nextSample, i, new Rng(Rng.streamSeed(3, x, y, 1)));
                fill(nextSeed, i, new Rng(Rng.streamSeed(4, x, y, 0)));
            }
        }
        for (int k = 0; k < draws; k++) {
            assertThat(correlation(here[k], right[k])).as("right neighbour, draw %d", k).isCloseTo(0, within(bound));
            assertThat(correlation(here[k], below[k])).as("lower neighbour, draw %d", k).isCloseTo(0, within(bound));
            assertThat(correlation(here[k], nextSample[k])).as("next sample, draw %d", k).isCloseTo(0, within(bound));
            assertThat(correlation(here[k], nextSeed[k])).as("next seed, draw %d", k).isCloseTo(0, within(bound));
            if (k > 0) {
                assertThat(correlation(here[k], here[k - 1])).as("consecutive draws %d", k).isCloseTo(0, within(bound));
            }
        }
    }

    private static void fill(double[][] dest, int i, Rng rng) {
        for (double[] draw : dest) {
            draw[i] = rng.nextDouble();
        }
    }

    private static double correlation(double[] a, double[] b) {
        int n = a.length;
        double ma = 0, mb = 0;
        for (int i = 0; i < n; i++) {
            ma += a[i];
            mb += b[i];
        }
        ma /= n;
        mb /= n;
        double sab = 0, saa = 0, sbb = 0;
        for (int i = 0; i < n; i++) {
            sab += (a[i] - ma) * (b[i] - mb);
            saa += (a[i] - ma) * (a[i] - ma);
            sbb += (b[i] - mb) * (b[i] - mb);
        }
        return sab / Math.sqrt(saa * sbb);
    }

    // ---------------------------------------------------------------------------------------------
    // Sample mode: stratified dimensions, then the stream

    private static double[] sampleDims(long seed, int px, int py, int sample, int count) {
        Rng rng = new Rng().startSample(seed, px, py, sample);
        double[] u = new double[count];
        for (int i = 0; i < count; i++) {
            u[i] = rng.nextDouble();
        }
        return u;
    }

    @Test
    void sampleModeIsAFunctionOfSeedPixelAndSampleAlone() {
        Rng reused = new Rng(99);
        reused.nextDouble();
        reused.startSample(7, 3, 4, 5).nextDouble();
        reused.startSample(7, 13, 21, 5);
        double[] again = new double[40];
        for (int i = 0; i < again.length; i++) {
            again[i] = reused.nextDouble();
        }
        assertThat(again).containsExactly(sampleDims(7, 13, 21, 5, 40));
        double[] base = sampleDims(7, 13, 21, 5, Rng.STRATIFIED_DIMENSIONS);
        for (double[] other : new double[][] {sampleDims(8, 13, 21, 5, base.length), sampleDims(7, 14, 21, 5, base.length),
            sampleDims(7, 13, 22, 5, base.length), sampleDims(7, 13, 21, 6, base.length), sampleDims(7, 21, 13, 5, base.length)}) {
            for (int d = 0; d < base.length; d++) {
                assertThat(other[d]).as("dimension %d", d).isNotEqualTo(base[d]);
            }
        }
    }

    @Test
    void eachPairOfDimensionsOfAPixelsSamplesIsAZeroMTwoNet() {
        int m = 8, n = 1 << m;
        for (int pixel = 0; pixel < 20; pixel++) {
            double[][] u = new double[n][];
            for (int s = 0; s < n; s++) {
                u[s] = sampleDims(5, pixel, 2 * pixel, s, Rng.STRATIFIED_DIMENSIONS);
            }
            for (int pair = 0; pair < Rng.STRATIFIED_DIMENSIONS / 2; pair++) {
                for (int k = 0; k <= m; k++) {
                    boolean[] seen = new boolean[n];
                    for (int s = 0; s < n; s++) {
                        int cell = (int) (u[s][2 * pair] * (1 << k)) * (1 << (m - k)) + (int) (u[s][2 * pair + 1] * (1 << (m - k)));
                        assertThat(seen[cell]).as("pixel %d, dimensions %d and %d, %d x %d grid", pixel, 2 * pair, 2 * pair + 1, 1 << k, 1 << (m - k)).isFalse();
                        seen[cell] = true;
                    }
                }
            }
        }
    }

    @Test
    void stratifiedDimensionsAreUniformAndUncorrelatedAcrossPixelsAndPairs() {
        // For one sample index, over many pixels: every dimension uniform (chi-square), and the first
        // coordinates of different pairs uncorrelated, as are neighbouring pixels.
        int width = 128, height = 128, n = width * height, dims = Rng.STRATIFIED_DIMENSIONS, bins = 32;
        double[][] u = new double[dims][n], right = new double[dims][n];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                double[] here = sampleDims(3, x, y, 7, dims), next = sampleDims(3, x + 1, y, 7, dims);
                for (int d = 0; d < dims; d++) {
                    u[d][y * width + x] = here[d];
                    right[d][y * width + x] = next[d];
                }
            }
        }
        double bound = 5 / Math.sqrt(n);
        double[] expected = new double[bins];
        java.util.Arrays.fill(expected, (double) n / bins);
        for (int d = 0; d < dims; d++) {
            long[] count = new long[bins];
            for (double v : u[d]) {
                assertThat(v).isGreaterThanOrEqualTo(0).isLessThan(1);
                count[(int) (v * bins)]++;
            }
            assertThat(dev.strahl.testing.ChiSquare.fromCounts(expected, count).pValue()).as("dimension %d", d).isGreaterThan(1e-5);
            assertThat(correlation(u[d], right[d])).as("right neighbour, dimension %d", d).isCloseTo(0, within(bound));
            if (d >= 2) {
                assertThat(correlation(u[d], u[d - 2])).as("dimensions %d and %d", d - 2, d).isCloseTo(0, within(bound));
            }
        }
    }

    @Test
    void afterTheStratifiedDimensionsTheSampleStreamContinues() {
        double[] u = sampleDims(7, 13, 21, 5, Rng.STRATIFIED_DIMENSIONS + 3);
        Rng stream = new Rng(Rng.streamSeed(7, 13, 21, 5));
        for (int i = 0; i < 3; i++) {
            assertThat(u[Rng.STRATIFIED_DIMENSIONS + i]).isEqualTo(stream.nextDouble());
        }
        Rng rng = new Rng().startSample(7, 13, 21, 5);
        assertThat(rng.nextLong()).as("nextLong always draws from the stream").isEqualTo(new Rng(Rng.streamSeed(7, 13, 21, 5)).nextLong());
        rng.seed(Rng.streamSeed(7, 13, 21, 5));
        assertThat(rng.nextDouble()).as("seed() leaves sample mode").isEqualTo(new Rng(Rng.streamSeed(7, 13, 21, 5)).nextDouble());
    }

    @Test
    void skippedDimensionsKeepTheLaterOnesInPlace() {
        double[] all = sampleDims(2, 5, 6, 3, 12);
        for (int skip = 0; skip < 6; skip++) {
            Rng rng = new Rng().startSample(2, 5, 6, 3);
            rng.nextDouble();
            rng.skip(skip);
            assertThat(rng.dimension()).isEqualTo(1 + skip);
            for (int d = 1 + skip; d < 12; d++) {
                assertThat(rng.nextDouble()).as("dimension %d after skipping %d", d, skip).isEqualTo(all[d]);
            }
        }
    }

    @Test
    void stratificationLowersTheErrorOfAPixelEstimate() {
        // The mean of f(u0, u1) = (u0 + u1)² over 64 samples of a pixel, over 500 pixels: the
        // stratified dimensions' mean squared error is far below the stream's (whose MSE is Var(f)/64).
        int pixels = 500, spp = 64;
        double exact = 7 / 6.0;
        double mseStratified = 0, mseStream = 0;
        for (int p = 0; p < pixels; p++) {
            double a = 0, b = 0;
            for (int s = 0; s < spp; s++) {
                Rng rng = new Rng().startSample(1, p, 0, s);
                double u0 = rng.nextDouble(), u1 = rng.nextDouble();
                a += (u0 + u1) * (u0 + u1);
                Rng plain = new Rng(Rng.streamSeed(1, p, 0, s));
                double v0 = plain.nextDouble(), v1 = plain.nextDouble();
                b += (v0 + v1) * (v0 + v1);
            }
            mseStratified += Math.pow(a / spp - exact, 2) / pixels;
            mseStream += Math.pow(b / spp - exact, 2) / pixels;
        }
        assertThat(mseStratified).isLessThan(mseStream / 20);
    }

    /** The state from which {@link Rng#nextLong()} returns {@code output}: the inverse of one SplitMix64 step. */
    private static long stateBefore(long output) {
        long z = output;
        z = unXorShift(z, 31);
        z *= inverse(0x94d049bb133111ebL);
        z = unXorShift(z, 27);
        z *= inverse(0xbf58476d1ce4e5b9L);
        z = unXorShift(z, 30);
        assertThat(Rng.mix64(z)).isEqualTo(output);
        return z - 0x9e3779b97f4a7c15L;
    }

    /** Inverts z ^ (z >>> shift). */
    private static long unXorShift(long y, int shift) {
        long z = y;
        for (int i = 0; i < 64 / shift + 1; i++) {
            z = y ^ (z >>> shift);
        }
        return z;
    }

    /** Multiplicative inverse of an odd number modulo 2^64 (Newton's iteration). */
    private static long inverse(long a) {
        long x = a;                 // correct to 3 bits for odd a
        for (int i = 0; i < 5; i++) {
            x *= 2 - a * x;
        }
        return x;
    }
}
