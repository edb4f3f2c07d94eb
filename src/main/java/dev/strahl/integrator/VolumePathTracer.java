package dev.strahl.integrator;

import dev.strahl.geometry.Ray;
import dev.strahl.light.Environment;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.material.BsdfSample;
import dev.strahl.math.Frame;
import dev.strahl.math.MathUtil;
import dev.strahl.color.MutableRgb;
import dev.strahl.medium.HenyeyGreenstein;
import dev.strahl.medium.Medium;
import dev.strahl.medium.TrackingRandom;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.Sampler;
import dev.strahl.world.Media;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * Unbiased volumetric path tracing (the radiative transfer equation; pbrt-v4 ch. 14, Mitsuba 3's
 * {@code volpath}): the path tracer of {@link PathTracer} with participating media between the
 * surfaces. The integrator of every world with media or invisible surfaces ({@link World#media()}).
 *
 * <p>Each segment of a path travels in one medium (or vacuum), known from where the path came:
 * the camera's medium first, then the side of each medium boundary it leaves towards
 * ({@link Media#after}). Per segment and vertex, in explicit steps:
 * <ol>
 *   <li><b>Distance sampling</b> ({@link Medium#sampleScattering}): where, before the next surface,
 *       the light last scattered in the medium — free-flight sampling with MIS over the channels in
 *       a homogeneous medium, delta tracking in a grid — and the weight that keeps it unbiased.</li>
 *   <li>A scattering point in the medium is a vertex: <b>next-event estimation</b>
 *       ({@link VolumeLight}: a light sample, the phase function, ratio-tracking transmittance
 *       through media and invisible surfaces), then <b>phase-function sampling</b> of the next
 *       direction (Henyey–Greenstein, weight 1).</li>
 *   <li>A surface: an invisible one ({@code null}) is crossed without counting as a bounce (the
 *       ray's medium changes if it is a boundary); at any other, emission, next-event estimation and
 *       BSDF sampling as in {@link PathTracer}, and the medium follows the sampled direction.</li>
 *   <li><b>MIS</b>: light samples and the scattering strategy (phase function or BSDF) are combined
 *       by the power heuristic; an emitter or the environment reached by a phase or BSDF sample is
 *       weighted with the light sampler's density at the last real scattering point (through any
 *       invisible surfaces between).</li>
 * </ol>
 * Russian roulette as in {@link PathTracer}, from the {@value PathTracer#RR_DEPTH}th real
 * scattering event. {@code maxDepth} counts segments between real scattering events (surfaces
 * and medium), as Mitsuba's {@code max_depth}; invisible surfaces do not count. Back faces are
 * never culled here (a ray leaving a medium must meet the boundary's inside).
 *
 * <p><b>Random numbers.</b> The path's first number chooses its hero channel (whose extinction
 * samples the distances of chromatic media; MIS over the channels keeps the others' colour noise
 * bounded, see {@link dev.strahl.medium.HomogeneousMedium}); per segment in a medium, a pair for distance sampling (a grid's delta
 * tracking continues from a {@link TrackingRandom} seeded with it); per real scattering vertex, the
 * light sample's four numbers ({@link VolumeLight}), one for the lobe (unused in a medium) and a
 * pair for the direction, and from depth {@value PathTracer#RR_DEPTH} on one for the roulette.
 */
public final class VolumePathTracer implements Integrator {
    private final World world;
    private final Bsdf[] bsdfs;
    private final int maxDepth;
    private final int lightSamples;
    private final boolean shadows;

    /**
     * @param maxDepth          segments between real scattering events, −1 unbounded
     * @param uniformHemisphere sample diffuse lobes uniformly instead of by the cosine
     * @param lightSamples      light samples per vertex (the {@code direct} integrator's option), ≥ 1
     * @param shadows           false: the teaching option without shadows (light samples unblocked and
     *                          unattenuated, the only estimate of light from emitters)
     */
    public VolumePathTracer(World world, int maxDepth, boolean uniformHemisphere, int lightSamples, boolean shadows) {
        if (lightSamples < 1) {
            throw new IllegalArgumentException("need at least one light sample, got " + lightSamples);
        }
        this.world = world;
        this.maxDepth = Integrator.checkMaxDepth(maxDepth);
        this.lightSamples = lightSamples;
        this.shadows = shadows;
        this.bsdfs = Shading.bsdfs(world, uniformHemisphere);
    }

    @Override
    public Worker newWorker() {
        return new VolumeWorker();
    }

    private final class VolumeWorker implements Worker {
        private final Tracer tracer = new Tracer(world, bsdfs, false);
        private final Transmittance transmittance = new Transmittance(world);
        private final VolumeLight light = new VolumeLight(world, transmittance);
        private final LightSampler lights = world.lights();
        private final Environment environment = world.environment();
        private final Media media = world.media();
        private final Shading s = new Shading();
        private final MutableRgb beta = new MutableRgb();
        private final MutableRgb weight = new MutableRgb();
        private final MutableRgb ratio = new MutableRgb();
        /** Per channel, the density of the path's distances under that channel over the hero's, normalised to mean 1. */
        private final MutableRgb channelRatio = new MutableRgb();
        private final MutableRgb environmentRadiance = new MutableRgb();
        private final Sample2D u = new Sample2D();
        private final TrackingRandom tracking = new TrackingRandom();
        private final Frame frame = new Frame();
        private final Vector3d p = new Vector3d();
        private final Vector3d wo = new Vector3d();
        private final Vector3d wi = new Vector3d();
        // the path's state
        private int medium;
        private int hero;                     // the channel whose extinction samples the path's distances
        private double prevPdf;               // density of the last scattering strategy's direction
        private boolean prevDelta;            // whether that direction came from a delta lobe (or the camera)
        private double etaScale;              // product of η'² over the refractions (for the roulette)
        private double sinceScatter;          // distance from the last real scattering point, along the ray
        private final Vector3d prevP = new Vector3d(), prevN = new Vector3d();   // that point and its normal: the light tree's choice there
        private boolean prevAtSurface;        // whether it was on a surface (else in a medium: no normal)

        @Override
        public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
            out.setZero();
            beta.set(1, 1, 1);
            channelRatio.set(1, 1, 1);
            hero = Math.min((int) (3 * sampler.get1D()), 2);
            medium = media.camera();
            prevPdf = 0;
            prevDelta = true;                 // the camera ray: emission seen directly counts fully
            etaScale = 1;
            sinceScatter = 0;
            int crossings = 0;
            for (int depth = 1; ; ) {
                double t = tracer.trace(ray, s);
                double tScatter = medium >= 0 ? sampleDistance(ray, t < 0 ? Double.POSITIVE_INFINITY : t, sampler) : Double.POSITIVE_INFINITY;
                if (beta.isBlack()) {
                    return;
                }
                if (tScatter < Double.POSITIVE_INFINITY) {
                    if (maxDepth > 0 && depth >= maxDepth) {
                        return;
                    }
                    scatterInMedium(ray, tScatter, sampler, out);
                } else if (t < 0) {
                    addEnvironment(ray, out);
                    return;
                } else {
                    sinceScatter += t;
                    if (media.isInvisible(s.sp.material)) {
                        if (++crossings > Tracer.MAX_PASSES) {
                            return;                   // a bound no real scene reaches (coincident invisible surfaces)
                        }
                        crossInvisible(ray);
                        continue;
                    }
                    addEmission(out);
                    if (maxDepth > 0 && depth >= maxDepth) {
                        return;
                    }
                    if (!scatterAtSurface(ray, sampler, out)) {
                        return;
                    }
                }
                crossings = 0;
                if (depth >= PathTracer.RR_DEPTH && !survivesRoulette(sampler)) {
                    return;
                }
                depth++;
            }
        }

        /**
         * Step 1: distance sampling in the current medium up to the surface at tSurface (∞: none).
         * Weighs beta, and keeps it the estimate of MIS over the channels (the balance heuristic over
         * the three hero channels, on the whole path): beta / mean(ratios) with the path's ratios of
         * the channels' densities to the hero's, both divided by that mean at every step so that
         * the ratios keep mean 1 and nothing overflows.
         */
        private double sampleDistance(Ray ray, double tSurface, Sampler sampler) {
            sampler.get2D(u);
            double t = media.medium(medium).sampleScattering(ray.o, ray.d, tSurface, hero, u.u1, u.u2, tracking, weight, ratio);
            beta.mul(weight);
            channelRatio.mul(ratio);
            double mean = (channelRatio.r + channelRatio.g + channelRatio.b) / 3;
            if (!(mean > 0)) {
                beta.setZero();
            } else if (mean != 1) {
                beta.mul(1 / mean);
                channelRatio.mul(1 / mean);
            }
            return t;
        }

        /** Steps 2 in a medium: next-event estimation at the scattering point, then phase-function sampling; the ray leaves from there. */
        private void scatterInMedium(Ray ray, double t, Sampler sampler, MutableRgb out) {
            ray.at(t, p);
            wo.set(ray.d).negate();
            double g = media.medium(medium).g();
            light.atMedium(p, wo, g, medium, sampler, lightSamples, shadows, shadows, beta, out);
            prevP.set(p);
            prevAtSurface = false;
            sampler.get1D();                  // the lobe choice of a surface vertex: the layout stays the same
            sampler.get2D(u);
            prevPdf = HenyeyGreenstein.sample(g, wo, u.u1, u.u2, frame, wi);      // weight p / pdf = 1
            prevDelta = false;
            sinceScatter = 0;
            ray.o.set(p);
            ray.d.set(wi);
            ray.tMax = Double.POSITIVE_INFINITY;
        }

        /** Step 3 at an invisible surface: straight on, into the medium of the side the ray leaves towards. */
        private void crossInvisible(Ray ray) {
            medium = media.after(s.sp.material, medium, ray.d.dot(s.sp.ng));     // a NullBsdf is one-sided: ng is the surface's own
            wi.set(ray.d);
            s.spawn(ray, wi);
        }

        /** Step 3 at a surface: emission reached by the last phase or BSDF sample, weighted against light sampling (step 4). */
        private void addEmission(MutableRgb out) {
            if (s.emitted.isBlack()) {
                return;
            }
            double w = prevDelta ? 1 : !shadows ? 0 : MathUtil.powerHeuristic(prevPdf,
                    lights.pdf(prevP, prevAtSurface ? prevN : null, s.sp.prim, sinceScatter, s.cosEmitter));
            out.addProduct(beta, s.emitted, w);
        }

        /** The environment reached by the last phase or BSDF sample, weighted against light sampling (step 4). */
        private void addEnvironment(Ray ray, MutableRgb out) {
            if (environment.isBlack()) {
                return;
            }
            double w = prevDelta ? 1 : !shadows ? 0 : MathUtil.powerHeuristic(prevPdf, lights.environmentPdf(ray.d));
            out.addProduct(beta, environment.eval(ray.d, environmentRadiance), w);
        }

        /** Step 3 at a surface: next-event estimation, then BSDF sampling; the medium follows the new direction. */
        private boolean scatterAtSurface(Ray ray, Sampler sampler, MutableRgb out) {
            light.atSurface(s, medium, sampler, lightSamples, shadows, shadows, beta, out);
            if (!s.sampleBsdf(sampler)) {
                return false;
            }
            BsdfSample bs = s.bs;
            beta.mul(bs.weight);
            etaScale *= bs.eta * bs.eta;
            prevPdf = bs.pdf;
            prevDelta = bs.delta;
            sinceScatter = 0;
            prevP.set(s.sp.p);
            prevN.set(s.sp.n);
            prevAtSurface = true;
            medium = media.after(s.sp.material, medium, s.wi.dot(s.sp.ng) * (s.flipped ? -1 : 1));
            s.spawn(ray, s.wi);
            return true;
        }

        /** Russian roulette on the throughput without the refractions' radiance scaling, as {@link PathTracer}'s. */
        private boolean survivesRoulette(Sampler sampler) {
            double q = Math.min(beta.max() * etaScale, 0.95);
            if (!(sampler.get1D() < q)) {     // also ends a path whose throughput became NaN
                return false;
            }
            beta.mul(1 / q);
            return true;
        }

        @Override
        public long rayCount() {
            return tracer.rayCount() + transmittance.rays;
        }
    }
}
