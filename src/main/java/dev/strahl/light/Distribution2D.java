package dev.strahl.light;

/**
 * A piecewise-constant density over the unit square [0, 1)², on a grid of {@code nu × nv} cells
 * with non-negative weights: a row is chosen from the marginal distribution of the row sums, then
 * a column from that row's conditional distribution, each by inverting its cumulative sum
 * (pbrt-v4 §A.5, {@code PiecewiseConstant2D}). The density of a point in cell (i, j) is
 * w_ij · nu · nv / Σ w. Flat arrays, immutable, thread-safe; sampling allocates nothing.
 */
final class Distribution2D {
    private final int nu, nv;
    private final float[] weight;          // nu · nv cell weights, row by row
    private final double[] conditional;    // per row: nu + 1 cumulative sums, normalised to end at 1
    private final double[] marginal;       // nv + 1 cumulative row sums, normalised to end at 1
    private final double total;

    /**
     * @param weights nu · nv cell weights, row j's cells at [j·nu, (j+1)·nu); finite, ≥ 0, not all 0
     */
    Distribution2D(int nu, int nv, float[] weights) {
        if (nu <= 0 || nv <= 0 || weights.length != (long) nu * nv) {
            throw new IllegalArgumentException(nu + "x" + nv + " cells for " + weights.length + " weights");
        }
        this.nu = nu;
        this.nv = nv;
        this.weight = weights.clone();
        this.conditional = new double[nv * (nu + 1)];
        this.marginal = new double[nv + 1];
        double sum = 0;
        for (int j = 0; j < nv; j++) {
            int c = j * (nu + 1);
            double row = 0;
            for (int i = 0; i < nu; i++) {
                float w = weight[j * nu + i];
                if (!(w >= 0) || Float.isInfinite(w)) {
                    throw new IllegalArgumentException("weight of cell (" + i + ", " + j + ") is " + w);
                }
                row += w;
                conditional[c + i + 1] = row;
            }
            for (int i = 1; i <= nu; i++) {
                conditional[c + i] = row > 0 ? conditional[c + i] / row : (double) i / nu;
            }
            sum += row;
            marginal[j + 1] = sum;
        }
        if (!(sum > 0)) {
            throw new IllegalArgumentException("all weights are zero");
        }
        for (int j = 1; j <= nv; j++) {
            marginal[j] /= sum;
        }
        this.total = sum;
    }

    int columns() {
        return nu;
    }

    int rows() {
        return nv;
    }

    /**
     * Samples a point of the square: writes (u, v) into {@code dest[0..1]} and returns its density
     * (0 only for a cell of weight 0, which the inversion never picks).
     */
    double sample(double u1, double u2, double[] dest) {
        int j = find(marginal, 0, nv, u2);
        double m0 = marginal[j], m1 = marginal[j + 1];
        double dv = m1 > m0 ? (u2 - m0) / (m1 - m0) : 0.5;
        int c = j * (nu + 1);
        int i = find(conditional, c, nu, u1);
        double c0 = conditional[c + i], c1 = conditional[c + i + 1];
        double du = c1 > c0 ? (u1 - c0) / (c1 - c0) : 0.5;
        dest[0] = Math.min((i + clamp01(du)) / nu, Math.nextDown(1.0));
        dest[1] = Math.min((j + clamp01(dv)) / nv, Math.nextDown(1.0));
        return density(i, j);
    }

    /** The density at (u, v) in [0, 1]². */
    double pdf(double u, double v) {
        int i = Math.min((int) (u * nu), nu - 1);
        int j = Math.min((int) (v * nv), nv - 1);
        return density(Math.max(i, 0), Math.max(j, 0));
    }

    /** The density of any point of cell (i, j). */
    double density(int i, int j) {
        return weight[j * nu + i] * ((double) nu * nv / total);
    }

    private static double clamp01(double x) {
        return x < 0 ? 0 : x > 1 ? 1 : x;
    }

    /**
     * The index i in [0, n) of the interval [cdf[off+i], cdf[off+i+1]) that holds u, skipping
     * empty intervals: the last i with cdf[off+i] ≤ u and a non-empty interval.
     */
    private static int find(double[] cdf, int off, int n, double u) {
        int lo = 0, hi = n - 1;                    // invariant: the answer lies in [lo, hi]
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (cdf[off + mid] <= u) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        // u == cdf[off + lo] at the end of empty intervals: step past them to one that has weight
        while (lo < n - 1 && !(cdf[off + lo + 1] > cdf[off + lo])) {
            lo++;
        }
        while (lo > 0 && !(cdf[off + lo + 1] > cdf[off + lo])) {
            lo--;
        }
        return lo;
    }
}
