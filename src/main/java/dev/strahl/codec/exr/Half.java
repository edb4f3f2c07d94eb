package dev.strahl.codec.exr;

/**
 * IEEE 754 binary16 ("half", the EXR pixel type HALF) to and from float; Java 17 has no
 * {@code Float.float16ToFloat}. Half has 1 sign bit, 5 exponent bits (bias 15) and 10 fraction
 * bits: normal values from 2^-14 to 65504, subnormals down to 2^-24, then ±0, ±∞ and NaN.
 */
public final class Half {
    /** The largest finite half, 65504. */
    public static final float MAX_VALUE = 65504f;

    private Half() {
    }

    /**
     * The float of a half's bits, exactly (every half is a float). A NaN keeps its payload
     * (shifted into the float's fraction), so that {@link #fromFloat} gives back the same bits.
     *
     * @param half the 16 bits, in the low half of the int
     * @return the value
     */
    public static float toFloat(int half) {
        int sign = (half & 0x8000) << 16;
        int exponent = (half >>> 10) & 0x1f;
        int fraction = half & 0x3ff;
        if (exponent == 0) {                 // zero or subnormal: fraction · 2^-24
            float magnitude = fraction * 0x1p-24f;
            return sign == 0 ? magnitude : -magnitude;
        }
        if (exponent == 31) {                // infinity (fraction 0) or NaN
            return Float.intBitsToFloat(sign | 0x7f800000 | fraction << 13);
        }
        return Float.intBitsToFloat(sign | (exponent + 127 - 15) << 23 | fraction << 13);
    }

    /**
     * The half nearest to {@code value}, ties to the even one (IEEE 754's default rounding, as
     * Java 20's {@code Float.floatToFloat16} and numpy's float16 round; ExrOpenExrCrossCheckTest
     * compares with numpy). Magnitudes
     * from 65520 up round to infinity, as IEEE 754 prescribes: a HALF channel cannot hold them, and
     * saying so with ∞ is better than a clamped value that looks plausible; write FLOAT channels
     * for data that large. Values below 2^-25 in magnitude round to ±0; NaN stays NaN (the top
     * fraction bits kept, never turned into ∞).
     *
     * @param value any float
     * @return the half's 16 bits, in the low half of the int
     */
    public static int fromFloat(float value) {
        int bits = Float.floatToRawIntBits(value);
        int sign = (bits >>> 16) & 0x8000;
        int abs = bits & 0x7fffffff;
        if (abs >= 0x7f800000) {             // infinity or NaN
            int fraction = (abs & 0x7fffff) >>> 13;
            return abs == 0x7f800000 ? sign | 0x7c00 : sign | 0x7c00 | (fraction == 0 ? 0x200 : fraction);
        }
        if (abs >= 0x477ff000) {             // >= 65520, half-way between 65504 and 2^16: to infinity
            return sign | 0x7c00;
        }
        if (abs >= 0x38800000) {             // >= 2^-14: a normal half; 13 fraction bits are dropped
            int half = ((abs >>> 23) - 127 + 15) << 10 | (abs & 0x7fffff) >>> 13;
            int dropped = abs & 0x1fff;
            if (dropped > 0x1000 || dropped == 0x1000 && (half & 1) != 0) {
                half++;                      // a carry into the exponent is the right result too
            }
            return sign | half;
        }
        if (abs <= 0x33000000) {             // <= 2^-25: half-way to the smallest subnormal or below, to zero
            return sign;
        }
        // a subnormal half: the value in units of 2^-24, from the 24-bit significand
        int exponent = abs >>> 23;           // 102 ..< 113
        int significand = (abs & 0x7fffff) | 0x800000;
        int shift = 126 - exponent;          // 14 ..= 24
        int half = significand >>> shift;
        int dropped = significand & ((1 << shift) - 1);
        int halfway = 1 << (shift - 1);
        if (dropped > halfway || dropped == halfway && (half & 1) != 0) {
            half++;                          // may become 0x400, the smallest normal: also right
        }
        return sign | half;
    }
}
