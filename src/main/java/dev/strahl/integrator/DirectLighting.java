package dev.strahl.integrator;

import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Ray;
import dev.strahl.material.BsdfSample;
import dev.strahl.material.Bsdf;
import dev.strahl.math.MathUtil;
import dev.strahl.sampling.Sampler;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * Direct lighting: emission seen by the camera plus light that reaches the first surface straight
 * from an emitter, estimated with {@code lightSamples} light samples and one BSDF sample combined
 * by multiple importance sampling (power heuristic with sample counts). It computes the same
 * quantity as the path tracer at max depth 2; soft shadows sharpen with more light samples.
 * Random numbers: the light samples' (pair, then light choice, each), then the BSDF sample's (lobe,
 * then direction pair), at every first hit, as at the path tracer's first vertex.
 *
 * <p>Without {@code shadows} (a teaching option) the light samples are taken as visible, no shadow
 * ray is traced, and they are the whole estimate of the light from emitters (weight 1): the BSDF
 * sample, which would find a light only past any occluder, then adds only what a mirror or glass
 * shows (a delta sample). It still draws its numbers, so the layout of the dimensions stays.
 */
public final class DirectLighting implements Integrator {
    private final World world;
    private final Bsdf[] bsdfs;
    private final boolean cullBackFaces;
    private final int lightSamples;
    private final boolean shadows;

    public DirectLighting(World world, boolean uniformHemisphere, boolean cullBackFaces, int lightSamples, boolean shadows) {
        if (lightSamples < 1) {
            throw new IllegalArgumentException("light samples must be >= 1, got " + lightSamples);
        }
        this.world = world;
        this.bsdfs = Shading.bsdfs(world, uniformHemisphere);
        this.cullBackFaces = cullBackFaces;
        this.lightSamples = lightSamples;
        this.shadows = shadows;
    }

    @Override
    public Worker newWorker() {
        return new TracingWorker(world, bsdfs, cullBackFaces) {
            private final Shading s = new Shading();
            private final MutableRgb beta = new MutableRgb();
            private final Vector3d firstP = new Vector3d(), firstN = new Vector3d();   // the first hit, where the light samples were chosen

            @Override
            public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
                beta.set(1, 1, 1);
                if (tracer.trace(ray, s) < 0) {
                    out.setZero();
                    addEnvironment(ray, beta, 1, out);
                    return;
                }
                out.set(s.emitted);
                Bsdf bsdf = s.bsdf;
                beta.set(1, 1, 1);
                boolean lightSampling = !bsdf.isDelta() && !lights.isEmpty();
                tracer.direct.add(s, sampler, lightSamples, shadows ? DirectLight.Use.MIS : DirectLight.Use.UNOCCLUDED, beta, out);
                // One BSDF sample: the light it finds, weighted against the light samples.
                if (!s.sampleBsdf(sampler)) {
                    return;
                }
                BsdfSample bs = s.bs;
                if (!shadows && lightSampling && !bs.delta) {
                    return;                            // the unoccluded light samples stand alone
                }
                double bsdfPdf = bs.pdf;
                beta.set(bs.weight);
                firstP.set(s.sp.p);
                firstN.set(s.sp.n);
                s.spawn(ray, s.wi);
                double t = tracer.trace(ray, s);
                if (t < 0) {
                    double w = bs.delta || !lightSampling ? 1
                            : MathUtil.powerHeuristic(bsdfPdf, lightSamples * lights.environmentPdf(ray.d));
                    addEnvironment(ray, beta, w, out);
                    return;
                }
                if (!s.emitted.isBlack()) {
                    double w = bs.delta || !lightSampling ? 1
                            : MathUtil.powerHeuristic(bsdfPdf, lightSamples * lights.pdf(firstP, firstN, s.sp.prim, t, s.cosEmitter));
                    out.addProduct(beta, s.emitted, w);
                }
            }
        };
    }
}
