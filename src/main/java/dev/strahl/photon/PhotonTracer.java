package dev.strahl.photon;

import dev.strahl.integrator.Shading;
import dev.strahl.integrator.Tracer;
import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.material.Bsdf;
import dev.strahl.material.Dielectric;
import dev.strahl.material.Fresnel;
import dev.strahl.sampling.IndependentSampler;
import dev.strahl.sampling.SplitMix64;
import org.joml.Vector3d;

/**
 * Traces photons from the lights through the scene and records where they land on non-specular
 * surfaces. One per worker thread; owns its scratch objects.
 *
 * <p><b>What is stored.</b> A photon is recorded at every hit on a surface whose BSDF is not a
 * pure delta (diffuse and glossy), after at least one scattering: light arriving straight from a
 * light or the environment is what next-event estimation at the camera's visible point already
 * computes (it samples both).
 * Caustic paths (light → mirror or glass → diffuse) are thus in the map, direct light is not.
 *
 * <p><b>Scattering</b> uses the BSDFs' own {@code sample}, with the photon's direction back to
 * where it came from as the first argument: all strahl BSDFs are symmetric, f(a, b) = f(b, a),
 * so sampling the other direction from it is sampling the adjoint. Two corrections make the
 * weights those of importance (flux) transport rather than radiance transport (Veach 1997,
 * §5.2–5.3; pbrt-v3 §16.1, pbrt-v4 §9.5.2 and {@code TransportMode::Importance}):
 * <ul>
 *   <li>refraction through a dielectric: the 1/η'² that radiance picks up (Dielectric's sample
 *       weight) does not apply to flux, so the weight is multiplied back by η'²;</li>
 *   <li>shading normals: the adjoint BSDF carries |wp·n|·|wi·ng| / (|wp·ng|·|wi·n|) for the
 *       photon's direction back to where it came from wp and its new direction wi, n the shading
 *       and ng the geometric normal (Veach 1997, §5.3.2; pbrt-v3's
 *       {@code CorrectShadingNormal}); 1 where n = ng.</li>
 * </ul>
 *
 * <p><b>Russian roulette</b> after every scattering, as pbrt-v4's SPPM does: the photon goes on
 * with probability q = min(max(β')/max(β), 0.99) for flux β before and β' after the scattering,
 * and its flux is divided by q — so photons keep about the flux they left the light with.
 * The 0.99 bounds paths between perfect mirrors or inside glass.
 *
 * <p><b>Depth.</b> A photon that lands after s segments (s − 1 scatterings) stands for paths of
 * s + k segments, k ≥ 1 being the camera path to the visible point; with a bounded max depth D it
 * is stored only if s + 1 ≤ D and traced on only while the next landing can still be stored.
 */
final class PhotonTracer {
    /** Continuation probability never exceeds this, so every photon path ends. */
    static final double MAX_CONTINUATION = 0.99;
    private static final long PHOTON_STREAM_SALT = 0x70686f746f6e73L;      // "photons"

    private final Tracer tracer;
    private final PhotonSource source;
    private final int maxDepth;
    private final Shading s = new Shading();
    /** Started per photon on the photon's own stream: no pixel sample, so no stratification either. */
    private final IndependentSampler sampler = new IndependentSampler(0);
    private final Ray ray = new Ray();
    private final MutableRgb beta = new MutableRgb();
    private final MutableRgb next = new MutableRgb();
    private final Vector3d wo = new Vector3d();

    PhotonTracer(Tracer tracer, PhotonSource source, int maxDepth) {
        this.tracer = tracer;
        this.source = source;
        this.maxDepth = maxDepth;
    }

    /** The random stream of photon {@code photon} in iteration {@code iteration}: a function of these and the seed only. */
    static long streamSeed(long seed, int iteration, long photon) {
        return SplitMix64.mix64(SplitMix64.mix64(SplitMix64.mix64(seed ^ PHOTON_STREAM_SALT) ^ iteration * SplitMix64.GOLDEN_GAMMA) ^ photon);
    }

    /**
     * Traces photons {@code first} .. {@code end − 1} of an iteration and appends what they leave
     * on surfaces to {@code out}; each carries its share of the flux times {@code fluxScale}
     * (1 / the photons emitted in the iteration).
     */
    void trace(long seed, int iteration, int first, int end, double fluxScale, PhotonList out) {
        for (int j = first; j < end; j++) {
            sampler.startStream(streamSeed(seed, iteration, j));
            source.emit(sampler, ray, beta);
            beta.mul(fluxScale);
            follow(out);
        }
    }

    private void follow(PhotonList out) {
        for (int segments = 1; ; segments++) {
            if (tracer.trace(ray, s) < 0) {
                return;
            }
            Bsdf bsdf = s.bsdf;
            SurfacePoint sp = s.sp;
            if (!bsdf.isDelta() && segments >= 2 && (maxDepth < 0 || segments + 1 <= maxDepth)) {
                out.add(sp.p.x, sp.p.y, sp.p.z, -ray.d.x, -ray.d.y, -ray.d.z, beta.r, beta.g, beta.b, segments);
            }
            if (maxDepth > 0 && segments + 2 > maxDepth) {
                return;                            // a further landing could not be stored
            }
            if (!s.sampleBsdf(sampler)) {
                return;                            // absorbed, or a light leak where shading and geometric normal disagree
            }
            next.set(beta).mul(s.bs.weight).mul(adjointFactor(bsdf, sp));
            double q = Math.min(next.max() / beta.max(), MAX_CONTINUATION);
            if (!(sampler.get1D() < q)) {          // also ends a photon whose flux became NaN
                return;
            }
            beta.set(next).mul(1 / q);
            s.spawn(ray, s.wi);
        }
    }

    /**
     * What turns the radiance sample weight {@code bs.weight} into the flux weight: η'² for a
     * refraction, times the shading-normal correction of the adjoint BSDF.
     */
    private double adjointFactor(Bsdf bsdf, SurfacePoint sp) {
        double factor = 1;
        if (bsdf instanceof Dielectric d && s.bs.wi.z * s.woLocal.z < 0) {
            double eta = Fresnel.relativeEta(s.woLocal.z, d.eta());
            factor = eta * eta;
        }
        if (!sp.n.equals(sp.ng)) {
            wo.set(ray.d).negate();
            double denominator = Math.abs(wo.dot(sp.ng)) * Math.abs(s.bs.wi.z);
            factor *= denominator > 0 ? Math.abs(s.woLocal.z) * Math.abs(s.wi.dot(sp.ng)) / denominator : 0;
        }
        return factor;
    }
}
