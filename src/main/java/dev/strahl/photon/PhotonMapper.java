package dev.strahl.photon;

import dev.strahl.integrator.Parallel;
import dev.strahl.integrator.PathTracer;
import dev.strahl.integrator.TracingWorker;
import dev.strahl.color.MutableRgb;
import dev.strahl.integrator.DirectLight;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.Shading;
import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Ray;
import dev.strahl.material.Bsdf;
import dev.strahl.sampling.Sampler;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * Photon mapping, progressive and consistent: <b>probabilistic progressive photon mapping</b>
 * (Knaus &amp; Zwicker, "Progressive Photon Mapping: A Probabilistic Approach", ACM TOG 30(3),
 * 2011). Each sample index is one <em>iteration</em>: an independent photon-mapping estimate
 * with its own photons and its own gather radius r_i. The image, the plain mean of the
 * iterations, converges to the solution of the rendering equation (the path tracer's image):
 * with r_{i+1}² = r_i² (i + α) / (i + 1), α = {@value #ALPHA} (so r_i² ∝ i^(α−1)), both the
 * bias of the density estimate and the variance of the mean vanish as iterations grow
 * (Knaus &amp; Zwicker 2011, §4; α ∈ (0, 1) trades one for the other).
 *
 * <p><b>One iteration.</b> Before the pixels take sample index i, {@link #prepareSample} traces
 * {@code photonsPerIteration} photons ({@link PhotonSource}, {@link PhotonTracer}) in chunks of
 * {@value #PHOTONS_PER_CHUNK} on the render job's threads, concatenates the chunks in order and
 * builds a {@link PhotonMap} with cells of edge r_i. Photon j of iteration i draws from a stream
 * of (seed, i, j) only, so the map, and the image, are the same bits on any number of threads.
 *
 * <p><b>Camera paths.</b> A camera ray is followed through specular (delta) bounces, weighted by
 * the BSDF sample weights, collecting emission it hits. At the first diffuse or glossy surface it
 * ends with the sum of
 * <ul>
 *   <li>direct light by next-event estimation (one light sample, {@link DirectLight}),</li>
 *   <li>the density estimate of all other light, Σ_p f(wo, wp) Φ_p / (π r_i²) over the photons
 *       p within r_i (constant kernel), wp the direction the photon came from; photons arriving
 *       from behind the surface's geometric normal do not count.</li>
 * </ul>
 * Caustics (light → specular → diffuse → camera) come from the photons, which makes them clean
 * long before a path tracer's, which finds them only when a BSDF sample happens to hit the light
 * through the specular chain. Every vertex draws its numbers as the path tracer's do (the light
 * sample's, even at a specular vertex, then the BSDF sample's), so a pixel's samples keep their
 * stratified pairs whatever surface their first hit is on.
 *
 * <p><b>Max depth</b> counts segments of the whole light path as for the path tracer: a camera
 * path of k segments to its visible point plus a photon path of s segments from the light make
 * k + s. The camera path follows specular bounces while k ≤ maxDepth; next-event estimation
 * counts if k + 1 ≤ maxDepth; a photon counts if k + s ≤ maxDepth. With −1, Russian roulette ends
 * both kinds of path. The same light paths as the path tracer's are thus included, and the image
 * converges to the path tracer's at every max depth.
 *
 * <p>A scene's environment is a light too: it emits photons, and next-event estimation samples it,
 * so its photons are stored from their second hit on, like those of the area lights.
 *
 * <p>Without {@code shadows} (a teaching option) next-event estimation takes every light sample as
 * visible and traces no shadow ray; the photons still travel through the scene as always, so only
 * the direct light loses its shadows, as in the path tracer's {@code UNOCCLUDED} strategy.
 */
public final class PhotonMapper implements Integrator {
    /** Knaus and Zwicker's α: the fraction of the radius reduction kept per iteration. */
    static final double ALPHA = 2.0 / 3;
    /** Photons per chunk of tracing work: fixed, so the chunking does not depend on the threads. */
    static final int PHOTONS_PER_CHUNK = 4096;
    private static final int STRIDE = PhotonList.STRIDE;

    private final World world;
    private final Bsdf[] bsdfs;
    private final int maxDepth;
    private final boolean cullBackFaces;
    private final DirectLight.Use lightUse;
    private final int photonsPerIteration;
    private final double initialRadius;
    private final int minPhotonSegments;
    private final boolean tracesPhotons;
    private final PhotonList[] chunks;
    private final PhotonList all = new PhotonList();
    private volatile Iteration current;

    /** The prepared iteration: its photon map and gather radius, 1/(π r²) for the estimate. */
    private record Iteration(int sampleIndex, PhotonMap map, double radius, double norm) {}

    public PhotonMapper(World world, int maxDepth, boolean uniformHemisphere, boolean cullBackFaces, int photonsPerIteration,
                        double initialRadius, boolean shadows) {
        this.world = world;
        this.bsdfs = Shading.bsdfs(world, uniformHemisphere);
        this.maxDepth = Integrator.checkMaxDepth(maxDepth);
        this.cullBackFaces = cullBackFaces;
        this.lightUse = shadows ? DirectLight.Use.LIGHT_ONLY : DirectLight.Use.UNOCCLUDED;
        this.photonsPerIteration = photonsPerIteration;
        this.initialRadius = initialRadius > 0 ? initialRadius : automaticRadius(world);
        boolean emits = !world.lights().isEmpty() || !world.environment().isBlack();
        // Stored photons have >= 2 segments: next-event estimation covers the first.
        this.minPhotonSegments = 2;
        this.tracesPhotons = emits && (maxDepth < 0 || maxDepth >= 1 + minPhotonSegments);
        int chunkCount = tracesPhotons ? (photonsPerIteration + PHOTONS_PER_CHUNK - 1) / PHOTONS_PER_CHUNK : 0;
        this.chunks = new PhotonList[chunkCount];
        for (int i = 0; i < chunkCount; i++) {
            chunks[i] = new PhotonList();
        }
    }

    /** The automatic gather radius, as a fraction of the scene's bounding-box diagonal. */
    static final double RADIUS_FRACTION = 0.01;

    /** {@value #RADIUS_FRACTION} of the scene's bounding-box diagonal (1 for an empty scene). */
    static double automaticRadius(World world) {
        Aabb box = world.bounds();
        double diagonal = box.diagonal();
        return diagonal > 0 && Double.isFinite(diagonal) ? RADIUS_FRACTION * diagonal : 1;
    }

    /** The gather radius of the first iteration. */
    public double initialRadius() {
        return initialRadius;
    }

    /**
     * r_i² of iteration i ≥ 1: r_1² · Π_{k=1}^{i−1} (k + α)/(k + 1) (Knaus &amp; Zwicker 2011,
     * eq. 20). Computed by the product itself, so it is the same bits whatever came before.
     */
    static double radiusSquared(double r1, int iteration) {
        double r2 = r1 * r1;
        for (int k = 1; k < iteration; k++) {
            r2 *= (k + ALPHA) / (k + 1);
        }
        return r2;
    }

    @Override
    public boolean preparesEachSample() {
        return true;
    }

    @Override
    public void prepareSample(long seed, int sampleIndex, Parallel parallel) {
        double r2 = radiusSquared(initialRadius, sampleIndex + 1);
        double radius = Math.sqrt(r2);
        PhotonMap map;
        if (tracesPhotons) {
            double fluxScale = 1.0 / photonsPerIteration;
            for (PhotonList c : chunks) {
                c.clear();
            }
            parallel.forEach(chunks.length, (c, worker) -> {
                int first = c * PHOTONS_PER_CHUNK;
                int end = Math.min(photonsPerIteration, first + PHOTONS_PER_CHUNK);
                ((PhotonWorker) worker).photons.trace(seed, sampleIndex, first, end, fluxScale, chunks[c]);
            });
            all.clear();
            for (PhotonList c : chunks) {
                all.addAll(c);
            }
            map = PhotonMap.build(all, radius, parallel);
        } else {
            map = PhotonMap.empty();
        }
        current = new Iteration(sampleIndex, map, radius, 1 / (Math.PI * r2));
    }

    /** Photons in the map of the prepared iteration (for tests and reports). */
    int storedPhotons() {
        Iteration it = current;
        return it == null ? 0 : it.map.size();
    }

    @Override
    public Worker newWorker() {
        return new PhotonWorker();
    }

    private final class PhotonWorker extends TracingWorker implements PhotonMap.Visitor {
        final PhotonTracer photons = new PhotonTracer(tracer, new PhotonSource(world), maxDepth);
        private final Shading s = new Shading();
        private final Vector3d wp = new Vector3d();
        private final Vector3d wpLocal = new Vector3d();
        private final MutableRgb beta = new MutableRgb();
        private final MutableRgb f = new MutableRgb();
        private final MutableRgb gathered = new MutableRgb();
        private final PhotonMap.Search search = new PhotonMap.Search();
        private float[] photonData;
        private int maxSegments;

        PhotonWorker() {
            super(world, bsdfs, cullBackFaces);
        }

        @Override
        public void radiance(Ray ray, Sampler sampler, MutableRgb out) {
            Iteration it = current;
            if (it == null) {
                throw new IllegalStateException("prepareSample was not called before radiance");
            }
            out.setZero();
            beta.set(1, 1, 1);
            double etaScale = 1;                       // product of η'² over the refractions so far (for the roulette)
            for (int depth = 1; ; depth++) {
                if (tracer.trace(ray, s) < 0) {
                    addEnvironment(ray, beta, 1, out);
                    return;
                }
                out.addProduct(beta, s.emitted, 1);     // reached directly or through specular bounces only
                if (maxDepth > 0 && depth >= maxDepth) {
                    return;
                }
                tracer.direct.add(s, sampler, 1, lightUse, beta, out);
                if (!s.bsdf.isDelta()) {
                    if (maxDepth < 0 || depth + minPhotonSegments <= maxDepth) {
                        gather(it, depth, out);
                    }
                    return;
                }
                if (!s.sampleBsdf(sampler)) {
                    return;
                }
                beta.mul(s.bs.weight);
                etaScale *= s.bs.eta * s.bs.eta;
                s.spawn(ray, s.wi);
                if (depth >= PathTracer.RR_DEPTH) {
                    double q = PathTracer.survival(beta, etaScale);
                    if (!(sampler.get1D() < q)) {
                        return;
                    }
                    beta.mul(1 / q);
                }
            }
        }

        /** Adds beta · Σ f(wo, wp) Φ_p / (π r²) over the photons around the visible point to out. */
        private void gather(Iteration it, int depth, MutableRgb out) {
            PhotonMap map = it.map;
            if (map.size() == 0) {
                return;
            }
            photonData = map.data();
            maxSegments = maxDepth < 0 ? Integer.MAX_VALUE : maxDepth - depth;
            gathered.setZero();
            map.forEachWithin(s.sp.p.x, s.sp.p.y, s.sp.p.z, it.radius, search, this);
            out.addProduct(beta, gathered, it.norm);
        }

        @Override
        public void visit(int photon, double dist2) {
            float[] d = photonData;
            int o = photon * STRIDE;
            if (d[o + PhotonList.SEGMENTS] > maxSegments) {
                return;
            }
            wp.set(d[o + PhotonList.WX], d[o + PhotonList.WX + 1], d[o + PhotonList.WX + 2]);
            if (wp.dot(s.sp.ng) <= 0) {
                return;                                 // arrived at the other side of the surface
            }
            s.frame.toLocal(wp, wpLocal);
            s.bsdf.eval(s.sp.uv, s.woLocal, wpLocal, f);
            gathered.r += f.r * d[o + PhotonList.R];
            gathered.g += f.g * d[o + PhotonList.R + 1];
            gathered.b += f.b * d[o + PhotonList.R + 2];
        }
    }
}
