package dev.strahl.light;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.image.Rgb;
import java.util.Arrays;
import java.util.List;
import org.joml.Vector3dc;

/**
 * Picks points on the emissive primitives (area lights), punctual lights ({@link PunctualLight})
 * and directions towards the {@link Environment} for next-event estimation.
 *
 * <p><b>Area lights or environment.</b> When a scene has both, each light sample is of the
 * environment with probability {@value #ENVIRONMENT_PROBABILITY} and of the area lights otherwise
 * (the number that chooses is reused, rescaled, for the choice among area lights); with one kind
 * only, that kind always. Not by power: the power of an infinitely distant light that reaches the
 * scene depends on the scene's size, and either kind can dominate what a given surface receives
 * (a lamp-lit room under a bright sky); an even split bounds either kind's pdf to half its own, so
 * neither is ever starved, and MIS with BSDF sampling covers the rest (pbrt-v4 weighs infinite
 * lights the same way in its BVH light sampler). Scenes without an environment keep exactly the
 * numbers they had: the area lights are then chosen with the very same arithmetic.
 *
 * <p><b>A constant environment</b> is sampled (uniformly over the sphere) only where nothing else
 * would find it: for estimators of light sampling alone ({@code withConstant}: Whitted, the photon
 * mapper's direct light). Where light sampling is combined with BSDF sampling by MIS, BSDF
 * sampling already follows f·cos, which is proportional to the whole integrand under a constant
 * radiance, so a uniform light sample could only add noise; there it has probability 0 and
 * {@link #environmentPdf} is 0 (pbrt-v4's "incomplete pdf" for {@code UniformInfiniteLight}). A
 * diffuse object under a constant sky thus stays exact with cosine sampling (the furnace test).
 *
 * <p><b>Area lights.</b> A primitive is
 * chosen in proportion to its power, area × mean(Le), then a point uniformly by area with
 * {@link Geometry#samplePoint} (the one sampling of a primitive); the density per unit area is
 * thus mean(Le) / total power for every emitter, which lets {@link #pdf} work from the material
 * alone. Lights are one-sided: they emit into the hemisphere of their geometric normal.
 * A textured emitter ({@link Emission}) is chosen by area × its mean over the texture, and its
 * point uniformly by area like any other: the sample carries Le at the point's (u, v), which is
 * unbiased whatever the texture (it is not importance-sampled within the texture), and the
 * density stays a function of the material, as the MIS weights of hit emitters need; a point
 * in the emitter's alpha cut-out carries Le = 0.
 *
 * <p><b>Punctual lights</b> share the part of the light samples that is not the environment's
 * with the area lights, by power: a punctual light with probability P_punctual / (P_punctual +
 * P_area), P_area = π·Σ area·mean(Le) the flux of the (Lambertian) area lights and P_punctual the
 * sum of {@link PunctualLight}'s powers (a directional light's over the scene's bounding sphere,
 * {@link #boundingRadius}); among them again by power. The number that chose the kind is
 * rescaled to choose within it, as for the environment. Without punctual lights the area lights
 * get the very same numbers and densities as before they existed.
 * Immutable and thread-safe.
 */
public final class LightSampler {
    /** The probability of sampling the environment when there are area lights too. */
    public static final double ENVIRONMENT_PROBABILITY = 0.5;

    private final Geometry geometry;
    private final Environment environment;
    private final double pEnvironment;   // probability of an environment sample under MIS: 0, 1/2 or 1
    private final double pArea;          // 1 - pEnvironment
    private final double pEnvironmentAlone;  // the same for light sampling alone, where a constant environment counts too
    private final double pAreaAlone;
    private final Emission[] emission;   // per material: the caller's table, not a copy
    private final int[] prims;           // emissive primitives
    private final double[] cdf;          // cumulative power, cdf[last] = 1
    private final double totalPower;     // sum of area × mean(Le)
    private final double[] density;      // per material: mean(Le) / total power, the density per unit area
    private final PunctualLight[] punctual;
    private final double[] punctualCdf;  // cumulative power of the punctual lights, last = 1
    private final double[] punctualProbability;  // each punctual light's share of the punctual power
    private final double punctualPower;  // their total power (W)
    private final double pPunctualShare; // of the samples that are not the environment's, the punctual lights' share
    private final double pAreaLights;    // pArea · (1 − pPunctualShare): exactly pArea without punctual lights
    private final double pAreaLightsAlone;

