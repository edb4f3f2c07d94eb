package dev.strahl.testing;

import dev.strahl.color.MutableRgb;
import dev.strahl.material.Bsdf;
import dev.strahl.material.BsdfSample;
import dev.strahl.image.Rgb;
import dev.strahl.sampling.Warp;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.function.Supplier;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * The properties every {@link Bsdf} must have (DESIGN.md §5, STYLE.md habit 12), for any
 * implementation, in its local frame (z = shading normal, wo and wi pointing away from the surface):
 *
 * <ul>
 *   <li>{@link #assertSamplingMatchesPdf}: chi-square test of {@code sample} against {@code pdf}
 *       for a fixed wo (non-delta lobes only; delta samples count as "absorbed", which is exactly
 *       the mass the non-delta pdf leaves over);</li>
 *   <li>{@link #assertSampleConsistent}: every sample has a unit wi, a finite positive pdf equal to
 *       {@code pdf(wo, wi)} and weight = eval·|cosθi|/pdf (non-delta samples), and a finite
 *       non-negative weight (all samples); {@link #assertPdfCoversEval}: wherever f &gt; 0 the pdf is
 *       &gt; 0 too, else sampling alone would be biased;</li>
 *   <li>{@link #assertReciprocal}: f(wo, wi) = f(wi, wo);</li>
 *   <li>{@link #assertEnergyAtMostOne}: the directional albedo ∫ f(wo, wi) |cosθi| dωi (delta lobes
 *       included, through the sample weights) is at most 1 in every channel, for many wo.</li>
 * </ul>
 *
 * <p>The BSDF's lobe-selection number {@code uc} is drawn from its own seeded stream, so every
 * check is deterministic. Two-sided BSDFs are only asked about wo in the upper hemisphere (the
 * integrator turns the frame to the side of wo); BSDFs that are not two-sided (dielectrics) about
 * both. Reciprocity and energy are checked in the form that holds for reflection; a transmissive
 * BSDF whose weights carry the (ηi/ηt)² radiance scaling (a dielectric seen from inside
 * "reflects" about 2.2 at η = 1.5) needs its own, η-aware, transmission checks.
 */
public final class BsdfAssert {
    /** Relative tolerance of identities that only round-off separates. */
    private static final double REL = 1e-9;
    /** Monte Carlo estimates may exceed a bound by this many standard errors before a check fails. */
    private static final double Z = 5;

    private BsdfAssert() {}

    /** A unit direction at polar angle θ from the normal (z) and azimuth φ, both in degrees. */
    public static Vector3d direction(double thetaDegrees, double phiDegrees) {
        double theta = Math.toRadians(thetaDegrees), phi = Math.toRadians(phiDegrees);
        return new Vector3d(Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta));
    }

    // ---------------------------------------------------------------------------------------------
    // Sampling against pdf

    /** Default chart of {@link #chiSquare}: 20 cells in cosθ by 40 in φ over the sphere. */
    public static final int COS_THETA_BINS = 20, PHI_BINS = 40;

    /**
     * Chi-square test of the directions {@code sample} draws for {@code wo} against {@code pdf(wo, ·)}
     * over {@value #COS_THETA_BINS} × {@value #PHI_BINS} equal-area cells. Failed and delta samples
     * count as absorbed.
     *
     * <p>The cells must be finer than the narrowest lobe, because {@link ChiSquare} integrates the pdf
     * over each cell with a fixed 8 × 8 Simpson rule: with {@link ChiSquare#test}'s default 10 × 20
     * cells, a correct Beckmann lobe of α = 0.14 (Ns = 100) at 80° incidence is rejected with
     * p ≈ 1e-17, while 20 × 40 and finer accept it. Use the overload with more bins for sharper lobes.
     */
    public static ChiSquare.Result chiSquare(Bsdf bsdf, Vector3dc wo, int sampleCount, long seed) {
        return chiSquare(bsdf, wo, sampleCount, seed, COS_THETA_BINS, PHI_BINS);
    }

    public static ChiSquare.Result chiSquare(Bsdf bsdf, Vector3dc wo, int sampleCount, long seed, int cosThetaBins, int phiBins) {
        return chiSquare(bsdf, wo, sampleCount, seed, cosThetaBins, phiBins, ChiSquare.SIMPSON_INTERVALS);
    }

    /** As above with {@code intervals} Simpson intervals per cell and axis ({@link ChiSquare#test(ChiSquare.DirectionSampler, ChiSquare.DirectionPdf, int, long, int, int, int)}). */
    public static ChiSquare.Result chiSquare(Bsdf bsdf, Vector3dc wo, int sampleCount, long seed, int cosThetaBins, int phiBins,
                                             int intervals) {
        if (bsdf.isDelta()) {
            throw new IllegalArgumentException(bsdf + " has only delta lobes: there is no density to test, check its sample in closed form");
        }
        SplittableRandom lobe = new SplittableRandom(seed ^ 0x5DEECE66DL);
        BsdfSample s = new BsdfSample();
        ChiSquare.DirectionSampler sampler = (u1, u2, dest) -> {
            if (!bsdf.sample(wo, lobe.nextDouble(), u1, u2, s) || s.delta) {
                return false;
            }
            dest.set(s.wi);
            return true;
        };
        return ChiSquare.test(sampler, w -> bsdf.pdf(wo, w), sampleCount, seed, cosThetaBins, phiBins, intervals);
    }

    public static void assertSamplingMatchesPdf(Bsdf bsdf, Vector3dc wo, int sampleCount, long seed, double alpha) {
        try {
            chiSquare(bsdf, wo, sampleCount, seed).assertAccepted(alpha);
        } catch (AssertionError e) {
            throw new AssertionError(bsdf + ", wo = " + wo + ": " + e.getMessage(), e);
        }
    }

    /** ∫ pdf(wo, wi) dωi over the sphere: 1 for a BSDF that never absorbs and has no delta lobe. */
    public static double pdfIntegral(Bsdf bsdf, Vector3dc wo) {
        return ChiSquare.integrateOverSphere(w -> bsdf.pdf(wo, w));
    }

    // ---------------------------------------------------------------------------------------------
    // sample, eval and pdf agree

    /**
     * For {@code sampleCount} random (uc, u1, u2): a successful sample has a finite unit wi, a
     * finite pdf &gt; 0 and a finite weight ≥ 0; a non-delta one also has pdf = pdf(wo, wi) and
     * weight = eval(wo, wi)·|cosθi|/pdf.
     */
    public static void assertSampleConsistent(Bsdf bsdf, Vector3dc wo, int sampleCount, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        BsdfSample s = new BsdfSample();
        MutableRgb f = new MutableRgb();
        for (int i = 0; i < sampleCount; i++) {
            double uc = random.nextDouble(), u1 = random.nextDouble(), u2 = random.nextDouble();
            if (!bsdf.sample(wo, uc, u1, u2, s)) {
                continue;
            }
            Supplier<String> at = () -> String.format(Locale.ROOT, "%s, wo = %s, u = (%s, %s, %s): wi = %s, pdf = %s, weight = %s",
                    bsdf, wo, uc, u1, u2, s.wi, s.pdf, s.weight);
            check(s.wi.isFinite() && Math.abs(s.wi.length() - 1) < 1e-9, () -> "wi is not a unit vector: " + at.get());
            check(s.pdf > 0 && Double.isFinite(s.pdf), () -> "pdf of a successful sample must be finite and > 0: " + at.get());
            check(s.weight.isFinite() && s.weight.r >= 0 && s.weight.g >= 0 && s.weight.b >= 0,
                    () -> "weight must be finite and >= 0: " + at.get());
            if (s.delta) {
                continue;
            }
            double pdf = bsdf.pdf(wo, s.wi);
            check(close(pdf, s.pdf), () -> "pdf(wo, wi) = " + pdf + " differs from the sampled pdf: " + at.get());
            bsdf.eval(wo, s.wi, f);
            double c = Math.abs(s.wi.z) / s.pdf;
            check(close(f.r * c, s.weight.r) && close(f.g * c, s.weight.g) && close(f.b * c, s.weight.b),
                    () -> "weight differs from eval·|cosθi|/pdf = " + new MutableRgb(f.r * c, f.g * c, f.b * c) + ": " + at.get());
        }
    }

    /** For random wi over the whole sphere: eval(wo, wi) &gt; 0 implies pdf(wo, wi) &gt; 0. */
    public static void assertPdfCoversEval(Bsdf bsdf, Vector3dc wo, int directions, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        Vector3d wi = new Vector3d();
        MutableRgb f = new MutableRgb();
        for (int i = 0; i < directions; i++) {
            Warp.uniformSphere(random.nextDouble(), random.nextDouble(), wi);
            bsdf.eval(wo, wi, f);
            check(f.isFinite() && f.r >= 0 && f.g >= 0 && f.b >= 0,
                    () -> "eval must be finite and >= 0: " + bsdf + ", wo = " + wo + ", wi = " + wi + ": f = " + f);
            if (!f.isBlack()) {
                check(bsdf.pdf(wo, wi) > 0, () -> "pdf is 0 where f > 0, so sampling never finds light the BSDF scatters: "
                        + bsdf + ", wo = " + wo + ", wi = " + wi + ": f = " + f);
            }
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Reciprocity

    /**
     * f(wo, wi) = f(wi, wo) for {@code pairs} random pairs: both in the upper hemisphere, and for
     * BSDFs that are not two-sided also both in the lower one. Pairs on opposite sides
     * (transmission) are checked only for two-sided BSDFs, where f must be symmetric there too.
     */
    public static void assertReciprocal(Bsdf bsdf, int pairs, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        Vector3d wo = new Vector3d(), wi = new Vector3d();
        MutableRgb a = new MutableRgb(), b = new MutableRgb();
        int checked = 0;
        while (checked < pairs) {
            Warp.uniformSphere(random.nextDouble(), random.nextDouble(), wo);
            Warp.uniformSphere(random.nextDouble(), random.nextDouble(), wi);
            boolean sameSide = wo.z * wi.z > 0;
            if (bsdf.isTwoSided() ? (sameSide && wo.z < 0) : !sameSide) {
                continue;
            }
            bsdf.eval(wo, wi, a);
            bsdf.eval(wi, wo, b);
            check(close(a.r, b.r) && close(a.g, b.g) && close(a.b, b.b),
                    () -> "not reciprocal: f(wo, wi) = " + a + " but f(wi, wo) = " + b + ": " + bsdf + ", wo = " + wo + ", wi = " + wi);
            checked++;
        }
    }

    // ---------------------------------------------------------------------------------------------
    // Energy

    /** A per-channel Monte Carlo estimate with its standard error. */
    public record Estimate(double r, double g, double b, double errR, double errG, double errB) {
        public double max() {
            return Math.max(r, Math.max(g, b));
        }

        /** Whether every channel is within {@code z} standard errors (plus round-off) of the value. */
        public boolean isCloseTo(Rgb value, double z) {
            return Math.abs(r - value.r()) <= z * errR + 1e-12 && Math.abs(g - value.g()) <= z * errG + 1e-12
                    && Math.abs(b - value.b()) <= z * errB + 1e-12;
        }

        @Override
        public String toString() {
            return String.format(Locale.ROOT, "(%.5f ± %.1e, %.5f ± %.1e, %.5f ± %.1e)", r, errR, g, errG, b, errB);
        }
    }

    /** Running mean and variance of a per-channel estimator (Welford's algorithm: no cancellation). */
    private static final class Accumulator {
        private final double[] mean = new double[3], m2 = new double[3];
        private long n;

        void add(double r, double g, double b) {
            n++;
            double[] v = {r, g, b};
            for (int k = 0; k < 3; k++) {
                double delta = v[k] - mean[k];
                mean[k] += delta / n;
                m2[k] += delta * (v[k] - mean[k]);
            }
        }

        Estimate estimate() {
            double[] err = new double[3];
            for (int k = 0; k < 3; k++) {
                err[k] = n > 1 ? Math.sqrt(m2[k] / (n - 1) / n) : 0;
            }
            return new Estimate(mean[0], mean[1], mean[2], err[0], err[1], err[2]);
        }
    }

    /**
     * The directional albedo ∫ f(wo, wi)|cosθi| dωi estimated by the BSDF's own sampling: the mean
     * sample weight, absorbed samples counting 0. Includes delta lobes.
     */
    public static Estimate albedoBySampling(Bsdf bsdf, Vector3dc wo, int sampleCount, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        BsdfSample s = new BsdfSample();
        Accumulator acc = new Accumulator();
        for (int i = 0; i < sampleCount; i++) {
            if (bsdf.sample(wo, random.nextDouble(), random.nextDouble(), random.nextDouble(), s)) {
                acc.add(s.weight.r, s.weight.g, s.weight.b);
            } else {
                acc.add(0, 0, 0);
            }
        }
        return acc.estimate();
    }

    /**
     * The directional albedo of the non-delta lobes estimated independently of the BSDF's sampling:
     * uniform directions over the sphere, 4π·f(wo, wi)·|cosθi| per sample.
     */
    public static Estimate albedoByEval(Bsdf bsdf, Vector3dc wo, int sampleCount, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        Vector3d wi = new Vector3d();
        MutableRgb f = new MutableRgb();
        Accumulator acc = new Accumulator();
        for (int i = 0; i < sampleCount; i++) {
            Warp.uniformSphere(random.nextDouble(), random.nextDouble(), wi);
            bsdf.eval(wo, wi, f);
            double c = Math.abs(wi.z) / Warp.uniformSpherePdf();
            acc.add(f.r * c, f.g * c, f.b * c);
        }
        return acc.estimate();
    }

    /**
     * Energy conservation: for {@code directions} random wo (upper hemisphere, both for BSDFs that
     * are not two-sided; grazing and normal incidence included), the sampled albedo is at most 1 in
     * every channel, allowing {@value #Z} standard errors of Monte Carlo noise.
     */
    public static void assertEnergyAtMostOne(Bsdf bsdf, int directions, int samplesPerDirection, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        for (int i = 0; i < directions; i++) {
            Vector3d wo = i == 0 ? new Vector3d(0, 0, 1)
                    : i == 1 ? direction(89.9, 30)
                    : Warp.uniformHemisphere(random.nextDouble(), random.nextDouble(), new Vector3d());
            if (!bsdf.isTwoSided() && random.nextBoolean()) {
                wo.z = -wo.z;
            }
            Estimate e = albedoBySampling(bsdf, wo, samplesPerDirection, random.nextLong());
            check(e.r <= 1 + Z * e.errR + 1e-12 && e.g <= 1 + Z * e.errG + 1e-12 && e.b <= 1 + Z * e.errB + 1e-12,
                    () -> "reflects more than it receives, albedo " + e + ": " + bsdf + ", wo = " + wo);
        }
    }

    // ---------------------------------------------------------------------------------------------

    private static boolean close(double a, double b) {
        return Math.abs(a - b) <= REL * Math.max(Math.abs(a), Math.abs(b)) + 1e-300;
    }

    private static void check(boolean condition, Supplier<String> message) {
        if (!condition) {
            throw new AssertionError(message.get());
        }
    }
}
