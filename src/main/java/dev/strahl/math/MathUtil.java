package dev.strahl.math;

/** Small numeric helpers that JOML does not provide. */
public final class MathUtil {
    public static final double INV_PI = 1.0 / Math.PI;

    private MathUtil() {}

    /** sqrt that treats small negative arguments from round-off as zero. */
    public static double safeSqrt(double x) {
        return Math.sqrt(Math.max(0.0, x));
    }

    public static double clamp(double x, double lo, double hi) {
        return x < lo ? lo : (x > hi ? hi : x);
    }

    /** Power heuristic with exponent 2 (Veach 1997, eq. 9.13): w = a² / (a² + b²). */
    public static double powerHeuristic(double pdfA, double pdfB) {
        if (!(pdfA > 0)) {
            return 0;
        }
        double ratio = pdfB / pdfA;        // the ratio form cannot overflow as the squares can
        return 1 / (1 + ratio * ratio);
    }
}