    /**
     * @param emissionByMaterial emission of each material index (black = not a light), constant or
     *                           textured; kept, not copied (the world's one table), so it must not
     *                           change afterwards
     * @param environment        the light from where rays leave the scene (black: none)
     * @param punctualLights     point, spot and directional lights
     */
    public LightSampler(Geometry geometry, Emission[] emissionByMaterial, Environment environment, List<PunctualLight> punctualLights) {
        this.geometry = geometry;
        this.environment = environment;
        this.emission = emissionByMaterial;
        int n = 0;
        int[] found = new int[16];
        double[] power = new double[16];
        double total = 0;
        for (int prim = 0; prim < geometry.primitiveCount(); prim++) {
            double w = weight(geometry.material(prim));
            if (w > 0) {
                if (n == found.length) {
                    found = Arrays.copyOf(found, 2 * n);
                    power = Arrays.copyOf(power, 2 * n);
                }
                found[n] = prim;
                total += w * geometry.area(prim);
                power[n++] = total;
            }
        }
        this.prims = Arrays.copyOf(found, n);
        this.cdf = Arrays.copyOf(power, n);
        for (int i = 0; i < n; i++) {
            cdf[i] /= total;
        }
        this.totalPower = total;
        this.density = new double[emission.length];
        for (int m = 0; m < emission.length; m++) {
            density[m] = total > 0 ? weight(m) / total : 0;
        }
        this.punctual = punctualLights.toArray(new PunctualLight[0]);
        double radius = boundingRadius(geometry.bounds());
        this.punctualCdf = new double[punctual.length];
        this.punctualProbability = new double[punctual.length];
        double sum = 0;
        for (int i = 0; i < punctual.length; i++) {
            punctualProbability[i] = punctual[i].power(radius);
            sum += punctualProbability[i];
            punctualCdf[i] = sum;
        }
        for (int i = 0; i < punctual.length; i++) {
            punctualCdf[i] = sum > 0 ? punctualCdf[i] / sum : (i + 1.0) / punctual.length;
            punctualProbability[i] = sum > 0 ? punctualProbability[i] / sum : 1.0 / punctual.length;
        }
        this.punctualPower = sum;
        boolean local = n > 0 || punctual.length > 0;
        double areaFlux = Math.PI * total;
        this.pPunctualShare = punctual.length == 0 ? 0 : n == 0 ? 1 : sum / (sum + areaFlux);
        this.pEnvironmentAlone = environment.isBlack() ? 0 : !local ? 1 : ENVIRONMENT_PROBABILITY;
        this.pAreaAlone = 1 - pEnvironmentAlone;
        this.pEnvironment = environment.isConstant() ? 0 : pEnvironmentAlone;
        this.pArea = 1 - pEnvironment;
        this.pAreaLights = pArea * (1 - pPunctualShare);
        this.pAreaLightsAlone = pAreaAlone * (1 - pPunctualShare);
    }

    /**
     * The radius of the sphere around the centre of {@code box} that holds it: where a directional
     * light's and the environment's photons start (1 for empty bounds).
     */
    public static double boundingRadius(Aabb box) {
        return box.isEmpty() ? 1 : Math.max(1e-6, 0.5 * box.diagonal() * (1 + 1e-6));
    }

    /** The environment (black if the scene has none). */
    public Environment environment() {
        return environment;
    }

    /** The probability that a light sample is of the environment (under MIS; {@code withConstant}). */
    public double environmentProbability(boolean withConstant) {
        return withConstant ? pEnvironmentAlone : pEnvironment;
    }

    /** Number of emissive primitives (area lights). */
    public int lightCount() {
        return prims.length;
    }

    /** Whether there is nothing to sample: no area light, no punctual light and a black environment. */
    public boolean isEmpty() {
        return prims.length == 0 && punctual.length == 0 && pEnvironmentAlone == 0;
    }

    /** Number of punctual lights. */
    public int punctualCount() {
        return punctual.length;
    }

    /** Total power of the punctual lights (mean over channels, W); see {@link PunctualLight}. */
    public double punctualPower() {
        return punctualPower;
    }

    /**
     * Picks a punctual light in proportion to its power, for photon emission: returns its index
     * (for {@link #punctualProbability} and {@link #punctualLight}).
     */
    public int selectPunctual(double u) {
        return select(punctualCdf, u);
    }

    /** The probability with which {@link #selectPunctual} picks light i. */
    public double punctualProbability(int i) {
        return punctualProbability[i];
    }

    /** Punctual light i. */
    public PunctualLight punctualLight(int i) {
        return punctual[i];
    }

    /** Total emitted power over π: the sum of area × mean(Le) (the flux of a Lambertian emitter is π times this). */
    public double totalPower() {
        return totalPower;
    }

    /** The emission of a material, {@link Emission#BLACK} if it is not a light. */
    public Emission emission(int material) {
        return emission[material];
    }

