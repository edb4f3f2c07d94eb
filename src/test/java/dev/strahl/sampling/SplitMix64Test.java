package dev.strahl.sampling;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * The per-sample random streams behind both samplers: deterministic, distinct for neighbours,
 * uniform and uncorrelated; position k computed directly equals k steps of the generator.
 */
class SplitMix64Test {

    private static long[] stream(long seed, int px, int py, long sample, int length) {
        long s = SplitMix64.streamSeed(seed, px, py, sample);
        long[] values = new long[length];
        for (int i = 0; i < length; i++) {
            values[i] = SplitMix64.at(s, i + 1);
        }
        return values;
    }

    @Test
    void positionKIsKStepsOfTheGenerator() {
        // The generator: state += γ, output mix64(state) (Steele, Lea & Flood 2014, Fig. 1).
        long state = SplitMix64.streamSeed(7, 13, 21, 5);
        long seed = state;
        for (int k = 1; k <= 1000; k++) {
            state += 0x9e3779b97f4a7c15L;
            assertThat(SplitMix64.at(seed, k)).as("position %d", k).isEqualTo(SplitMix64.mix64(state));
        }
    }

    @Test
    void sameSeedPixelAndSampleGiveTheSameStream() {
        assertThat(stream(7, 13, 21, 5, 100)).containsExactly(stream(7, 13, 21, 5, 100));
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
                        seen.add(SplitMix64.streamSeed(seed, px, py, s));
                        count++;
                    }
                }
            }
        }
        assertThat(seen).hasSize(count);
    }

    @Test
    void toUnitIsInTheHalfOpenUnitInterval() {
        long s = SplitMix64.streamSeed(1, 0, 0, 0);
        for (int k = 1; k <= 1_000_000; k++) {
            assertThat(SplitMix64.toUnit(SplitMix64.at(s, k))).isGreaterThanOrEqualTo(0).isLessThan(1);
        }
        // The extreme outputs: all ones gives the largest double below 1, and the state that hashes
        // to all ones exists (mix64 is a bijection), as does the one that hashes to zero.
        assertThat(SplitMix64.toUnit(-1L)).isEqualTo(Math.nextDown(1.0));
        assertThat(SplitMix64.toUnit(0L)).isZero();
        assertThat(SplitMix64.at(stateBefore(-1L), 1)).isEqualTo(-1L);
        assertThat(SplitMix64.at(stateBefore(0L), 1)).isZero();
    }

    @Test
    void valuesHaveTheMomentsOfTheUniformDistribution() {
        int pixels = 1000, draws = 1000;
        long n = (long) pixels * draws;
        double sum = 0, sumSq = 0;
        for (int p = 0; p < pixels; p++) {
            long s = SplitMix64.streamSeed(42, p % 40, p / 40, 0);
            for (int k = 1; k <= draws; k++) {
                double u = SplitMix64.toUnit(SplitMix64.at(s, k));
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
                fill(here, i, SplitMix64.streamSeed(3, x, y, 0));
                fill(right, i, SplitMix64.streamSeed(3, x + 1, y, 0));
                fill(below, i, SplitMix64.streamSeed(3, x, y + 1, 0));
                fill(nextSample, i, SplitMix64.streamSeed(3, x, y, 1));
                fill(nextSeed, i, SplitMix64.streamSeed(4, x, y, 0));
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

    private static void fill(double[][] dest, int i, long streamSeed) {
        for (int k = 0; k < dest.length; k++) {
            dest[k][i] = SplitMix64.toUnit(SplitMix64.at(streamSeed, k + 1));
        }
    }

    static double correlation(double[] a, double[] b) {
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

    /** The seed whose first value is {@code output}: the inverse of one SplitMix64 step. */
    private static long stateBefore(long output) {
        long z = output;
        z = unXorShift(z, 31);
        z *= inverse(0x94d049bb133111ebL);
        z = unXorShift(z, 27);
        z *= inverse(0xbf58476d1ce4e5b9L);
        z = unXorShift(z, 30);
        assertThat(SplitMix64.mix64(z)).isEqualTo(output);
        return z - SplitMix64.GOLDEN_GAMMA;
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
