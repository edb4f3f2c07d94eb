package dev.strahl.integrator;

import dev.strahl.accel.Bvh;
import dev.strahl.accel.TraversalStack;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.light.LightSample;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.material.BsdfSample;
import dev.strahl.math.Frame;
import dev.strahl.math.MathUtil;
import dev.strahl.math.Rgb;
import dev.strahl.sampling.HemisphereSampling;
import dev.strahl.sampling.Rng;
import dev.strahl.scene.Scene;
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
    static final int RR_DEPTH = 5;

    private final Scene scene;
    private final Bsdf[] bsdfs;
    private final Rgb[] emission;
    private final int maxDepth;
    private final boolean cullBackFaces;

    public PathTracer(Scene scene, int maxDepth, HemisphereSampling hemisphere, boolean cullBackFaces) {
        if (maxDepth == 0 || maxDepth < -1) {
            throw new IllegalArgumentException("maxDepth must be -1 (unbounded) or >= 1, got " + maxDepth);
        }
        this.scene = scene;
        this.maxDepth = maxDepth;
        this.cullBackFaces = cullBackFaces;
        int n = scene.materials().size();
        this.bsdfs = new Bsdf[n];
        this.emission = new Rgb[n];
        for (int i = 0; i < n; i++) {
            bsdfs[i] = scene.materials().get(i).bsdf().withHemisphereSampling(hemisphere);
            emission[i] = scene.materials().get(i).emission();
        }
    }

    @Override
    public Worker newWorker() {
        return new PathWorker();
    }

    private final class PathWorker implements Worker {
        private final Bvh bvh = scene.bvh();
        private final Geometry geometry = scene.geometry();
        private final LightSampler lights = scene.lights();
        private final Rgb environment = scene.environment();
        private final TraversalStack stack = Bvh.newStack();
        private final Hit hit = new Hit();
        private final SurfacePoint sp = new SurfacePoint();
        private final SurfacePoint lightPoint = new SurfacePoint();
        private final LightSample ls = new LightSample();
        private final Ray shadow = new Ray();
        private final Frame frame = new Frame();
        private final BsdfSample bs = new BsdfSample();
        private final Vector3d wo = new Vector3d();
        private final Vector3d woLocal = new Vector3d();
        private final Vector3d wiLocal = new Vector3d();
        private final Vector3d wiWorld = new Vector3d();
        private final Vector3d toSurface = new Vector3d();
        private final Vector3d target = new Vector3d();
        private final Rgb.Mutable beta = new Rgb.Mutable();
        private final Rgb.Mutable f = new Rgb.Mutable();
        private long rays;

        @Override
        public long rayCount() {
            return rays;
        }

        @Override
        public void radiance(Ray ray, Rng rng, Rgb.Mutable out) {
            out.setZero();
            beta.set(1, 1, 1);
            double prevPdf = 0;
            boolean prevDelta = true;              // the camera ray: emission seen directly counts fully
            for (int depth = 1; ; depth++) {
                rays++;
                hit.reset();
                if (!bvh.intersect(ray, hit, stack, cullBackFaces)) {
                    out.addProduct(beta, environment, 1);
                    return;
                }
                geometry.surface(ray, hit, sp);
                int material = sp.material;

                // Emission reached by the previous BSDF sample, weighted against light sampling.
                Rgb le = emission[material];
                double cosLight = -ray.d.dot(sp.ng);
                if (!le.isBlack() && cosLight > 0) {
                    double w = 1;
                    if (!prevDelta) {
                        double lightPdf = lights.pdf(material, hit.t, cosLight);
                        w = MathUtil.powerHeuristic(prevPdf, lightPdf);
                    }
                    out.addProduct(beta, le, w);
                }
                if (maxDepth > 0 && depth >= maxDepth) {
                    return;
                }

                // Local frame on the side of wo for two-sided BSDFs.
                Bsdf bsdf = bsdfs[material];
                wo.set(ray.d).negate();
                if (bsdf.isTwoSided() && wo.dot(sp.ng) < 0) {
                    sp.ng.negate();
                    sp.n.negate();
                }
                frame.set(sp.n);
                frame.toLocal(wo, woLocal);

                if (!bsdf.isDelta() && !lights.isEmpty()) {
                    sampleLight(bsdf, rng, out);
                }

                // Continue the path by sampling the BSDF.
                if (!bsdf.sample(woLocal, rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), bs)) {
                    return;
                }
                frame.toWorld(bs.wi, wiWorld);
                if (wiWorld.dot(sp.ng) * bs.wi.z <= 0) {
                    return;                        // shading and geometric normal disagree: avoid light leaks
                }
                beta.mul(bs.weight);
                prevPdf = bs.pdf;
                prevDelta = bs.delta;
                sp.spawnOrigin(wiWorld, ray.o);
                ray.d.set(wiWorld);
                ray.tMax = Double.POSITIVE_INFINITY;

                if (depth >= RR_DEPTH) {
                    double q = Math.min(beta.max(), 0.95);
                    if (!(rng.nextDouble() < q)) {
                        return;
                    }
                    beta.mul(1 / q);
                }
            }
        }

        /** Next-event estimation: one light sample, MIS-weighted against BSDF sampling. */
        private void sampleLight(Bsdf bsdf, Rng rng, Rgb.Mutable out) {
            double uLight = rng.nextDouble(), u1 = rng.nextDouble(), u2 = rng.nextDouble();
            if (!lights.sample(sp.p, uLight, u1, u2, lightPoint, ls)) {
                return;
            }
            frame.toLocal(ls.wi, wiLocal);
            if (ls.wi.dot(sp.ng) * wiLocal.z <= 0) {
                return;
            }
            bsdf.eval(woLocal, wiLocal, f);
            if (f.isBlack()) {
                return;
            }
            // Shadow ray between the two surfaces, each end moved off its surface.
            sp.spawnOrigin(ls.wi, shadow.o);
            toSurface.set(ls.wi).negate();
            SurfacePoint.offset(ls.p, ls.ng, toSurface, target);
            shadow.d.set(target).sub(shadow.o);
            double dist = shadow.d.length();
            if (!(dist > 0)) {
                return;
            }
            shadow.d.div(dist);
            shadow.tMax = dist;
            rays++;
            if (bvh.occluded(shadow, stack)) {
                return;
            }
            double w = MathUtil.powerHeuristic(ls.pdf, bsdf.pdf(woLocal, wiLocal));
            f.mul(ls.radiance);
            out.addProduct(beta, f, Math.abs(wiLocal.z) * w / ls.pdf);
        }
    }
}
