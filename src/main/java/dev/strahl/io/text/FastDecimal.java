package dev.strahl.io.text;

/**
 * The fast path of the text readers' number parsing, for plain decimals ({@code [+-]digits[.digits]})
 * with at most {@value #MAX_SIGNIFICANT} significant digits and fewer than 23 decimals: the digits
 * as an exact integer (below 2^53) divided by an exact power of ten (at most 10^22) is one
 * correctly rounded IEEE operation, so the result equals {@link Double#parseDouble} bit for bit
 * (Clinger 1990, "How to read floating point numbers accurately"). Anything else (exponents,
 * more digits, nan, inf, stray characters) gives NaN, and the caller hands the text to the slow,
 * general parser.
 *
 * <p>There are two overloads with the same loop: one over a {@code String} (OBJ and MTL lines)
 * and one over bytes (ASCII PLY, read straight from its buffer without a String per value). They
 * stand side by side here so that they cannot drift apart; {@code FastDecimalTest} holds both to
 * {@code parseDouble}.
 */
public final class FastDecimal {
    /** More significant digits than this may not fit a double's 53-bit mantissa exactly. */
    static final int MAX_SIGNIFICANT = 15;
    /** The powers of ten that are exact doubles. */
    private static final double[] POW10 = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22
    };

    private FastDecimal() {
    }

    /** The plain decimal in {@code s[from, to)}, or NaN if it is not one the fast path takes. */
    public static double parse(String s, int from, int to) {
        int i = from;
        boolean negative = false;
        if (i < to && (s.charAt(i) == '-' || s.charAt(i) == '+')) {
            negative = s.charAt(i) == '-';
            i++;
        }
        long mantissa = 0;
        int significant = 0;
        int decimals = 0;
        boolean dot = false;
        boolean digit = false;
        for (; i < to; i++) {
            char c = s.charAt(i);
            if (c >= '0' && c <= '9') {
                digit = true;
                decimals += dot ? 1 : 0;
                if (mantissa == 0 && c == '0') {
                    continue;
                }
                if (++significant > MAX_SIGNIFICANT) {
                    return Double.NaN;
                }
                mantissa = mantissa * 10 + (c - '0');
            } else if (c == '.' && !dot) {
                dot = true;
            } else {
                return Double.NaN;
            }
        }
        return digit ? value(mantissa, decimals, negative) : Double.NaN;
    }

    /** The same for the ASCII bytes {@code s[from, to)}. */
    public static double parse(byte[] s, int from, int to) {
        int i = from;
        boolean negative = false;
        if (i < to && (s[i] == '-' || s[i] == '+')) {
            negative = s[i] == '-';
            i++;
        }
        long mantissa = 0;
        int significant = 0;
        int decimals = 0;
        boolean dot = false;
        boolean digit = false;
        for (; i < to; i++) {
            byte c = s[i];
            if (c >= '0' && c <= '9') {
                digit = true;
                decimals += dot ? 1 : 0;
                if (mantissa == 0 && c == '0') {
                    continue;
                }
                if (++significant > MAX_SIGNIFICANT) {
                    return Double.NaN;
                }
                mantissa = mantissa * 10 + (c - '0');
            } else if (c == '.' && !dot) {
                dot = true;
            } else {
                return Double.NaN;
            }
        }
        return digit ? value(mantissa, decimals, negative) : Double.NaN;
    }

    /** ±mantissa / 10^decimals, one correctly rounded division; NaN if 10^decimals is not exact. */
    private static double value(long mantissa, int decimals, boolean negative) {
        if (decimals >= POW10.length) {
            return Double.NaN;
        }
        double value = mantissa / POW10[decimals];
        return negative ? -value : value;
    }
}
