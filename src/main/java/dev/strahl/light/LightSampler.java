package dev.strahl.light;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.image.Rgb;
import java.util.List;
import org.joml.Vector3dc;

/**
 * Picks points on the emissive primitives (area lights), punctual lights ({@link PunctualLight})
 * and directions towards the {@link Environment} for next-event estimation, seen from a shading
 * point.
 *
 * <p><b>Area lights or environment.</b> When a scene has both, each light sample is of the
 * environment with probability {@value #ENVIRONMENT_PROBABILITY} and of the other lights otherwise
 * (the number that chooses is reused, rescaled, for the choice among them); with one kind only,
 * that kind always. Not by power: the power of an infinitely distant light that reaches the scene
 * depends on the scene's size, and either kind can dominate what a given surface receives (a
 * lamp-lit room under a bright sky); an even split bounds either kind's pdf to half its own, so
 * neither is ever starved, and MIS with BSDF sampling covers the rest (pbrt-v4 weighs infinite
 * lights the same way in its BVH light sampler).
 *
 * <p><b>A constant environment</b> is sampled (uniformly over the sphere) only where nothing else
 * would find it: for estimators of light sampling alone ({@code withConstant}: Whitted, the photon
 * mapper's direct light). Where light sampling is combined with BSDF sampling by MIS, BSDF
 * sampling already follows f·cos, which is proportional to the whole integrand under a constant
 * radiance, so a uniform light sample could only add noise; there it has probability 0 and
 * {@link #environmentPdf} is 0 (pbrt-v4's "incomplete pdf" for {@code UniformInfiniteLight}). A
 * diffuse object under a constant sky thus stays exact with cosine sampling (the furnace test).
 *
 * <p><b>The other lights</b> are chosen by what they give the shading point: a {@link LightTree}
 * over the area and the point and spot lights, the directional lights by their share of the power
 * ({@link TreeSelection}). {@link #byPower()} is the same sampler choosing by power alone,
 * wherever the shading point is ({@link PowerSelection}): the teaching option, and what photon
 * emission uses ({@link #samplePoint}, {@link #selectPunctual}). Lights are one-sided: they emit
 * into the hemisphere of their geometric normal. Immutable and thread-safe.
 */
public final class LightSampler {
    /** The probability of sampling the environment when there are other lights too. */
    public static final double ENVIRONMENT_PROBABILITY = 0.5;

