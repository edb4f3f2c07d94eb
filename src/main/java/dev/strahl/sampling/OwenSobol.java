package dev.strahl.sampling;

/**
 * Shuffled, Owen-scrambled Sobol points in two dimensions (Burley, "Practical Hash-based Owen
 * Scrambling", JCGT 9(4), 2020), as 32-bit fixed-point values: the first two Sobol dimensions
 * (a (0,2)-sequence in base 2), the sample index shuffled by a nested uniform scramble and each
 * coordinate Owen-scrambled, all three from one seed.
 *
 * <p>For any seed, the points of indices [0, 2^m) form a (0,m,2)-net: every rectangle
 * [a/2^k, (a+1)/2^k) × [b/2^(m−k), (b+1)/2^(m−k)) holds exactly one. That holds for every
 * power-of-two prefix, so a render stopped early is still stratified. Each point on its own is
 * uniformly distributed, so estimates stay unbiased; different seeds give independent point sets
 * (which is what decorrelates the pairs of dimensions of {@link StratifiedSampler}).
 */
public final class OwenSobol {
    private OwenSobol() {}

    /** Direction numbers of the second Sobol dimension (primitive polynomial x + 1): v_k = v_{k−1} ^ (v_{k−1} >>> 1). */
    private static final int[] DIRECTIONS = new int[32];
    /** The second dimension as four byte-indexed tables: the XOR of the direction numbers of the set bits. */
    private static final int[] TABLES = new int[4 * 256];
    /** The same for the bit-reversed direction numbers: the second dimension, bit-reversed. */
    private static final int[] REVERSED_TABLES = new int[4 * 256];

    static {
        int v = 0x80000000;
        for (int k = 0; k < 32; k++) {
            DIRECTIONS[k] = v;
            v ^= v >>> 1;
        }
        for (int b = 0; b < 4; b++) {
            for (int i = 0; i < 256; i++) {
                int x = 0;
                for (int bit = 0; bit < 8; bit++) {
                    if ((i >>> bit & 1) != 0) {
                        x ^= DIRECTIONS[8 * b + bit];
                    }
                }
                TABLES[256 * b + i] = x;
                REVERSED_TABLES[256 * b + i] = Integer.reverse(x);
            }
        }
    }

    /** The first Sobol dimension of index i: the van der Corput radical inverse, i.e. i's bits reversed. */
    static int sobol0(int i) {
        return Integer.reverse(i);
    }

    /** The second Sobol dimension of index i (generator matrix: Pascal's triangle mod 2). */
    static int sobol1(int i) {
        return TABLES[i & 0xff] ^ TABLES[256 + (i >>> 8 & 0xff)] ^ TABLES[512 + (i >>> 16 & 0xff)] ^ TABLES[768 + (i >>> 24)];
    }

    /**
     * Laine and Karras' hash-based permutation, which on bit-reversed values acts like an Owen
     * scramble: each output bit depends only on the input bits below it (the constants are
     * Burley's, 2020).
     */
    static int laineKarras(int x, int seed) {
        x += seed;
        x ^= x * 0x6c50b47c;
        x ^= x * 0xb82f1e52;
        x ^= x * 0xc7afe638;
        x ^= x * 0x8d22f6e6;
        return x;
    }

    /** An Owen (nested uniform) scramble of the 32-bit fixed-point fraction x, chosen by the seed. */
    static int nestedUniformScramble(int x, int seed) {
        return Integer.reverse(laineKarras(Integer.reverse(x), seed));
    }

    /**
     * A well-mixed 32-bit hash ("lowbias32", C. Wellons, 2018, an improved MurmurHash3
     * finaliser); seeds of neighbouring pixels and dimensions come out unrelated.
     */
    public static int mix32(int x) {
        x ^= x >>> 16;
        x *= 0x7feb352d;
        x ^= x >>> 15;
        x *= 0x846ca68b;
        x ^= x >>> 16;
        return x;
    }

    /** {@code Integer.reverse(sobol1(i))}, from the reversed tables. */
    static int sobol1Reversed(int i) {
        return REVERSED_TABLES[i & 0xff] ^ REVERSED_TABLES[256 + (i >>> 8 & 0xff)] ^ REVERSED_TABLES[512 + (i >>> 16 & 0xff)]
                ^ REVERSED_TABLES[768 + (i >>> 24)];
    }

    /**
     * Point {@code index} of the point set chosen by {@code seed}: x in the high 32 bits, y in the
     * low 32 bits; the same values as {@link #x} and {@link #y} of the {@link #shuffle shuffled}
     * index, with the bit reversals that cancel left out (four instead of seven).
     */
    public static long point(int index, int seed) {
        int shuffled = Integer.reverse(laineKarras(Integer.reverse(index), seed));
        // x: NUS(sobol0(s)) = reverse(LK(reverse(reverse(s)))) = reverse(LK(s)); y: reverse(LK(reverse(sobol1(s)))).
        int x = Integer.reverse(laineKarras(shuffled, mix32(seed ^ 0x68bc21eb)));
        int y = Integer.reverse(laineKarras(sobol1Reversed(shuffled), mix32(seed ^ 0x02e5be93)));
        return (long) x << 32 | (y & 0xffffffffL);
    }

    /** The shuffled index of point {@code index} of the point set chosen by {@code seed}: the argument of {@link #x} and {@link #y}. */
    public static int shuffle(int index, int seed) {
        return nestedUniformScramble(index, seed);
    }

    /** First coordinate, as a 32-bit fraction, of the point with shuffled index {@code shuffled} of the set chosen by {@code seed}. */
    public static int x(int shuffled, int seed) {
        return nestedUniformScramble(sobol0(shuffled), mix32(seed ^ 0x68bc21eb));
    }

    /** Second coordinate, as a 32-bit fraction; see {@link #x}. */
    public static int y(int shuffled, int seed) {
        return nestedUniformScramble(sobol1(shuffled), mix32(seed ^ 0x02e5be93));
    }

    /** A 32-bit fraction as a double in [0, 1). */
    public static double toUnit(int fraction) {
        return (fraction & 0xffffffffL) * 0x1p-32;
    }
}
