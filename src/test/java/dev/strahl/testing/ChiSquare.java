package dev.strahl.testing;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.joml.Vector2d;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Pearson's chi-square goodness-of-fit test of a sampling routine against the density it claims,
 * as pbrt (src/pbrt/util/tests, {@code chi2test}) and Mitsuba 3 ({@code mitsuba.chi2}) do it.
 *
 * <ol>
 *   <li>Draw {@code sampleCount} samples from uniform numbers (u1, u2) of a fixed-seed
 *       {@link SplittableRandom} and histogram them over a grid of cells of a chart of the domain.
 *       Directions use the equal-area chart (cosθ, φ): {@value #DEFAULT_COS_THETA_BINS} ×
 *       {@value #DEFAULT_PHI_BINS} cells over the whole sphere by default.</li>
 *   <li>Expected count of a cell = sampleCount × ∫ pdf over the cell, by composite Simpson
 *       quadrature ({@value #SIMPSON_INTERVALS} × {@value #SIMPSON_INTERVALS} intervals per cell)
 *       whose outermost nodes sit a hair inside the cell. So a density that jumps on a cell edge
 *       (the rim of a hemisphere at cosθ = 0) is integrated with its one-sided limits instead of the
 *       value of the wrong side.</li>
 *   <li>A sampler may fail (return false, an absorbed sample): then the density integrates to the
 *       probability of success, and the failures form one more cell with the missing mass.</li>
 *   <li>Cells with an expected count below {@value #MIN_EXPECTED} are pooled (the usual validity
 *       condition of the chi-square approximation); a sample in a cell whose expected count is zero
 *       rejects at once (p = 0).</li>
 *   <li>The statistic Σ (O − E)²/E has, under the null hypothesis, a chi-square distribution with
 *       cells − 1 degrees of freedom (no fitted parameters); the p-value is its upper tail
 *       Q(dof/2, statistic/2), the regularised upper incomplete gamma function.</li>
 * </ol>
 *
 * <p><b>Significance.</b> A test suite that runs k independent chi-square tests at level α each
 * raises a false alarm with probability 1 − (1 − α)^k. To hold the whole suite at α = 0.01,
 * each test uses the Šidák level {@link #sidak(double, int) 1 − (1 − α)^(1/k)} (pbrt does the
 * same). With fixed seeds the outcome is deterministic anyway; the correction keeps the tests
 * honest when seeds change, and the sample counts are large enough that wrong densities have
 * p-values many orders of magnitude below any such level.
 */
public final class ChiSquare {
    /** Cells with fewer expected samples than this are pooled. */
    public static final double MIN_EXPECTED = 5;
    public static final int DEFAULT_COS_THETA_BINS = 10;
    public static final int DEFAULT_PHI_BINS = 20;
    /** Simpson intervals per cell and axis (even). */
    static final int SIMPSON_INTERVALS = 8;
    /** The outermost Simpson nodes sit this fraction of a cell inside it. */
    private static final double EDGE_INSET = 1e-9;
    private static final double TWO_PI = 2 * Math.PI;

    private ChiSquare() {}

    /** Writes a direction (unit vector) for the uniform numbers (u1, u2) into dest; false if the sample is absorbed. */
    @FunctionalInterface
    public interface DirectionSampler {
        boolean sample(double u1, double u2, Vector3d dest);
    }

    /** Density of a {@link DirectionSampler} with respect to solid angle. */
    @FunctionalInterface
    public interface DirectionPdf {
        double pdf(Vector3dc w);
    }

    /** Writes a point of a planar domain for the uniform numbers (u1, u2) into dest; false if absorbed. */
    @FunctionalInterface
    public interface PointSampler {
        boolean sample(double u1, double u2, Vector2d dest);
    }

    /** Density of a {@link PointSampler} with respect to area. */
    @FunctionalInterface
    public interface PointPdf {
        double pdf(double x, double y);
    }

    /**
     * A parametrisation of a planar domain by the unit square (s, t), over whose uniform grid the
     * cells are laid out. It need not be area-preserving: the Jacobian enters the expected counts.
     */
    public interface Chart {
        /** Writes the chart coordinates (s, t) ∈ [0, 1]² of (x, y) into dest; false if (x, y) is outside the domain. */
        boolean toChart(double x, double y, Vector2d dest);

        /** Writes the point of chart coordinates (s, t) into dest and returns |∂(x, y)/∂(s, t)|. */
        double fromChart(double s, double t, Vector2d dest);

        /** The unit disk in polar coordinates: s = r, t = φ/2π; Jacobian 2π r. */
        static Chart unitDisk() {
            return new Chart() {
                @Override
                public boolean toChart(double x, double y, Vector2d dest) {
                    double r = Math.sqrt(x * x + y * y);
                    if (!(r <= 1)) {
                        return false;
                    }
                    dest.set(r, angle(x, y) / TWO_PI);
                    return true;
                }

                @Override
                public double fromChart(double s, double t, Vector2d dest) {
                    double phi = TWO_PI * t;
                    dest.set(s * Math.cos(phi), s * Math.sin(phi));
                    return TWO_PI * s;
                }
            };
        }

        /**
         * The triangle {x ≥ 0, y ≥ 0, x + y ≤ 1} (barycentric coordinates (b0, b1)) in Duffy's
         * collapsed coordinates: s = x + y, t = y / (x + y); x = s(1 − t), y = s t, Jacobian s.
         * Deliberately not the square-root map that uniform triangle sampling uses.
         */
        static Chart unitTriangle() {
            return new Chart() {
                @Override
                public boolean toChart(double x, double y, Vector2d dest) {
                    double s = x + y;
                    if (!(x >= 0 && y >= 0 && s <= 1)) {
                        return false;
                    }
                    dest.set(s, s > 0 ? y / s : 0);
                    return true;
                }

                @Override
                public double fromChart(double s, double t, Vector2d dest) {
                    dest.set(s * (1 - t), s * t);
                    return s;
                }
            };
        }
    }

    /** The outcome of one test. {@code detail} names the cells that contribute most, for failure messages. */
    public record Result(double statistic, int dof, double pValue, String detail) {
        public boolean accepted(double alpha) {
            return pValue >= alpha;
        }

        /** Fails unless the null hypothesis (samples follow the pdf) survives at level alpha. */
        public Result assertAccepted(double alpha) {
            if (!accepted(alpha)) {
                throw new AssertionError(String.format(Locale.ROOT,
                        "chi-square test rejects the null hypothesis (samples follow the pdf): %s < alpha %.3g%n%s",
                        summary(), alpha, detail));
            }
            return this;
        }

        /** Fails unless the null hypothesis is rejected at level alpha (for testing the test). */
        public Result assertRejected(double alpha) {
            if (accepted(alpha)) {
                throw new AssertionError(String.format(Locale.ROOT,
                        "chi-square test should reject, but %s >= alpha %.3g%n%s", summary(), alpha, detail));
            }
            return this;
        }

        public String summary() {
            return String.format(Locale.ROOT, "chi2 = %.4g, dof = %d, p = %.4g", statistic, dof, pValue);
        }
    }

    /** The Šidák level that keeps the chance of any false alarm among {@code tests} independent tests at {@code alpha}. */
    public static double sidak(double alpha, int tests) {
        return 1 - Math.pow(1 - alpha, 1.0 / tests);
    }

    // ------------------------------------------------------------------------------------------
    // Directions on the sphere

    public static Result test(DirectionSampler sampler, DirectionPdf pdf, int sampleCount, long seed) {
        return test(sampler, pdf, sampleCount, seed, DEFAULT_COS_THETA_BINS, DEFAULT_PHI_BINS);
    }

    /**
     * Chi-square test of a direction sampler over {@code cosThetaBins} × {@code phiBins} equal-area
     * cells of the whole sphere (cosθ = w.z ∈ [−1, 1], φ = atan2(w.y, w.x) ∈ [0, 2π)). Fails at
     * once, with the offending sample, if a direction is not finite or not of unit length.
     */
    public static Result test(DirectionSampler sampler, DirectionPdf pdf, int sampleCount, long seed,
                              int cosThetaBins, int phiBins) {
        return test(sampler, pdf, sampleCount, seed, cosThetaBins, phiBins, SIMPSON_INTERVALS);
    }

    /**
     * As {@link #test(DirectionSampler, DirectionPdf, int, long, int, int)} with {@code intervals}
     * × {@code intervals} Simpson intervals per cell (even) instead of {@value #SIMPSON_INTERVALS}:
     * for a density that jumps inside cells (along a curve that no cell edge follows) or peaks
     * within a cell, where the default rule's error exceeds the sampling noise.
     */
    public static Result test(DirectionSampler sampler, DirectionPdf pdf, int sampleCount, long seed,
                              int cosThetaBins, int phiBins, int intervals) {
        Vector3d w = new Vector3d();
        double[] expected = expectedCounts(cosThetaBins, phiBins, sampleCount, intervals,
                (s, t) -> pdf.pdf(sphereFromChart(s, t, w)) * 4 * Math.PI);
        long[] observed = new long[cosThetaBins * phiBins + 1];
        SplittableRandom random = new SplittableRandom(seed);
        for (int i = 0; i < sampleCount; i++) {
            double u1 = random.nextDouble(), u2 = random.nextDouble();
            if (!sampler.sample(u1, u2, w)) {
                observed[observed.length - 1]++;
                continue;
            }
            if (!w.isFinite() || Math.abs(w.length() - 1) > 1e-6) {
                throw new AssertionError("sampler returned " + w + " (not a finite unit vector) for u = (" + u1 + ", " + u2 + ")");
            }
            int a = bin(0.5 * (w.z + 1), cosThetaBins);
            int b = bin(angle(w.x, w.y) / TWO_PI, phiBins);
            observed[a * phiBins + b]++;
        }
        return fromCounts(withAbsorbed(expected, sampleCount), observed,
                cell -> cellName(cell, cosThetaBins, phiBins, "cosθ", -1, 2, "φ/2π"));
    }

    /** ∫ pdf dω over the sphere, by the same quadrature as the expected counts (fine grid). */
    public static double integrateOverSphere(DirectionPdf pdf) {
        Vector3d w = new Vector3d();
        double[] cells = expectedCounts(64, 128, 1, (s, t) -> pdf.pdf(sphereFromChart(s, t, w)) * 4 * Math.PI);
        return sum(cells);
    }

    private static Vector3d sphereFromChart(double s, double t, Vector3d dest) {
        double z = 2 * s - 1;
        double r = Math.sqrt(Math.max(0, 1 - z * z));
        double phi = TWO_PI * t;
        return dest.set(r * Math.cos(phi), r * Math.sin(phi), z);
    }

    // ------------------------------------------------------------------------------------------
    // Points of a planar domain

    /**
     * Chi-square test of a planar point sampler over {@code sBins} × {@code tBins} cells of a
     * chart of its domain. Fails at once, with the offending sample, if a point is outside the domain.
     */
    public static Result test2d(PointSampler sampler, PointPdf pdf, Chart chart, int sBins, int tBins,
                                int sampleCount, long seed) {
        Vector2d p = new Vector2d();
        double[] expected = expectedCounts(sBins, tBins, sampleCount, (s, t) -> {
            double jacobian = chart.fromChart(s, t, p);
            return jacobian * pdf.pdf(p.x, p.y);
        });
        long[] observed = new long[sBins * tBins + 1];
        Vector2d st = new Vector2d();
        SplittableRandom random = new SplittableRandom(seed);
        for (int i = 0; i < sampleCount; i++) {
            double u1 = random.nextDouble(), u2 = random.nextDouble();
            if (!sampler.sample(u1, u2, p)) {
                observed[observed.length - 1]++;
                continue;
            }
            if (!chart.toChart(p.x, p.y, st)) {
                throw new AssertionError("sampler returned " + p + " outside the domain for u = (" + u1 + ", " + u2 + ")");
            }
            observed[bin(st.x, sBins) * tBins + bin(st.y, tBins)]++;
        }
        return fromCounts(withAbsorbed(expected, sampleCount), observed,
                cell -> cellName(cell, sBins, tBins, "s", 0, 1, "t"));
    }

    /** ∫ pdf dA over the chart's domain, by the same quadrature as the expected counts (fine grid). */
    public static double integrate2d(PointPdf pdf, Chart chart) {
        Vector2d p = new Vector2d();
        return sum(expectedCounts(64, 64, 1, (s, t) -> chart.fromChart(s, t, p) * pdf.pdf(p.x, p.y)));
    }

    // ------------------------------------------------------------------------------------------
    // The statistic

    /** Pearson's test on given cell counts, pooling cells with expected counts below {@value #MIN_EXPECTED}. */
    public static Result fromCounts(double[] expected, long[] observed) {
        return fromCounts(expected, observed, cell -> "cell " + cell);
    }

    private static Result fromCounts(double[] expected, long[] observed, java.util.function.IntFunction<String> names) {
        if (expected.length != observed.length) {
            throw new IllegalArgumentException("expected and observed differ in length: " + expected.length + " vs " + observed.length);
        }
        Integer[] order = new Integer[expected.length];
        for (int i = 0; i < order.length; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (a, b) -> Double.compare(expected[a], expected[b]));

        double statistic = 0;
        int cells = 0;
        double pooledExpected = 0;
        long pooledObserved = 0;
        List<String> worst = new ArrayList<>();
        double[] contribution = new double[expected.length];
        for (int index : order) {
            double e = expected[index];
            long o = observed[index];
            if (!(e >= 0) || !Double.isFinite(e)) {
                throw new IllegalArgumentException("expected count of " + names.apply(index) + " is " + e);
            }
            if (e == 0) {
                if (o > 0) {
                    String detail = o + " samples in " + names.apply(index) + ", where the pdf integrates to 0";
                    return new Result(Double.POSITIVE_INFINITY, Math.max(1, cells), 0, detail);
                }
            } else if (e < MIN_EXPECTED || (pooledExpected > 0 && pooledExpected < MIN_EXPECTED)) {
                pooledExpected += e;
                pooledObserved += o;
            } else {
                double diff = o - e;
                contribution[index] = diff * diff / e;
                statistic += contribution[index];
                cells++;
            }
        }
        if (pooledExpected > 0) {
            double diff = pooledObserved - pooledExpected;
            statistic += diff * diff / pooledExpected;
            cells++;
            worst.add(String.format(Locale.ROOT, "  pooled cells: observed %d, expected %.1f", pooledObserved, pooledExpected));
        }
        int dof = cells - 1;
        if (dof < 1) {
            throw new IllegalStateException("too few cells with expected counts >= " + MIN_EXPECTED + " for a chi-square test");
        }
        Integer[] byContribution = order.clone();
        Arrays.sort(byContribution, (a, b) -> Double.compare(contribution[b], contribution[a]));
        for (int k = 0; k < Math.min(5, byContribution.length); k++) {
            int i = byContribution[k];
            if (contribution[i] > 0) {
                worst.add(String.format(Locale.ROOT, "  %s: observed %d, expected %.1f, (O-E)^2/E = %.3g",
                        names.apply(i), observed[i], expected[i], contribution[i]));
            }
        }
        return new Result(statistic, dof, chiSquareSurvival(statistic, dof),
                "largest contributions:" + System.lineSeparator() + String.join(System.lineSeparator(), worst));
    }

    /** P(X ≥ x) for X chi-square distributed with {@code dof} degrees of freedom: Q(dof/2, x/2). */
    public static double chiSquareSurvival(double x, int dof) {
        if (dof < 1) {
            throw new IllegalArgumentException("degrees of freedom must be >= 1, got " + dof);
        }
        if (x <= 0) {
            return 1;
        }
        if (x == Double.POSITIVE_INFINITY) {
            return 0;
        }
        return regularizedGammaQ(0.5 * dof, 0.5 * x);
    }

    // ------------------------------------------------------------------------------------------
    // Incomplete gamma function (Numerical Recipes, 3rd ed., §6.2)

    private static final int MAX_ITERATIONS = 100_000;
    private static final double EPS = 1e-16;
    private static final double FPMIN = Double.MIN_NORMAL / EPS;

    /** Regularised lower incomplete gamma P(a, x) = γ(a, x)/Γ(a), for a > 0, x ≥ 0. */
    public static double regularizedGammaP(double a, double x) {
        checkGammaArguments(a, x);
        if (x == 0) {
            return 0;
        }
        return x < a + 1 ? gammaSeries(a, x) : 1 - gammaContinuedFraction(a, x);
    }

    /** Regularised upper incomplete gamma Q(a, x) = 1 − P(a, x), accurate in the far tail too. */
    public static double regularizedGammaQ(double a, double x) {
        checkGammaArguments(a, x);
        if (x == 0) {
            return 1;
        }
        return x < a + 1 ? 1 - gammaSeries(a, x) : gammaContinuedFraction(a, x);
    }

    private static void checkGammaArguments(double a, double x) {
        if (!(a > 0) || !(x >= 0)) {
            throw new IllegalArgumentException("incomplete gamma needs a > 0 and x >= 0, got a = " + a + ", x = " + x);
        }
    }

    /** P(a, x) by its series e^−x x^a / Γ(a) · Σ x^n / (a (a+1) … (a+n)); converges fast for x < a + 1. */
    private static double gammaSeries(double a, double x) {
        double ap = a;
        double term = 1 / a;
        double sum = term;
        for (int n = 0; n < MAX_ITERATIONS; n++) {
            ap += 1;
            term *= x / ap;
            sum += term;
            if (Math.abs(term) < Math.abs(sum) * EPS) {
                return sum * Math.exp(-x + a * Math.log(x) - logGamma(a));
            }
        }
        throw new ArithmeticException("incomplete gamma series did not converge for a = " + a + ", x = " + x);
    }

    /** Q(a, x) by its continued fraction (modified Lentz); converges fast for x ≥ a + 1. */
    private static double gammaContinuedFraction(double a, double x) {
        double b = x + 1 - a;
        double c = 1 / FPMIN;
        double d = 1 / b;
        double h = d;
        for (int i = 1; i < MAX_ITERATIONS; i++) {
            double an = -i * (i - a);
            b += 2;
            d = an * d + b;
            if (Math.abs(d) < FPMIN) {
                d = FPMIN;
            }
            c = b + an / c;
            if (Math.abs(c) < FPMIN) {
                c = FPMIN;
            }
            d = 1 / d;
            double delta = d * c;
            h *= delta;
            if (Math.abs(delta - 1) < EPS) {
                return Math.exp(-x + a * Math.log(x) - logGamma(a)) * h;
            }
        }
        throw new ArithmeticException("incomplete gamma continued fraction did not converge for a = " + a + ", x = " + x);
    }

    private static final double[] LANCZOS = {
        0.99999999999980993, 676.5203681218851, -1259.1392167224028, 771.32342877765313,
        -176.61502916214059, 12.507343278686905, -0.13857109526572012, 9.9843695780195716e-6,
        1.5056327351493116e-7};

    /** ln Γ(x) for x > 0: Lanczos approximation with g = 7, n = 9 (relative error ~1e-15), reflection below 1/2. */
    public static double logGamma(double x) {
        if (!(x > 0)) {
            throw new IllegalArgumentException("logGamma needs x > 0, got " + x);
        }
        if (x < 0.5) {
            return Math.log(Math.PI / Math.sin(Math.PI * x)) - logGamma(1 - x);
        }
        x -= 1;
        double sum = LANCZOS[0];
        for (int i = 1; i < LANCZOS.length; i++) {
            sum += LANCZOS[i] / (x + i);
        }
        double t = x + 7.5;
        return 0.5 * Math.log(TWO_PI) + (x + 0.5) * Math.log(t) - t + Math.log(sum);
    }

    // ------------------------------------------------------------------------------------------
    // Quadrature and binning

    @FunctionalInterface
    private interface ChartDensity {
        /** Density with respect to ds dt on the unit square (pdf × Jacobian). */
        double at(double s, double t);
    }

    /** scale × ∫ f over each cell of an sBins × tBins grid of the unit square, composite Simpson per cell. */
    private static double[] expectedCounts(int sBins, int tBins, double scale, ChartDensity f) {
        return expectedCounts(sBins, tBins, scale, SIMPSON_INTERVALS, f);
    }

    private static double[] expectedCounts(int sBins, int tBins, double scale, int m, ChartDensity f) {
        if (sBins < 1 || tBins < 1) {
            throw new IllegalArgumentException("need at least one bin per axis, got " + sBins + " x " + tBins);
        }
        if (m < 2 || m % 2 != 0) {
            throw new IllegalArgumentException("Simpson's rule needs an even number of intervals, got " + m);
        }
        double[] weight = new double[m + 1];
        for (int k = 0; k <= m; k++) {
            weight[k] = k == 0 || k == m ? 1 : (k % 2 == 1 ? 4 : 2);
        }
        double[] sNode = new double[m + 1];
        double[] tNode = new double[m + 1];
        double[] cells = new double[sBins * tBins];
        double ds = 1.0 / sBins, dt = 1.0 / tBins;
        for (int a = 0; a < sBins; a++) {
            nodes(a * ds, ds, sNode);
            for (int b = 0; b < tBins; b++) {
                nodes(b * dt, dt, tNode);
                double sum = 0;
                for (int i = 0; i <= m; i++) {
                    double row = 0;
                    for (int j = 0; j <= m; j++) {
                        double v = f.at(sNode[i], tNode[j]);
                        if (!(v >= 0) || !Double.isFinite(v)) {
                            throw new AssertionError("pdf is " + v + " (negative or not finite) at chart point (" + sNode[i] + ", " + tNode[j] + ")");
                        }
                        row += weight[j] * v;
                    }
                    sum += weight[i] * row;
                }
                cells[a * tBins + b] = scale * sum * (ds / (3 * m)) * (dt / (3 * m));
            }
        }
        return cells;
    }

    /** Simpson nodes of one cell [start, start + width], the two end nodes moved inside by a hair. */
    private static void nodes(double start, double width, double[] dest) {
        int m = dest.length - 1;
        for (int k = 0; k <= m; k++) {
            dest[k] = start + width * k / m;
        }
        dest[0] = start + EDGE_INSET * width;
        dest[m] = start + width * (1 - EDGE_INSET);
    }

    /** Appends the absorbed cell: the mass the pdf leaves over (zero for a pdf that integrates to one). */
    private static double[] withAbsorbed(double[] expected, int sampleCount) {
        double[] all = Arrays.copyOf(expected, expected.length + 1);
        double missing = sampleCount - sum(expected);
        // Quadrature round-off of a normalised pdf must not turn into a phantom cell.
        all[expected.length] = missing > 1e-6 * sampleCount ? missing : 0;
        return all;
    }

    private static int bin(double x, int bins) {
        int b = (int) (x * bins);
        return b < 0 ? 0 : Math.min(b, bins - 1);
    }

    /** φ = atan2(y, x) in [0, 2π). */
    private static double angle(double x, double y) {
        double phi = Math.atan2(y, x);
        return phi < 0 ? phi + TWO_PI : phi;
    }

    private static double sum(double[] values) {
        double s = 0;
        for (double v : values) {
            s += v;
        }
        return s;
    }

    private static String cellName(int cell, int aBins, int bBins, String aName, double aMin, double aWidth, String bName) {
        if (cell == aBins * bBins) {
            return "absorbed samples";
        }
        int a = cell / bBins, b = cell % bBins;
        return String.format(Locale.ROOT, "cell %s in [%.3f, %.3f), %s in [%.3f, %.3f)",
                aName, aMin + aWidth * a / aBins, aMin + aWidth * (a + 1) / aBins,
                bName, (double) b / bBins, (double) (b + 1) / bBins);
    }
}
