package dev.strahl.integrator;

import dev.strahl.geometry.SurfacePoint;
import dev.strahl.light.LightSample;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.math.MathUtil;
import dev.strahl.color.MutableRgb;
import dev.strahl.medium.HenyeyGreenstein;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.Sampler;
import dev.strahl.world.Media;
import dev.strahl.world.World;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Next-event estimation in a world with participating media, at a surface point or at a
 * scattering point inside a medium: a point sampled on a light (or a direction towards the
 * environment), the scattering function there (the BSDF times |cosθ|, or the phase function),
 * the light's radiance and the {@link Transmittance} of the way to it, weighted against the other
 * strategy of the vertex (BSDF or phase-function sampling) by the power heuristic. The three
 * steps, {@link #sampleLight}, {@link #surfaceFactor} or {@link #mediumFactor}, and
 * {@link #resolve}, are apart so that each can be read (and reused) alone.
 *
 * <p><b>Random numbers.</b> Each light sample draws four numbers, always, whatever follows: a
 * pair for the point on the light, one for the choice of light, one that seeds ratio tracking.
 */
final class VolumeLight {
    private final LightSampler lights;
    private final Media media;
    private final Transmittance transmittance;
    private final SurfacePoint lightPoint = new SurfacePoint();
    private final LightSample ls = new LightSample();
    private final Sample2D uPoint = new Sample2D();
    private final Vector3d wiLocal = new Vector3d();
    private final Vector3d origin = new Vector3d();
    private final Vector3d toSurface = new Vector3d();
    private final Vector3d target = new Vector3d();
    private final Vector3d toTarget = new Vector3d();
    private final MutableRgb f = new MutableRgb();
    private final MutableRgb tr = new MutableRgb();
    private double uTrack;
    /** The scattering strategy's density of the sampled direction (solid angle), for the MIS weight. */
    private double scatterPdf;

    VolumeLight(World world, Transmittance transmittance) {
        this.lights = world.lights();
        this.media = world.media();
        this.transmittance = transmittance;
    }

    /**
     * Adds beta · f · Le · T · w / pdf for {@code n} light samples (each weighing 1/n) at the surface
     * set up in {@code s}, the path travelling in {@code medium} before it. Nothing is added at a
     * delta BSDF, but the numbers are drawn.
     */
    void atSurface(Shading s, int medium, Sampler sampler, int n, boolean mis, boolean shadows, MutableRgb beta, MutableRgb out) {
        boolean estimate = !s.bsdf.isDelta() && !lights.isEmpty();
        for (int i = 0; i < n; i++) {
            if (sampleLight(s.sp.p, s.sp.n, sampler, mis) && estimate && surfaceFactor(s)) {
                s.sp.spawnOrigin(ls.wi, origin);
                double cosOutward = ls.wi.dot(s.sp.ng) * (s.flipped ? -1 : 1);
                resolve(origin, media.after(s.sp.material, medium, cosOutward), n, mis, shadows, beta, out);
            }
        }
    }

    /** As {@link #atSurface}, at the point p of {@code medium} where light arriving along −wo scatters by HG(g). */
    void atMedium(Vector3dc p, Vector3dc wo, double g, int medium, Sampler sampler, int n, boolean mis, boolean shadows, MutableRgb beta,
                  MutableRgb out) {
        for (int i = 0; i < n; i++) {
            if (sampleLight(p, null, sampler, mis) && !lights.isEmpty()) {
                mediumFactor(wo, g);
                resolve(origin.set(p), medium, n, mis, shadows, beta, out);
            }
        }
    }

    /** Step 1: draws the four numbers and samples a light as seen from p (normal n, null in a medium); false if there is none to sample. */
    private boolean sampleLight(Vector3dc p, Vector3dc n, Sampler sampler, boolean mis) {
        sampler.get2D(uPoint);
        double uLight = sampler.get1D();
        uTrack = sampler.get1D();
        return lights.sample(p, n, uLight, uPoint.u1, uPoint.u2, !mis, lightPoint, ls);
    }

    /** Step 2 at a surface: f = BSDF · |cosθi| into {@link #f}; false where it is zero or the normals disagree (no leaks). */
    private boolean surfaceFactor(Shading s) {
        s.frame.toLocal(ls.wi, wiLocal);
        if (ls.wi.dot(s.sp.ng) * wiLocal.z <= 0) {
            return false;
        }
        Bsdf bsdf = s.bsdf;
        bsdf.eval(s.sp.uv, s.woLocal, wiLocal, f);
        f.mul(Math.abs(wiLocal.z));
        scatterPdf = bsdf.pdf(s.sp.uv, s.woLocal, wiLocal);
        return !f.isBlack();
    }

    /** Step 2 in a medium: f = the phase function, which is also phase sampling's density. */
    private void mediumFactor(Vector3dc wo, double g) {
        double phase = HenyeyGreenstein.pdf(g, wo, ls.wi);
        f.set(phase, phase, phase);
        scatterPdf = phase;
    }

    /**
     * Step 3: the transmittance from {@code from} (moved off its surface, if any) to the light, and
     * the sample's contribution beta · f · Le · T · w / (n · pdf) with the power heuristic against
     * the scattering strategy (weight 1 for delta lights and without MIS).
     */
    private void resolve(Vector3dc from, int medium, int n, boolean mis, boolean shadows, MutableRgb beta, MutableRgb out) {
        tr.set(1, 1, 1);
        if (shadows) {
            double distance = Double.POSITIVE_INFINITY;
            toTarget.set(ls.wi);
            if (!ls.infinite) {
                if (ls.delta) {
                    target.set(ls.p);                  // a point light is no surface: nothing to move off
                } else {
                    SurfacePoint.offset(ls.p, ls.ng, toSurface.set(ls.wi).negate(), target);
                }
                distance = toTarget.set(target).sub(from).length();
                if (!(distance > 0)) {
                    return;
                }
                toTarget.div(distance);                // from the moved origin straight to the (moved) light point
            }
            transmittance.random.seed(uTrack, uPoint.u1);
            if (!transmittance.along(from, toTarget, distance, medium, tr)) {
                return;
            }
        }
        double w = !mis || ls.delta ? 1 : MathUtil.powerHeuristic(n * ls.pdf, scatterPdf);
        f.mul(tr).mul(ls.radiance);
        out.addProduct(beta, f, w / (n * ls.pdf));
    }
}
