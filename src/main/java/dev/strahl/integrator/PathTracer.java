package dev.strahl.integrator;

import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Ray;
import dev.strahl.material.Bsdf;
import dev.strahl.material.BsdfSample;
import dev.strahl.math.MathUtil;
import dev.strahl.sampling.Sampler;
import dev.strahl.world.World;
import org.joml.Vector3dc;

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
 * whatever its surface: {@link VertexSamples}, drawn at once by the vertex kernel {@link #scatter}
 * (the light sample's numbers are drawn even where no light sample is taken).
 *
 * <p>The vertex logic is kernels over explicit numbers — {@link #scatter}, the MIS weights of
 * emission and environment, {@link #survival} — shared by the scalar worker, which traces one
 * path at a time, and {@link PathWavefront}, which runs a batch of paths stage by stage: the same
 * operations on each path in the same order, so both give the same bits.
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

    /** The longest a path may be: {@code maxDepth} segments, -1 for unbounded. */
    int maxDepth() {
        return maxDepth;
    }

    /** Each material's BSDF as this integrator samples it. */
    Bsdf[] bsdfs() {
        return bsdfs;
    }

    World world() {
        return world;
    }

    boolean cullBackFaces() {
        return cullBackFaces;
    }

    /** The MIS weight of the environment reached along {@code d} by the path's last BSDF sample, against light sampling. */
    double environmentWeight(PathState p, Vector3dc d) {
        if (p.prevDelta || strategy == Strategy.BSDF) {
            return 1;                              // the camera ray, a specular bounce, or no light sampling to share with
        }
        return strategy != Strategy.MIS ? 0 : MathUtil.powerHeuristic(p.prevPdf, world.lights().environmentPdf(d));
    }

    /** The MIS weight of the emission at {@code s}, {@code t} from the last vertex and reached by its BSDF sample, against light sampling. */
    double emissionWeight(PathState p, Shading s, double t) {
        if (p.prevDelta || strategy == Strategy.BSDF) {
            return 1;
        }
        return strategy != Strategy.MIS ? 0 : MathUtil.powerHeuristic(p.prevPdf, world.lights().pdf(p.prevP, p.prevN, s.sp.prim, t, s.cosEmitter));
    }

    /**
     * Russian roulette's continuation probability min(max channel of beta · etaScale, 0.95): the
     * throughput without the 1/η'² radiance scaling of the refractions so far (Mitsuba 3's path.cpp,
     * pbrt-v4's etaScale). Inside glass of η 2.5 the weight is 1/6.25 of what leaving the glass
     * restores, and deciding from it killed those paths 6× too often and gave the survivors 6× the
     * weight. A path survives where its roulette number is below it (never with a NaN throughput).
     */
    public static double survival(MutableRgb beta, double etaScale) {
        return Math.min(beta.max() * etaScale, 0.95);
    }

    /**
     * The vertex kernel: what a path does at the surface {@code s} it reached {@code t} along
     * {@code ray}, shared by the scalar worker and the wavefront. Adds the emission seen there
     * (MIS-weighted) to {@code out}; unless the path has its full length, draws the vertex's
     * numbers from {@code sampler} (all of them, in the one layout: {@link VertexSamples}),
     * prepares the light sample's shadow query into {@code q} ({@code q.pending}: the caller
     * resolves it with {@link DirectLight#resolve} before the next vertex adds anything), samples
     * the BSDF into the path's throughput and {@code ray}, and plays Russian roulette. Returns
     * whether the path goes on along {@code ray}.
     */
    boolean scatter(Tracer tracer, Shading s, double t, PathState p, VertexSamples u, Sampler sampler, ShadowQuery q, Ray ray,
                    MutableRgb out) {
        q.pending = false;
        MutableRgb beta = p.beta;
        if (!s.emitted.isBlack()) {
            out.addProduct(beta, s.emitted, emissionWeight(p, s, t));
        }
        int depth = p.depth;
        if (maxDepth > 0 && depth >= maxDepth) {
            return false;
        }
        u.draw(sampler, depth >= RR_DEPTH);
        DirectLight direct = tracer.direct;
        q.pending = direct.estimates(s, lightUse) && direct.prepare(s, u.lightU1, u.lightU2, u.lightChoice, lightUse, 1, 1.0, beta, q);
        if (!s.sampleBsdf(u.lobe, u.directionU1, u.directionU2)) {
            return false;
        }
        BsdfSample bs = s.bs;
        beta.mul(bs.weight);
        p.etaScale *= bs.eta * bs.eta;
        p.prevPdf = bs.pdf;
        p.prevDelta = bs.delta;
        p.prevP.set(s.sp.p);                       // where the BSDF sample leaves from: the light tree's choice there
        p.prevN.set(s.sp.n);
        s.spawn(ray, s.wi);
        if (depth >= RR_DEPTH) {
            double survive = survival(beta, p.etaScale);
            if (!(u.roulette < survive)) {         // also ends a path whose throughput became NaN
                return false;
            }
            beta.mul(1 / survive);
        }
        p.depth = depth + 1;
        return true;
    }

    /**
     * A wavefront of {@code samplers.length} paths for one thread (each path draws from its own
     * sampler): the same radiance as {@link #newWorker()}'s, bit for bit, a batch at a time.
     */
    public PathWavefront newWavefront(Sampler[] samplers) {
        return new PathWavefront(this, samplers);
    }

    /** The scalar worker, one path at a time; its scratch objects also serve a {@link PathWavefront}. */
    final class PathWorker extends TracingWorker {
        final Shading s = new Shading();
        final PathState path = new PathState();
        final VertexSamples u = new VertexSamples();
        final ShadowQuery q = new ShadowQuery();

        PathWorker() {
            super(world, bsdfs, cullBackFaces);
        }

        @Override
        public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
            out.setZero();
            path.start();
            while (true) {
                double t = tracer.trace(ray, s);
                if (t < 0) {
                    addEnvironment(ray, path.beta, environmentWeight(path, ray.d), out);
                    return;
                }
                boolean goesOn = scatter(tracer, s, t, path, u, sampler, q, ray, out);
                if (q.pending) {
                    tracer.direct.resolve(q, out);
                }
                if (!goesOn) {
                    return;
                }
            }
        }
    }
}
