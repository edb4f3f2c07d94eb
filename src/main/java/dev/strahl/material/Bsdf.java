package dev.strahl.material;

import dev.strahl.color.MutableRgb;
import dev.strahl.image.Rgb;
import org.joml.Vector2d;
import org.joml.Vector2dc;
import org.joml.Vector3dc;

/**
 * A bidirectional scattering distribution function in the local frame (z = shading normal; see
 * the package documentation for the direction convention). Implementations are immutable and
 * shared between threads.
 *
 * <p>Every method takes the shading point's texture coordinates {@code uv}, at which the BSDF looks
 * up its textured parameters (Mitsuba's way: the BSDF stays immutable, nothing is allocated per hit).
 * The overloads without {@code uv} evaluate at (0, 0): for parameters that are constants, and tests.
 */
public sealed interface Bsdf permits Lambert, Glossy, Conductor, Principled, Glass, DeltaBsdf {

    /** Texture coordinates (0, 0), for the overloads without uv. Never modified. */
    Vector2dc ORIGIN = new Vector2d();

    /** f(wo, wi) WITHOUT the cosine factor at texture coordinates uv, into {@code dest}. Zero for delta lobes. */
    void eval(Vector2dc uv, Vector3dc wo, Vector3dc wi, MutableRgb dest);

    /** Solid-angle density with which {@link #sample} picks wi given wo at uv. Zero for delta lobes. */
    double pdf(Vector2dc uv, Vector3dc wo, Vector3dc wi);

    /**
     * Samples wi given wo at texture coordinates uv from the uniform numbers uc (lobe choice) and
     * (u1, u2) (direction). Returns false if the path is absorbed.
     */
    boolean sample(Vector2dc uv, Vector3dc wo, double uc, double u1, double u2, BsdfSample out);

    /** {@link #eval(Vector2dc, Vector3dc, Vector3dc, MutableRgb)} at uv = (0, 0). */
    default void eval(Vector3dc wo, Vector3dc wi, MutableRgb dest) {
        eval(ORIGIN, wo, wi, dest);
    }

    /** {@link #pdf(Vector2dc, Vector3dc, Vector3dc)} at uv = (0, 0). */
    default double pdf(Vector3dc wo, Vector3dc wi) {
        return pdf(ORIGIN, wo, wi);
    }

    /** {@link #sample(Vector2dc, Vector3dc, double, double, double, BsdfSample)} at uv = (0, 0). */
    default boolean sample(Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        return sample(ORIGIN, wo, uc, u1, u2, out);
    }

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
    void albedo(Vector2dc uv, Vector3dc wo, MutableRgb dest);

    /**
     * Completes a sample whose direction {@code out.wi} was drawn from one lobe of a mixture: its
     * pdf is the whole BSDF's ({@link #pdf}: the mixture's density, as MIS needs) and its weight
     * f·|cos θi|/pdf. False (the path ends) for a direction of zero or non-finite density or weight.
     */
    default boolean weighByPdf(Vector2dc uv, Vector3dc wo, BsdfSample out) {
        out.pdf = pdf(uv, wo, out.wi);
        if (!(out.pdf > 0) || !Double.isFinite(out.pdf)) {
            return false;
        }
        eval(uv, wo, out.wi, out.weight);
        out.weight.mul(Math.abs(out.wi.z) / out.pdf);
        return out.weight.isFinite();
    }

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
