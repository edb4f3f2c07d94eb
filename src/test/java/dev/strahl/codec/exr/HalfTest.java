package dev.strahl.codec.exr;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Half conversion against a slow, obviously right reference: the nearest of all finite halfs. */
class HalfTest {

    /** The 31744 finite non-negative halfs as doubles, in the order of their bits (which is the order of their values). */
    private static final double[] POSITIVE = new double[0x7c00];

    static {
        for (int h = 0; h < POSITIVE.length; h++) {
            int e = h >>> 10;
            int f = h & 0x3ff;
            POSITIVE[h] = e == 0 ? f * 0x1p-24 : Math.scalb(1 + f / 1024.0, e - 15);
        }
    }

    /** Round to nearest, ties to even bits; beyond the largest half, the next "value" is 2^16 (infinity). */
    static int reference(float value) {
        if (Float.isNaN(value)) {
            return -1;
        }
        int sign = value < 0 || Float.floatToRawIntBits(value) == 0x80000000 ? 0x8000 : 0;
        double v = Math.abs((double) value);
        int lo = 0;
        int hi = POSITIVE.length;                // the largest index whose value is <= v
        while (hi - lo > 1) {
            int mid = (lo + hi) >>> 1;
            if (POSITIVE[mid] <= v) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        double next = lo + 1 < POSITIVE.length ? POSITIVE[lo + 1] : 65536;
        double below = v - POSITIVE[lo];
        double above = next - v;
        int h = below < above || below == above && (lo & 1) == 0 ? lo : lo + 1;
        return sign | h;                         // lo + 1 == 0x7c00 is infinity
    }

    private static void check(float f) {
        int expected = reference(f);
        int actual = Half.fromFloat(f);
        if (expected < 0) {
            assertThat(Float.isNaN(Half.toFloat(actual))).as("NaN %08x stays NaN", Float.floatToRawIntBits(f)).isTrue();
        } else if (actual != expected) {
            assertThat(Integer.toHexString(actual)).as("half of %s (%08x)", f, Float.floatToRawIntBits(f))
                    .isEqualTo(Integer.toHexString(expected));
        }
    }

    @Test
    void everyHalfSurvivesAFloatRoundTripBitForBitNaNPayloadsIncluded() {
        for (int h = 0; h < 1 << 16; h++) {
            assertThat(Half.fromFloat(Half.toFloat(h))).as("%04x", h).isEqualTo(h);
        }
    }

    @Test
    void toFloatGivesTheValueOfTheBits() {
        assertThat(Half.toFloat(0x3c00)).isEqualTo(1f);
        assertThat(Half.toFloat(0xc000)).isEqualTo(-2f);
        assertThat(Half.toFloat(0x7bff)).isEqualTo(65504f);
        assertThat(Half.toFloat(0x0001)).isEqualTo(0x1p-24f);
        assertThat(Half.toFloat(0x0400)).isEqualTo(0x1p-14f);
        assertThat(Half.toFloat(0x3555)).isEqualTo(0.333251953125f);
        assertThat(Float.floatToRawIntBits(Half.toFloat(0x8000))).isEqualTo(0x80000000);
        assertThat(Half.toFloat(0x7c00)).isEqualTo(Float.POSITIVE_INFINITY);
        assertThat(Half.toFloat(0xfc00)).isEqualTo(Float.NEGATIVE_INFINITY);
        assertThat(Half.toFloat(0x7e00)).isNaN();
    }

    @Test
    void roundsToNearestTiesToEvenAndOverflowsToInfinity() {
        assertThat(Half.fromFloat(65504f)).isEqualTo(0x7bff);
        assertThat(Half.fromFloat(65519.996f)).isEqualTo(0x7bff);             // just below the half-way point
        assertThat(Half.fromFloat(65520f)).isEqualTo(0x7c00);                 // half-way: to even, which is infinity
        assertThat(Half.fromFloat(1e9f)).isEqualTo(0x7c00);
        assertThat(Half.fromFloat(-1e9f)).isEqualTo(0xfc00);
        assertThat(Half.fromFloat(1 + 0x1p-11f)).isEqualTo(0x3c00);          // tie between 1 and 1 + 2^-10: to even (1)
        assertThat(Half.fromFloat(1 + 3 * 0x1p-11f)).isEqualTo(0x3c02);      // tie: to even (1 + 2^-9)
        assertThat(Half.fromFloat(0x1p-25f)).isEqualTo(0);                    // tie between 0 and 2^-24: to 0
        assertThat(Half.fromFloat(Math.nextUp(0x1p-25f))).isEqualTo(1);
        assertThat(Half.fromFloat(3 * 0x1p-25f)).isEqualTo(2);                // tie between 1 and 2 ulps: to 2
        assertThat(Half.fromFloat(-0f)).isEqualTo(0x8000);
        assertThat(Half.fromFloat(1e-30f)).isEqualTo(0);
    }

    @Test
    void agreesWithTheReferenceAtEveryMidpointAndAroundIt() {
        for (int h = 0; h < 0x7c00; h++) {
            double next = h + 1 < 0x7c00 ? POSITIVE[h + 1] : 65536;
            float mid = (float) ((POSITIVE[h] + next) / 2);    // exact: one bit more than a half needs
            for (float f : new float[] {mid, Math.nextDown(mid), Math.nextUp(mid), (float) POSITIVE[h], -mid, -(float) POSITIVE[h]}) {
                check(f);
            }
        }
    }

    @Test
    void agreesWithTheReferenceOnASpreadOfAllFloats() {
        for (long bits = 0; bits <= 0xffffffffL; bits += 4099) {
            check(Float.intBitsToFloat((int) bits));
        }
        SplittableRandom r = new SplittableRandom(7);
        for (int i = 0; i < 1_000_000; i++) {
            check(Float.intBitsToFloat(0x33000000 + r.nextInt(0x47800000 - 0x33000000)) * (r.nextBoolean() ? 1 : -1));
        }
    }
}
