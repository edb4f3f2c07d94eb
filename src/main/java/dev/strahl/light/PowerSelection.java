package dev.strahl.light;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.SurfacePoint;
import java.util.Arrays;
import org.joml.Vector3dc;

/**
 * The choice of a light by its power alone, wherever the shading point is: what photon emission
 * uses, and the light sampler's teaching option ({@code --light-selection power}).
 *
 * <p><b>Area lights.</b> A primitive is chosen in proportion to its power, area × mean(Le), then
 * a point uniformly by area with {@link Geometry#samplePoint}; the density per unit area is thus
 * mean(Le) / total power for every emitter, a function of the material alone. A textured
 * emitter ({@link Emission}) is chosen by area × its mean over the texture, and its point
 * uniformly by area like any other: the sample carries Le at the point's (u, v), which is
 * unbiased whatever the texture; a point in the emitter's alpha cut-out carries Le = 0.
 *
 * <p><b>Punctual lights</b> share the samples with the area lights by power: a punctual light
 * with probability P_punctual / (P_punctual + P_area), P_area = π·Σ area·mean(Le) the flux of the
 * (Lambertian) area lights and P_punctual the sum of {@link PunctualLight}'s powers (a
 * directional light's over the scene's bounding sphere); among them again by power. The number
 * that chose the kind is rescaled to choose within it. Immutable.
 */
final class PowerSelection {
    final int[] prims;                    // emissive primitives, ascending
    final double[] weight;                // per emissive primitive: mean(Le), the weight per unit area
    private final double[] cdf;           // cumulative power, cdf[last] = 1
    final double totalPower;              // sum of area × mean(Le)
    private final double[] density;       // per material: mean(Le) / total power, the density per unit area
    final PunctualLight[] punctual;
    private final double[] punctualCdf;   // cumulative power of the punctual lights, last = 1
    final double[] punctualProbability;   // each punctual light's share of the punctual power
    final double punctualPower;           // their total power (W)
    private final double pPunctualShare;  // of the samples that are not the environment's, the punctual lights' share

    PowerSelection(Geometry geometry, double[] materialWeight, PunctualLight[] punctual, double sceneRadius) {
        int n = 0;
        int[] found = new int[16];
        double[] power = new double[16];
        double[] weights = new double[16];
        double total = 0;
        for (int prim = 0; prim < geometry.primitiveCount(); prim++) {
            double w = materialWeight[geometry.material(prim)];
            if (w > 0) {
                if (n == found.length) {
                    found = Arrays.copyOf(found, 2 * n);
                    power = Arrays.copyOf(power, 2 * n);
                    weights = Arrays.copyOf(weights, 2 * n);
                }
                found[n] = prim;
                weights[n] = w;
                total += w * geometry.area(prim);
                power[n++] = total;
            }
        }
        this.prims = Arrays.copyOf(found, n);
        this.weight = Arrays.copyOf(weights, n);
        this.cdf = Arrays.copyOf(power, n);
        for (int i = 0; i < n; i++) {
            cdf[i] /= total;
        }
        this.totalPower = total;
        this.density = new double[materialWeight.length];
        for (int m = 0; m < density.length; m++) {
            density[m] = total > 0 ? materialWeight[m] / total : 0;
        }
        this.punctual = punctual;
        this.punctualCdf = new double[punctual.length];
        this.punctualProbability = new double[punctual.length];
        this.punctualPower = cumulate(punctual, sceneRadius, punctualCdf, punctualProbability);
        this.pPunctualShare = punctual.length == 0 ? 0 : n == 0 ? 1 : punctualPower / (punctualPower + Math.PI * total);
    }

    /**
     * Fills the cumulative distribution and the probabilities of choosing among {@code lights} by
     * power (evenly if none has any); returns their total power.
     */
    static double cumulate(PunctualLight[] lights, double sceneRadius, double[] cdf, double[] probability) {
        double sum = 0;
        for (int i = 0; i < lights.length; i++) {
            probability[i] = lights[i].power(sceneRadius);
            sum += probability[i];
            cdf[i] = sum;
        }
        for (int i = 0; i < lights.length; i++) {
            cdf[i] = sum > 0 ? cdf[i] / sum : (i + 1.0) / lights.length;
            probability[i] = sum > 0 ? probability[i] / sum : 1.0 / lights.length;
        }
        return sum;
    }

    /** Index of the first entry whose cumulative probability exceeds u: a linear scan for a few, else bisection. */
    static int select(double[] cdf, double u) {
        int n = cdf.length;
        if (n <= 8) {
            int i = 0;
            while (i < n - 1 && !(cdf[i] > u)) {
                i++;
            }
            return i;
        }
        int i = Arrays.binarySearch(cdf, u);
        i = i >= 0 ? i + 1 : -i - 1;                 // first entry with cdf > u
        return Math.min(i, n - 1);
    }

    boolean isEmpty() {
        return prims.length == 0 && punctual.length == 0;
    }

    /**
     * Samples a punctual or area light with u, already rescaled to the non-environment part of the
     * samples, of probability {@code pLocal}; as {@link LightSampler#sample}.
     */
    boolean sample(Geometry geometry, Emission[] emission, Vector3dc ref, double u, double u1, double u2, double pLocal,
                   SurfacePoint scratch, LightSample out) {
        if (pPunctualShare > 0) {
            if (u < pPunctualShare) {
                int i = select(punctualCdf, Math.min(u / pPunctualShare, Math.nextDown(1.0)));
                out.pdf = pLocal * pPunctualShare * punctualProbability[i];
                return punctual[i].illuminate(ref, out) && out.pdf > 0;
            }
            u = Math.min((u - pPunctualShare) / (1 - pPunctualShare), Math.nextDown(1.0));
        }
        double cosLight = out.aimAtAreaLight(geometry, prims[select(cdf, u)], ref, u1, u2, scratch);
        if (cosLight <= 0) {
            return false;
        }
        int m = scratch.material;
        double dist = out.distance;
        out.pdf = pLocal * (1 - pPunctualShare) * density[m] * dist * dist / cosLight;
        emission[m].eval(scratch.uv, out.radiance);
        return out.pdf > 0 && Double.isFinite(out.pdf);
    }

    /** The density {@link #sample} gives a point of a light of this material; see {@link LightSampler#pdf}. */
    double pdf(int material, double dist, double cosLight, double pLocal) {
        if (cosLight <= 0 || totalPower <= 0) {
            return 0;
        }
        return pLocal * (1 - pPunctualShare) * density[material] * dist * dist / cosLight;
    }

    /** An emissive primitive chosen by power and a point on it uniformly by area; its density per unit area. */
    double samplePoint(Geometry geometry, double uLight, double u1, double u2, SurfacePoint dest) {
        if (prims.length == 0) {
            return 0;
        }
        int i = select(cdf, uLight);
        geometry.samplePoint(prims[i], u1, u2, dest);
        return weight[i] / totalPower;
    }

    int selectPunctual(double u) {
        return select(punctualCdf, u);
    }
}
