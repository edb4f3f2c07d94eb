package dev.strahl.material;

import dev.strahl.math.MutableRgb;
import dev.strahl.image.Rgb;
import org.joml.Vector3dc;

/**
 * A bidirectional scattering distribution function in the local frame (z = shading normal; see
 * the package documentation for the direction convention). Implementations are immutable and
 * shared between threads.
 */
public sealed interface Bsdf permits Lambert, Glossy, DeltaBsdf {

    /** f(wo, wi) WITHOUT the cosine factor, into {@code dest}. Zero for delta lobes. */
    void eval(Vector3dc wo, Vector3dc wi, MutableRgb dest);

    /** Solid-angle density with which {@link #sample} picks wi given wo. Zero for delta lobes. */
    double pdf(Vector3dc wo, Vector3dc wi);

    /**
     * Samples wi given wo from the uniform numbers uc (lobe choice) and (u1, u2) (direction).
     * Returns false if the path is absorbed.
     */
    boolean sample(Vector3dc wo, double uc, double u1, double u2, BsdfSample out);

    /**
     * The albedo of this surface seen from {@code wo}, into {@code dest}: what the feature buffers
     * (and so the denoiser) take as the surface's colour. The contract every BSDF keeps:
     * <ul>
     *   <li>each channel lies in [0, 1] and approximates the directional albedo
     *       ∫ f(wo, wi) |cosθi| dωi (the fraction of light arriving along wo that the surface
     *       scatters, reflection and transmission together); an exact integral is not required,
     *       a closed form that follows the colour the eye sees is (Kd + Ks for a diffuse base
     *       under a glossy coat; the texture's value at the point for a textured surface);</li>
     *   <li>deterministic and cheap: no random numbers, no tracing, no allocation;</li>
     *   <li>for a BSDF whose lobes are all deltas ({@link #isDelta()}), the tint its specular
     *       interaction gives whatever is seen through or in it (a mirror's Ks, 1 for clear
     *       glass): the feature tracer looks through such surfaces and multiplies by it;</li>
     *   <li>defined for wo on either side (two-sided surfaces may ignore the side).</li>
     * </ul>
     */
    void albedo(Vector3dc wo, MutableRgb dest);

    /** Whether every lobe is a delta (no light sampling possible at this surface). */
    default boolean isDelta() {
        return false;
    }

    /**
     * Whether the back face scatters like the front face. The integrator then turns the frame to
     * the side of wo. Dielectrics are not two-sided: their inside differs from their outside.
     */
    default boolean isTwoSided() {
        return true;
    }

    /** This BSDF with its diffuse lobes sampled uniformly or cosine-weighted; BSDFs without diffuse lobes return themselves. */
    default Bsdf withUniformHemisphere(boolean uniform) {
        return this;
    }
}
