package dev.strahl.sampling;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.testing.ChiSquare;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The shuffled, Owen-scrambled (0,2)-sequence: its table matches the definition, every
 * power-of-two prefix is a (0,m,2)-net whatever the seed, each point is uniform over seeds, the
 * scramble is an Owen scramble (it keeps dyadic intervals together), and different seeds give
 * unrelated point sets.
 */
class OwenSobolTest {

    /**
     * The second Sobol dimension by its generator matrix, Pascal's triangle mod 2: input bit k
     * flips output bit j (counted from the most significant) where C(k, j) is odd, i.e. where
     * j's bits are a subset of k's (Lucas).
     */
    private static int sobol1ByDefinition(int i) {
        int x = 0;
        for (int k = 0; k < 32; k++) {
            if ((i >>> k & 1) != 0) {
                for (int j = 0; j <= k; j++) {
                    if ((j & ~k) == 0) {
                        x ^= 1 << (31 - j);
                    }
                }
            }
        }
        return x;
    }

    @Test
    void tableEvaluationOfTheSecondDimensionMatchesTheDefinition() {
        SplittableRandom random = new SplittableRandom(1);
        for (int k = 0; k < 100_000; k++) {
            int i = k < 1024 ? k : random.nextInt();
            assertThat(OwenSobol.sobol1(i)).isEqualTo(sobol1ByDefinition(i));
        }
        // The first points of the second Sobol dimension in index order: 0, 1/2, 3/4, 1/4, 5/8, 1/8, 3/8, 7/8.
        int[] eighths = {0, 4, 6, 2, 5, 1, 3, 7};
        for (int i = 0; i < 8; i++) {
            assertThat(OwenSobol.toUnit(OwenSobol.sobol1(i))).isEqualTo(eighths[i] / 8.0);
        }
    }

    @Test
    void theFastPointEqualsTheDefinition() {
        SplittableRandom random = new SplittableRandom(4);
        for (int k = 0; k < 100_000; k++) {
            int seed = random.nextInt(), index = k < 5000 ? k : random.nextInt();
            int s = OwenSobol.shuffle(index, seed);
            long xy = OwenSobol.point(index, seed);
            assertThat((int) (xy >>> 32)).isEqualTo(OwenSobol.x(s, seed));
            assertThat((int) xy).isEqualTo(OwenSobol.y(s, seed));
            assertThat(OwenSobol.sobol1Reversed(index)).isEqualTo(Integer.reverse(OwenSobol.sobol1(index)));
        }
    }

    @Test
    void everyPowerOfTwoPrefixIsAZeroMTwoNetForAnySeed() {
        SplittableRandom random = new SplittableRandom(2);
        for (int trial = 0; trial < 40; trial++) {
            int seed = random.nextInt();
            for (int m = 0; m <= 10; m++) {
                assertNet(seed, m);
            }
        }
    }

    /** Every elementary interval [a/2^k, (a+1)/2^k) × [b/2^(m−k), (b+1)/2^(m−k)) holds exactly one of the first 2^m points. */
    private static void assertNet(int seed, int m) {
        int n = 1 << m;
        for (int k = 0; k <= m; k++) {
            boolean[] seen = new boolean[n];
            for (int i = 0; i < n; i++) {
                int s = OwenSobol.shuffle(i, seed);
                int x = OwenSobol.x(s, seed) >>> (32 - k) & ((1 << k) - 1);
                int y = m - k == 0 ? 0 : OwenSobol.y(s, seed) >>> (32 - (m - k));
                if (k == 0) {
                    x = 0;
                }
                int cell = (x << (m - k)) | y;
                assertThat(seen[cell]).as("seed %d, m %d, k %d: cell %d holds two points", seed, m, k, cell).isFalse();
                seen[cell] = true;
            }
        }
    }

    @Test
    void eachPointIsUniformlyDistributedOverSeeds() {
        int bins = 64, seeds = 64_000;
        for (int index : new int[] {0, 1, 5, 1000}) {
            long[] countX = new long[bins], countY = new long[bins];
            for (int seed = 0; seed < seeds; seed++) {
                int h = OwenSobol.mix32(seed);
                int s = OwenSobol.shuffle(index, h);
                countX[OwenSobol.x(s, h) >>> 26]++;
                countY[OwenSobol.y(s, h) >>> 26]++;
            }
            double[] expected = new double[bins];
            java.util.Arrays.fill(expected, (double) seeds / bins);
            assertThat(ChiSquare.fromCounts(expected, countX).pValue()).as("x of point %d", index).isGreaterThan(1e-4);
            assertThat(ChiSquare.fromCounts(expected, countY).pValue()).as("y of point %d", index).isGreaterThan(1e-4);
        }
    }

    @Test
    void scramblingKeepsDyadicIntervalsTogether() {
        // An Owen scramble maps all points sharing their first k bits to points sharing their first k bits.
        SplittableRandom random = new SplittableRandom(3);
        for (int trial = 0; trial < 10_000; trial++) {
            int seed = random.nextInt(), a = random.nextInt(), k = random.nextInt(1, 32);
            int b = (a & ~(-1 >>> k)) | (random.nextInt() & (-1 >>> k));
            int sa = OwenSobol.nestedUniformScramble(a, seed), sb = OwenSobol.nestedUniformScramble(b, seed);
            assertThat(sa >>> (32 - k)).as("first %d bits", k).isEqualTo(sb >>> (32 - k));
        }
        // And it is a bijection: no two of 2^16 inputs collide.
        java.util.Set<Integer> out = new java.util.HashSet<>();
        for (int i = 0; i < 1 << 16; i++) {
            out.add(OwenSobol.nestedUniformScramble(i << 16, 12345));
        }
        assertThat(out).hasSize(1 << 16);
    }

    @Test
    void differentSeedsGiveUnrelatedPointSets() {
        // (x of set A, x of set B) over the same 4096 indices: uniform in the square (chi-square), while
        // the same seed twice would put every point on the diagonal.
        int n = 4096, bins = 8;
        int a = OwenSobol.mix32(11), b = OwenSobol.mix32(12);
        long[] count = new long[bins * bins];
        long onDiagonalSameSeed = 0;
        for (int i = 0; i < n; i++) {
            int xa = OwenSobol.x(OwenSobol.shuffle(i, a), a) >>> 29;
            int xb = OwenSobol.x(OwenSobol.shuffle(i, b), b) >>> 29;
            count[xa * bins + xb]++;
            onDiagonalSameSeed += xa == (OwenSobol.x(OwenSobol.shuffle(i, a), a) >>> 29) ? 1 : 0;
        }
        double[] expected = new double[bins * bins];
        java.util.Arrays.fill(expected, (double) n / (bins * bins));
        assertThat(ChiSquare.fromCounts(expected, count).pValue()).isGreaterThan(1e-4);
        assertThat(onDiagonalSameSeed).isEqualTo(n);
    }
}
