package dev.strahl.integrator;

import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Ray;
import dev.strahl.material.Bsdf;
import dev.strahl.material.BsdfSample;
import dev.strahl.sampling.Sampler;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * Recursive ray tracing after Whitted (1980), with area lights. Mirrors and glass spawn their
 * reflected and refracted rays (both, weighted by Fresnel); diffuse and glossy surfaces take the
 * light arriving directly from the area lights, estimated with {@code lightSamples} shadow rays
 * (soft shadows whose noise falls as the count grows). Light that reaches a diffuse surface via
 * another diffuse surface is never followed, so this is not a converged global-illumination
 * image: corners and shadows are darker than the path tracer's, and there is no colour bleeding.
 * Only the light samples draw random numbers (their pair, then the light choice, each); delta
 * surfaces follow all their lobes and draw none.
 *
 * <p>{@code maxDepth} limits the recursion in path segments as for the path tracer; -1 means
 * {@value #UNBOUNDED_DEPTH} segments.
 *
 * <p>Without {@code shadows} (a teaching option) the shadow rays are not traced and every light
 * sample counts as visible: a diffuse surface shows Lambert × light from every light in front of
 * it, the first picture of a ray tracer before it learns shadows. Mirrors and glass still reflect
 * and refract as always.
 */
public final class Whitted implements Integrator {
    /** The recursion limit used for max depth -1: deep enough for glass, bounded for mirror pairs. */
    static final int UNBOUNDED_DEPTH = 16;

    private final World world;
    private final Bsdf[] bsdfs;
    private final int maxDepth;
    private final boolean cullBackFaces;
    private final int lightSamples;
    private final DirectLight.Use lightUse;

    public Whitted(World world, int maxDepth, boolean cullBackFaces, int lightSamples, boolean shadows) {
        Integrator.checkMaxDepth(maxDepth);
        if (lightSamples < 1) {
            throw new IllegalArgumentException("light samples must be >= 1, got " + lightSamples);
        }
        this.world = world;
        this.bsdfs = Shading.bsdfs(world, false);
        this.maxDepth = maxDepth > 0 ? maxDepth : UNBOUNDED_DEPTH;
        this.cullBackFaces = cullBackFaces;
        this.lightSamples = lightSamples;
        this.lightUse = shadows ? DirectLight.Use.LIGHT_ONLY : DirectLight.Use.UNOCCLUDED;
    }

    @Override
    public Worker newWorker() {
        return new WhittedWorker();
    }

    private final class WhittedWorker extends TracingWorker {
        // Scratch per recursion level, so that a level's state survives its children.
        private final Shading[] shading = new Shading[maxDepth + 1];
        private final BsdfSample[][] lobes = new BsdfSample[maxDepth + 1][2];
        private final MutableRgb[] beta = new MutableRgb[maxDepth + 1];
        private final Vector3d wi = new Vector3d();

        WhittedWorker() {
            super(world, bsdfs, cullBackFaces);
            for (int i = 0; i <= maxDepth; i++) {
                shading[i] = new Shading();
                lobes[i][0] = new BsdfSample();
                lobes[i][1] = new BsdfSample();
                beta[i] = new MutableRgb();
            }
        }

        @Override
        public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
            out.setZero();
            beta[0].set(1, 1, 1);
            trace(ray, 1, sampler, out);
        }

        /** Adds beta[depth-1]·L(ray) to out, where the ray is the depth-th segment of the path. */
        private void trace(Ray ray, int depth, Sampler sampler, MutableRgb out) {
            MutableRgb weight = beta[depth - 1];
            Shading s = shading[depth];
            if (tracer.trace(ray, s) < 0) {
                addEnvironment(ray, weight, 1, out);
                return;
            }
            out.addProduct(weight, s.emitted, 1);
            if (depth >= maxDepth) {
                return;
            }
            Bsdf bsdf = s.bsdf;
            if (!bsdf.isDelta()) {
                tracer.direct.add(s, sampler, lightSamples, lightUse, weight, out);
                return;
            }
            int count = deltaLobes(bsdf, s, lobes[depth]);
            for (int i = 0; i < count; i++) {
                BsdfSample lobe = lobes[depth][i];
                s.frame.toWorld(lobe.wi, wi);
                if (wi.dot(s.sp.ng) * lobe.wi.z <= 0) {
                    continue;
                }
                beta[depth].set(weight).mul(lobe.weight);
                s.spawn(ray, wi);
                trace(ray, depth + 1, sampler, out);
            }
        }
    }

    /**
     * The lobes of a delta BSDF with their Fresnel weights (f·|cos|, not divided by a choice
     * probability), found by sampling with the lobe-choice number at both ends of [0, 1): a delta
     * BSDF picks its first lobe for uc below that lobe's probability. Returns the lobe count.
     */
    static int deltaLobes(Bsdf bsdf, Shading s, BsdfSample[] out) {
        if (!bsdf.sample(s.sp.uv, s.woLocal, 0, 0.5, 0.5, out[0])) {
            return 0;
        }
        out[0].weight.mul(out[0].pdf);
        if (out[0].pdf >= 1 || !bsdf.sample(s.sp.uv, s.woLocal, Math.nextDown(1.0), 0.5, 0.5, out[1])) {
            return 1;
        }
        out[1].weight.mul(out[1].pdf);
        return 2;
    }
}
