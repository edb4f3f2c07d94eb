package dev.strahl.integrator;

import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Ray;
import dev.strahl.material.Bsdf;
import dev.strahl.material.BsdfSample;
import dev.strahl.math.MathUtil;
import dev.strahl.sampling.Sampler;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * Unidirectional path tracing with next-event estimation and multiple importance sampling
 * (Veach 1997, ch. 9: power heuristic between light and BSDF sampling), and Russian roulette
 * from the {@value #RR_DEPTH}th interaction on with continuation probability
 * min(max channel of the throughput · Π η'², 0.95), the product over the path's refractions
 * undoing their radiance scaling 1/η'² ({@link dev.strahl.material.BsdfSample#eta}). Unbiased: converges to the solution of the
 * rendering equation whatever the sampling choices.
 *
 * <p>{@code maxDepth} counts path segments including the camera segment: 1 shows only emitters
 * seen directly, 2 adds direct lighting, -1 is unbounded.
 *
 * <p><b>Random numbers.</b> Every vertex that scatters draws the same calls in the same order,
 * whatever its surface: the light sample (a pair for the point on the light, one number for the
 * choice of light, drawn by {@link DirectLight#add} even where no light sample is taken), the BSDF
 * sample (one number for the lobe, a pair for the direction) and, from depth {@value #RR_DEPTH}
 * on, one number for Russian roulette. With the stratified sampler the first vertex's numbers are
 * its dimensions 2–7: the pairs (light point), (light choice, lobe choice), (BSDF direction).
 */
public final class PathTracer implements Integrator {
    public static final int RR_DEPTH = 5;

    /** How light reaching a surface directly from an emitter is estimated. */
    public enum Strategy {
        /** Light and BSDF sampling combined by the power heuristic: the default. */
        MIS,
        /** BSDF sampling only: emitters count only when a path hits them. */
        BSDF,
        /** Light sampling only: a path hitting an emitter counts only after a specular bounce. */
        LIGHT,
        /**
         * Light sampling only, as {@link #LIGHT}, with every shadow ray taken as unblocked: the
         * teaching option without shadows. Only the last segment of each path, the one to the
         * light, ignores what stands in its way; the bounces before it are traced as always, so
         * indirect light keeps its occlusion. (With MIS a BSDF sample that hits a light would
         * count too, and it would have crossed any occluder: so light sampling alone.)
         */
        UNOCCLUDED
    }

    private final World world;
    private final Bsdf[] bsdfs;
    private final int maxDepth;
    private final boolean cullBackFaces;
    private final Strategy strategy;
    private final DirectLight.Use lightUse;

    public PathTracer(World world, int maxDepth, boolean uniformHemisphere, boolean cullBackFaces, Strategy strategy) {
        this.world = world;
        this.maxDepth = Integrator.checkMaxDepth(maxDepth);
        this.cullBackFaces = cullBackFaces;
        this.strategy = strategy;
        this.lightUse = switch (strategy) {
            case MIS -> DirectLight.Use.MIS;
            case BSDF -> DirectLight.Use.DRAW_ONLY;
            case LIGHT -> DirectLight.Use.LIGHT_ONLY;
            case UNOCCLUDED -> DirectLight.Use.UNOCCLUDED;
        };
        this.bsdfs = Shading.bsdfs(world, uniformHemisphere);
    }

    @Override
    public Worker newWorker() {
        return new PathWorker();
    }

    private final class PathWorker extends TracingWorker {
        private final Shading s = new Shading();
        private final MutableRgb beta = new MutableRgb();
        private final Vector3d prevP = new Vector3d(), prevN = new Vector3d();   // where the BSDF sample left from: the light tree's choice there

        PathWorker() {
            super(world, bsdfs, cullBackFaces);
        }

        @Override
        public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
            out.setZero();
            beta.set(1, 1, 1);
            double prevPdf = 0;
            boolean prevDelta = true;              // the camera ray: emission seen directly counts fully
            double etaScale = 1;                   // product of η'² over the refractions so far (for the roulette)
            for (int depth = 1; ; depth++) {
                double t = tracer.trace(ray, s);
                if (t < 0) {
                    // The environment reached by the previous BSDF sample, weighted against light sampling.
                    double w = 1;
                    if (!prevDelta && strategy != Strategy.BSDF) {
                        w = strategy != Strategy.MIS ? 0 : MathUtil.powerHeuristic(prevPdf, lights.environmentPdf(ray.d));
                    }
                    addEnvironment(ray, beta, w, out);
                    return;
                }

                // Emission reached by the previous BSDF sample, weighted against light sampling.
                if (!s.emitted.isBlack()) {
                    double w = 1;
                    if (!prevDelta && strategy != Strategy.BSDF) {
                        w = strategy != Strategy.MIS ? 0
                                : MathUtil.powerHeuristic(prevPdf, lights.pdf(prevP, prevN, s.sp.prim, t, s.cosEmitter));
                    }
                    out.addProduct(beta, s.emitted, w);
                }
                if (maxDepth > 0 && depth >= maxDepth) {
                    return;
                }
                tracer.direct.add(s, sampler, 1, lightUse, beta, out);

                // Continue the path by sampling the BSDF.
                if (!s.sampleBsdf(sampler)) {
                    return;
                }
                BsdfSample bs = s.bs;
                beta.mul(bs.weight);
                etaScale *= bs.eta * bs.eta;
                prevPdf = bs.pdf;
                prevDelta = bs.delta;
                prevP.set(s.sp.p);
                prevN.set(s.sp.n);
                s.spawn(ray, s.wi);

                if (depth >= RR_DEPTH) {
                    // The roulette sees the throughput without the 1/η'² radiance scaling of the
                    // refractions (Mitsuba 3's path.cpp, pbrt-v4's etaScale): inside glass of η 2.5
                    // the weight is 1/6.25 of what leaving the glass restores, and deciding from it
                    // killed those paths 6× too often and gave the survivors 6× the weight.
                    double q = Math.min(beta.max() * etaScale, 0.95);
                    if (!(sampler.get1D() < q)) {      // also ends a path whose throughput became NaN
                        return;
                    }
                    beta.mul(1 / q);
                }
            }
        }
    }
}
