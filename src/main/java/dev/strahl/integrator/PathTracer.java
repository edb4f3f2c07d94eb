package dev.strahl.integrator;

import dev.strahl.math.MutableRgb;
import dev.strahl.geometry.Ray;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.material.BsdfSample;
import dev.strahl.math.MathUtil;
import dev.strahl.image.Rgb;
import dev.strahl.sampling.Rng;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * Unidirectional path tracing with next-event estimation and multiple importance sampling
 * (Veach 1997, ch. 9: power heuristic between light and BSDF sampling), and Russian roulette
 * from the {@value #RR_DEPTH}th interaction on with continuation probability
 * min(max channel of the throughput, 0.95). Unbiased: converges to the solution of the
 * rendering equation whatever the sampling choices.
 *
 * <p>{@code maxDepth} counts path segments including the camera segment: 1 shows only emitters
 * seen directly, 2 adds direct lighting, -1 is unbounded.
 */
public final class PathTracer implements Integrator {
    public static final int RR_DEPTH = 5;
    /** Random numbers one light sample takes (point on the light, then the light's choice). */
    private static final int LIGHT_DIMENSIONS = 3;

    /** How light reaching a surface directly from an emitter is estimated. */
    public enum Strategy {
        /** Light and BSDF sampling combined by the power heuristic: the default. */
        MIS,
        /** BSDF sampling only: emitters count only when a path hits them. */
        BSDF,
        /** Light sampling only: a path hitting an emitter counts only after a specular bounce. */
        LIGHT
    }

    private final World world;
    private final Bsdf[] bsdfs;
    private final int maxDepth;
    private final boolean cullBackFaces;
    private final Strategy strategy;

    public PathTracer(World world, int maxDepth, boolean uniformHemisphere, boolean cullBackFaces, Strategy strategy) {
        if (maxDepth == 0 || maxDepth < -1) {
            throw new IllegalArgumentException("maxDepth must be -1 (unbounded) or >= 1, got " + maxDepth);
        }
        this.world = world;
        this.maxDepth = maxDepth;
        this.cullBackFaces = cullBackFaces;
        this.strategy = strategy;
        this.bsdfs = Shading.bsdfs(world, uniformHemisphere);
    }

    @Override
    public Worker newWorker() {
        return new PathWorker();
    }

    private final class PathWorker implements Worker {
        private final Tracer tracer = new Tracer(world, bsdfs, cullBackFaces);
        private final LightSampler lights = world.lights();
        private final Rgb environment = world.environment();
        private final Shading s = new Shading();
        private final BsdfSample bs = new BsdfSample();
        private final Vector3d wiWorld = new Vector3d();
        private final MutableRgb beta = new MutableRgb();

        @Override
        public long rayCount() {
            return tracer.rayCount();
        }

        @Override
        public void radiance(Ray ray, Rng rng, MutableRgb out) {
            out.setZero();
            beta.set(1, 1, 1);
            double prevPdf = 0;
            boolean prevDelta = true;              // the camera ray: emission seen directly counts fully
            for (int depth = 1; ; depth++) {
                double t = tracer.trace(ray, s);
                if (t < 0) {
                    out.addProduct(beta, environment, 1);
                    return;
                }

                // Emission reached by the previous BSDF sample, weighted against light sampling.
                if (!s.emitted.isBlack()) {
                    double w = 1;
                    if (!prevDelta && strategy != Strategy.BSDF) {
                        w = strategy == Strategy.LIGHT ? 0
                                : MathUtil.powerHeuristic(prevPdf, lights.pdf(s.sp.material, t, s.cosEmitter));
                    }
                    out.addProduct(beta, s.emitted, w);
                }
                if (maxDepth > 0 && depth >= maxDepth) {
                    return;
                }
                Bsdf bsdf = s.bsdf;
                if (!bsdf.isDelta() && !lights.isEmpty() && strategy != Strategy.BSDF) {
                    tracer.direct.add(bsdf, s.sp, s.frame, s.woLocal, rng, 1, strategy == Strategy.MIS ? 1 : 0, beta, out);
                } else {
                    rng.skip(LIGHT_DIMENSIONS);        // keeps the BSDF sample on its pair of dimensions
                }

                // Continue the path by sampling the BSDF.
                if (!bsdf.sample(s.woLocal, rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), bs)) {
                    return;
                }
                s.frame.toWorld(bs.wi, wiWorld);
                if (wiWorld.dot(s.sp.ng) * bs.wi.z <= 0) {
                    return;                        // shading and geometric normal disagree: avoid light leaks
                }
                beta.mul(bs.weight);
                prevPdf = bs.pdf;
                prevDelta = bs.delta;
                s.sp.spawnOrigin(wiWorld, ray.o);
                ray.d.set(wiWorld);
                ray.tMax = Double.POSITIVE_INFINITY;

                if (depth >= RR_DEPTH) {
                    double q = Math.min(beta.max(), 0.95);
                    if (!(rng.nextDouble() < q)) {     // also ends a path whose throughput became NaN
                        return;
                    }
                    beta.mul(1 / q);
                }
            }
        }
    }
}