    /** Selection weight per unit area: the mean radiance's channel mean (over the texture for a textured emitter). */
    private double weight(int material) {
        Rgb le = emission[material].mean();
        return (le.r() + le.g() + le.b()) / 3;
    }

    /**
     * Samples a direction towards a light from {@code ref}: the environment with probability
     * {@link #environmentProbability} (then {@code out.infinite}), else a punctual light (then
     * {@code out.delta}) or a point on an area light.
     * Returns false when nothing can be sampled or the chosen point faces away from ref.
     *
     * @param withConstant whether a constant environment is sampled too: true for light sampling
     *                     alone, false where BSDF samples are weighted against these by MIS
     * @param scratch      a per-thread surface record for the sampled point
     */
    public boolean sample(Vector3dc ref, double uLight, double u1, double u2, boolean withConstant, SurfacePoint scratch,
                          LightSample out) {
        double pEnvironment = withConstant ? pEnvironmentAlone : this.pEnvironment;
        double pArea = withConstant ? pAreaAlone : this.pArea;
        if (uLight < pEnvironment) {
            double pdf = environment.sample(u1, u2, out.uv, out.wi, out.radiance);
            out.infinite = true;
            out.delta = false;
            out.distance = Double.POSITIVE_INFINITY;
            out.pdf = pEnvironment * pdf;
            return pdf > 0 && Double.isFinite(out.pdf);
        }
        if (prims.length == 0 && punctual.length == 0) {
            return false;
        }
        if (pEnvironment > 0) {
            uLight = Math.min((uLight - pEnvironment) / pArea, Math.nextDown(1.0));
        }
        if (pPunctualShare > 0) {
            if (uLight < pPunctualShare) {
                int i = select(punctualCdf, Math.min(uLight / pPunctualShare, Math.nextDown(1.0)));
                out.pdf = pArea * pPunctualShare * punctualProbability[i];
                return punctual[i].illuminate(ref, out) && out.pdf > 0;
            }
            uLight = Math.min((uLight - pPunctualShare) / (1 - pPunctualShare), Math.nextDown(1.0));
        }
        out.infinite = false;
        out.delta = false;
        geometry.samplePoint(prims[select(cdf, uLight)], u1, u2, scratch);
        int m = scratch.material;
        out.p.set(scratch.p);
        out.ng.set(scratch.ng);
        if (out.aim(ref, out.p.x, out.p.y, out.p.z) == 0) {
            return false;
        }
        double cosLight = -out.ng.dot(out.wi);
        if (cosLight <= 0) {
            return false;
        }
        double dist = out.distance;
        out.pdf = (withConstant ? pAreaLightsAlone : pAreaLights) * density[m] * dist * dist / cosLight;
        emission[m].eval(scratch.uv, out.radiance);
        return out.pdf > 0 && Double.isFinite(out.pdf);
    }

    /** Index of the first emitter whose cumulative power exceeds u: a linear scan for a few lights, else bisection. */
    private static int select(double[] cdf, double u) {
        int n = cdf.length;
        if (n <= 8) {
            int i = 0;
            while (i < n - 1 && !(cdf[i] > u)) {
                i++;
            }
            return i;
        }
        int i = Arrays.binarySearch(cdf, u);
        i = i >= 0 ? i + 1 : -i - 1;                 // first entry with cdf > uLight
        return Math.min(i, n - 1);
    }

    /**
     * Picks an emissive primitive in proportion to its power and a point on it uniformly by area,
     * as {@link #sample} does but without a reference point: the start of a light path (photon
     * emission). Writes the point, its geometric normal and material into {@code dest} and returns
     * the point's density per unit area, mean(Le) / {@link #totalPower()}; 0 if there is no light.
     */
    public double samplePoint(double uLight, double u1, double u2, SurfacePoint dest) {
        if (prims.length == 0) {
            return 0;
        }
        geometry.samplePoint(prims[select(cdf, uLight)], u1, u2, dest);
        return weight(dest.material) / totalPower;
    }

    /**
     * Solid-angle density with which {@link #sample} picks a point of a light of the given
     * material at distance {@code dist} whose normal makes cosine {@code cosLight} with the
     * direction to the reference point.
     */
    public double pdf(int material, double dist, double cosLight) {
        if (cosLight <= 0 || totalPower <= 0) {
            return 0;
        }
        return pAreaLights * density[material] * dist * dist / cosLight;
    }

    /**
     * Solid-angle density with which {@link #sample} (under MIS, without {@code withConstant})
     * picks the environment in direction {@code d}: 0 for a constant environment.
     */
    public double environmentPdf(Vector3dc d) {
        return pEnvironment == 0 ? 0 : pEnvironment * environment.pdf(d);
    }
}
