package dev.strahl.medium;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import org.joml.Vector3dc;

/**
 * A participating medium: extinction, single-scattering albedo and a Henyey–Greenstein phase
 * function of asymmetry {@link #g()}. Immutable and shared between threads; the two questions a
 * volumetric path tracer asks of it along a ray segment are answered without allocation:
 * <ul>
 *   <li>{@link #sampleScattering}: where along the segment the light of the path last scattered
 *       (free-flight sampling), with the weight that makes the estimate unbiased;</li>
 *   <li>{@link #transmittance}: the fraction of light that crosses the segment (for shadow rays),
 *       exact or an unbiased estimate.</li>
 * </ul>
 * A segment is o + t·d for t in (0, tMax), d a unit vector, tMax the distance to the next surface
 * (infinite if the ray leaves the scene).
 */
public sealed interface Medium permits HomogeneousMedium, GridMedium {

    /** The Henyey–Greenstein asymmetry g in (−1, 1) of the medium's phase function. */
    double g();

    /** The single-scattering albedo σs/σt per channel, in [0, 1]. */
    Rgb albedo();

    /**
     * Samples the first real scattering event along the segment. Returns its distance t in
     * (0, tMax), or {@link Double#POSITIVE_INFINITY} if the light crosses the whole segment; either
     * way sets {@code weight} to the factor the path throughput takes: T(t)·σs(t)/p(t) for a
     * scattering event, T(tMax)/P(reaching tMax) for a crossing (T the transmittance, p and P the
     * densities with which the {@code channel} (0, 1, 2: r, g, b) of a chromatic extinction
     * samples). {@code ratio} gets, per channel k, the density with which channel k would have
     * sampled the same outcome over the one of {@code channel}: a path tracer that chooses the
     * channel once per path (the hero channel) multiplies these up and divides its estimates by
     * their mean, which is MIS over the channels (1 in every channel where σt is grey). Uses the
     * caller's pair (u1, u2) and, where more numbers are needed (delta tracking), {@code random}
     * seeded from them.
     */
    double sampleScattering(Vector3dc o, Vector3dc d, double tMax, int channel, double u1, double u2, TrackingRandom random, MutableRgb weight,
                            MutableRgb ratio);

    /**
     * Multiplies {@code tr} by the transmittance of the segment (an unbiased estimate of it where
     * it is not known in closed form: ratio tracking, drawing from {@code random}, which the caller
     * has seeded).
     */
    void transmittance(Vector3dc o, Vector3dc d, double tMax, TrackingRandom random, MutableRgb tr);

    /** Checks the phase function's asymmetry: g in (−1, 1). */
    static double checkG(double g) {
        if (!(g > -1 && g < 1)) {
            throw new IllegalArgumentException("the phase function's g must lie in (-1, 1), got " + g);
        }
        return g;
    }

    /** Checks a single-scattering albedo: every channel in [0, 1]. */
    static Rgb checkAlbedo(Rgb albedo) {
        if (!(albedo.r() >= 0 && albedo.g() >= 0 && albedo.b() >= 0 && albedo.max() <= 1)) {
            throw new IllegalArgumentException("the albedo must lie in [0, 1] in every channel, got " + albedo);
        }
        return albedo;
    }

    /** e^(−σ·d), 1 where σ = 0 (also for an infinite d). */
    static double beerLambert(double sigma, double d) {
        return sigma == 0 ? 1 : Math.exp(-sigma * d);
    }
}