    private final Geometry geometry;
    private final Environment environment;
    private final double pEnvironment;   // probability of an environment sample under MIS: 0, 1/2 or 1
    private final double pArea;          // 1 - pEnvironment: the other lights'
    private final double pEnvironmentAlone;  // the same for light sampling alone, where a constant environment counts too
    private final double pAreaAlone;
    private final Emission[] emission;   // per material: the caller's table, not a copy
    private final PowerSelection power;
    private final TreeSelection tree;    // null: choose by power

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
        double[] materialWeight = new double[emission.length];
        for (int m = 0; m < emission.length; m++) {
            Rgb le = emission[m].mean();
            materialWeight[m] = (le.r() + le.g() + le.b()) / 3;
        }
        double radius = boundingRadius(geometry.bounds());
        PunctualLight[] punctual = punctualLights.toArray(new PunctualLight[0]);
        this.power = new PowerSelection(geometry, materialWeight, punctual, radius);
        this.tree = new TreeSelection(geometry, power.prims, power.weight, punctual, radius);
        boolean local = !power.isEmpty();
        this.pEnvironmentAlone = environment.isBlack() ? 0 : !local ? 1 : ENVIRONMENT_PROBABILITY;
        this.pAreaAlone = 1 - pEnvironmentAlone;
        this.pEnvironment = environment.isConstant() ? 0 : pEnvironmentAlone;
        this.pArea = 1 - pEnvironment;
    }

    private LightSampler(LightSampler s, TreeSelection tree) {
        this.geometry = s.geometry;
        this.environment = s.environment;
        this.emission = s.emission;
        this.power = s.power;
        this.tree = tree;
        this.pEnvironment = s.pEnvironment;
        this.pArea = s.pArea;
        this.pEnvironmentAlone = s.pEnvironmentAlone;
        this.pAreaAlone = s.pAreaAlone;
    }

    /**
     * This sampler choosing among the lights other than the environment by power alone, wherever
     * the shading point is: the teaching option {@code --light-selection power}, the choice before
     * the light tree. The environment's share and every table are shared.
     */
    public LightSampler byPower() {
        return tree == null ? this : new LightSampler(this, null);
    }

    /** Whether lights are chosen by the light tree (else by power). */
    public boolean usesTree() {
        return tree != null;
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
        return power.prims.length;
    }

    /** Whether there is nothing to sample: no area light, no punctual light and a black environment. */
    public boolean isEmpty() {
        return power.isEmpty() && pEnvironmentAlone == 0;
    }

    /** Number of punctual lights. */
    public int punctualCount() {
        return power.punctual.length;
    }

    /** Total power of the punctual lights (mean over channels, W); see {@link PunctualLight}. */
    public double punctualPower() {
        return power.punctualPower;
    }

    /**
     * Picks a punctual light in proportion to its power, for photon emission: returns its index
     * (for {@link #punctualProbability} and {@link #punctualLight}).
     */
    public int selectPunctual(double u) {
        return power.selectPunctual(u);
    }

    /** The probability with which {@link #selectPunctual} picks light i. */
    public double punctualProbability(int i) {
        return power.punctualProbability[i];
    }

    /** Punctual light i. */
    public PunctualLight punctualLight(int i) {
        return power.punctual[i];
    }

    /** Total emitted power over π: the sum of area × mean(Le) (the flux of a Lambertian emitter is π times this). */
    public double totalPower() {
        return power.totalPower;
    }

    /** The emission of a material, {@link Emission#BLACK} if it is not a light. */
    public Emission emission(int material) {
        return emission[material];
    }

    /** Nodes of the light tree (0 when lights are chosen by power or there is no local light). */
    public int treeNodeCount() {
        return tree == null ? 0 : tree.nodeCount();
    }

    /** Bytes of the light tree. */
    public long treeByteSize() {
        return tree == null ? 0 : tree.byteSize();
    }

    /**
     * Samples a direction towards a light from the shading point {@code ref} with normal {@code n}:
     * the environment with probability {@link #environmentProbability} (then {@code out.infinite}),
     * else a punctual light (then {@code out.delta}) or a point on an area light.
     * Returns false when nothing can be sampled or the chosen point faces away from ref.
     *
     * @param n            the shading normal at ref (either side), or null for a point that is not on a
     *                     surface; the light tree weighs lights by the cosine there
     * @param withConstant whether a constant environment is sampled too: true for light sampling
     *                     alone, false where BSDF samples are weighted against these by MIS
     * @param scratch      a per-thread surface record for the sampled point
     */
    public boolean sample(Vector3dc ref, Vector3dc n, double uLight, double u1, double u2, boolean withConstant, SurfacePoint scratch,
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
        if (power.isEmpty()) {
            return false;
        }
        if (pEnvironment > 0) {
            uLight = Math.min((uLight - pEnvironment) / pArea, Math.nextDown(1.0));
        }
        return tree == null ? power.sample(geometry, emission, ref, uLight, u1, u2, pArea, scratch, out)
                : tree.sample(geometry, emission, ref, n, uLight, u1, u2, pArea, scratch, out);
    }

    /**
     * Picks an emissive primitive in proportion to its power and a point on it uniformly by area,
     * without a reference point: the start of a light path (photon emission). Writes the point, its
     * geometric normal and material into {@code dest} and returns the point's density per unit
     * area, mean(Le) / {@link #totalPower()}; 0 if there is no light.
     */
    public double samplePoint(double uLight, double u1, double u2, SurfacePoint dest) {
        return power.samplePoint(geometry, uLight, u1, u2, dest);
    }

    /**
     * Solid-angle density with which {@link #sample} (under MIS) picks a point of the emissive
     * primitive {@code prim} seen from the shading point {@code ref} with normal {@code n} (those
     * that sampled) at distance {@code dist}, whose normal makes cosine {@code cosLight} with the
     * direction back to ref: what the MIS weight of a BSDF sample that hits it needs.
     */
    public double pdf(Vector3dc ref, Vector3dc n, int prim, double dist, double cosLight) {
        return tree == null ? power.pdf(geometry.material(prim), dist, cosLight, pArea) : tree.pdf(ref, n, prim, dist, cosLight, pArea);
    }

    /**
     * Solid-angle density with which {@link #sample} (under MIS, without {@code withConstant})
     * picks the environment in direction {@code d}: 0 for a constant environment.
     */
    public double environmentPdf(Vector3dc d) {
        return pEnvironment == 0 ? 0 : pEnvironment * environment.pdf(d);
    }

    /** The tree's choice, for the tests; null when choosing by power. */
    TreeSelection treeSelection() {
        return tree;
    }
}
