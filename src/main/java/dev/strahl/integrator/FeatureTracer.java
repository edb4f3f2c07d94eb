package dev.strahl.integrator;

import dev.strahl.geometry.Ray;
import dev.strahl.material.Bsdf;
import dev.strahl.color.MutableRgb;
import dev.strahl.sampling.SplitMix64;
import dev.strahl.world.World;
import java.util.Arrays;

/**
 * The feature buffers' tracer (AOVs: what a denoiser is guided by), apart from every integrator:
 * it follows a camera ray through specular surfaces to the first surface that is not, and records
 * <ul>
 *   <li><b>albedo</b>: that surface's {@link Bsdf#albedo}, times the tint of the specular surfaces
 *       on the way (a mirror's Ks; clear glass 1), as Intel Open Image Denoise recommends for
 *       mirrors and glass;</li>
 *   <li><b>normal</b>: its shading normal in world space, turned to the side the ray came from
 *       for two-sided surfaces (as shading sees it);</li>
 *   <li><b>depth</b>: the distance along the camera ray to the first hit, specular or not, that is not invisible (a null surface).</li>
 * </ul>
 * A ray that leaves the scene records zero albedo and normal (and depth 0 if the camera ray
 * itself escapes).
 *
 * <p><b>Specular</b> means {@link Bsdf#isDelta()}: perfect mirrors and smooth glass. Rough
 * surfaces (glossy, and the rough conductors and dielectrics to come) count as non-specular: their
 * albedo is recorded, and the denoiser keeps their blurred reflections as lighting. At smooth
 * glass the tracer follows reflection or refraction, chosen with the Fresnel probability the BSDF's
 * own sampling uses, so the albedo of a pixel is the mean of both over its samples. That choice
 * draws from a stream of its own, keyed by (seed, pixel, sample index) with a salt: never from the
 * image's sampler, so the image is the same bits with and without feature buffers, and the
 * features are the same bits on any thread count. At most {@value #MAX_SPECULAR} specular
 * bounces are followed; a path still specular then records its last surface.
 *
 * <p>One per thread, like an integrator's worker; allocates nothing per ray.
 */
public final class FeatureTracer {
    /** Values per pixel sample: albedo r, g, b, normal x, y, z, depth. */
    public static final int CHANNELS = 7;
    /** Specular bounces followed at most. */
    public static final int MAX_SPECULAR = 16;
    /** Keeps the feature streams apart from the image's streams of the same (seed, pixel, sample). */
    private static final long SALT = 0x5f3759df_a0e1_b7c3L;

    private final Tracer tracer;
    private final Shading s = new Shading();
    private final MutableRgb tint = new MutableRgb();
    private final MutableRgb albedo = new MutableRgb();

    /**
     * A tracer for one thread.
     *
     * @param world         the scene
     * @param cullBackFaces whether camera rays skip back faces, as the render's
     */
    public FeatureTracer(World world, boolean cullBackFaces) {
        this.tracer = new Tracer(world, Shading.bsdfs(world, false), cullBackFaces);
    }

    /**
     * Traces the features of one camera sample into {@code out[0..6]} (albedo, normal, depth).
     * May modify {@code ray}.
     *
     * @param ray    the camera ray, unit direction
     * @param seed   the render seed
     * @param x      the pixel's column
     * @param y      the pixel's row
     * @param sample the sample index
     * @param out    receives {@value #CHANNELS} values
     */
    public void trace(Ray ray, long seed, int x, int y, int sample, double[] out) {
        Arrays.fill(out, 0, CHANNELS, 0.0);
        tint.set(1, 1, 1);
        long stream = 0;
        for (int bounce = 0, first = 0; ; bounce++) {
            double t = tracer.trace(ray, s);
            if (t < 0) {
                return;
            }
            Bsdf bsdf = s.bsdf;
            if (bounce == first) {                 // the first hit, past invisible surfaces (a medium's boundary)
                out[6] += t;
                first += bsdf instanceof dev.strahl.material.NullBsdf ? 1 : 0;
            }
            bsdf.albedo(s.sp.uv, s.woLocal, albedo);
            albedo.mul(tint);
            if (!bsdf.isDelta() || bounce == MAX_SPECULAR) {
                out[0] = albedo.r;
                out[1] = albedo.g;
                out[2] = albedo.b;
                out[3] = s.sp.n.x;
                out[4] = s.sp.n.y;
                out[5] = s.sp.n.z;
                return;
            }
            tint.set(albedo);
            if (stream == 0) {
                stream = SplitMix64.streamSeed(seed ^ SALT, x, y, sample);
            }
            double uc = SplitMix64.toUnit(SplitMix64.at(stream, bounce + 1));
            if (!bsdf.sample(s.sp.uv, s.woLocal, uc, 0.5, 0.5, s.bs)) {
                return;
            }
            s.frame.toWorld(s.bs.wi, s.wi);
            s.spawn(ray, s.wi);
        }
    }

    /**
     * Rays traced so far.
     *
     * @return the count
     */
    public long rayCount() {
        return tracer.rayCount();
    }
}
