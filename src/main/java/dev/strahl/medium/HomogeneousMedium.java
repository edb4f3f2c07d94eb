package dev.strahl.medium;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import org.joml.Vector3dc;

/**
 * A medium of the same extinction σt (per scene unit, per channel) and albedo everywhere, as
 * Mitsuba 3's {@code homogeneous} with an {@code hg} phase function.
 *
 * <p><b>Chromatic extinction.</b> Where σt differs between channels, a distance sampled in
 * proportion to one channel's e^(−σt·t) would weigh the others by ratios of exponentials that grow
 * without bound along a path (colour noise). So {@link #sampleScattering} samples the channel it is
 * told (the path's hero channel, chosen once per path) and reports the ratios of the channels'
 * densities to it; the path tracer divides by their mean over the whole path, which is one-sample
 * MIS with the balance heuristic over the three channels' strategies (the spectral MIS of Mitsuba's
 * {@code volpathmis} and pbrt-v4's {@code VolPathIntegrator}). Each channel's estimate is then at
 * most 3 × what sampling that channel alone gives. For a grey σt this is plain free-flight
 * sampling: weight = albedo, ratios 1.
 *
 * <p><b>Absorption only</b> (albedo 0 in every channel, tinted glass): nothing scatters, so no
 * distance is sampled; the light crosses every segment with weight T = e^(−σt·tMax), which has no
 * variance at all.
 *
 * @param sigmaT extinction per scene unit, finite and ≥ 0 in every channel
 * @param albedo single-scattering albedo σs/σt, in [0, 1] per channel
 * @param g      Henyey–Greenstein asymmetry in (−1, 1)
 */
public record HomogeneousMedium(Rgb sigmaT, Rgb albedo, double g) implements Medium {

    /** Checks the three parameters' ranges. */
    public HomogeneousMedium {
        if (!(sigmaT.r() >= 0 && sigmaT.g() >= 0 && sigmaT.b() >= 0 && Double.isFinite(sigmaT.max()))) {
            throw new IllegalArgumentException("sigmaT must be finite and >= 0 in every channel, got " + sigmaT);
        }
        Medium.checkAlbedo(albedo);
        Medium.checkG(g);
    }

    @Override
    public double sampleScattering(Vector3dc o, Vector3dc d, double tMax, int channel, double u1, double u2, TrackingRandom random,
                                   MutableRgb weight, MutableRgb ratio) {
        double sr = sigmaT.r(), sg = sigmaT.g(), sb = sigmaT.b();
        ratio.set(1, 1, 1);
        if (albedo.isBlack()) {              // nothing scatters: cross with the transmittance, no sampling
            weight.set(Medium.beerLambert(sr, tMax), Medium.beerLambert(sg, tMax), Medium.beerLambert(sb, tMax));
            return Double.POSITIVE_INFINITY;
        }
        double hero = channel == 0 ? sr : channel == 1 ? sg : sb;
        double t = hero > 0 ? -Math.log1p(-u2) / hero : Double.POSITIVE_INFINITY;
        if (t < tMax) {
            double tr = Math.exp(-sr * t), tg = Math.exp(-sg * t), tb = Math.exp(-sb * t);
            double pdf = hero * (channel == 0 ? tr : channel == 1 ? tg : tb);
            if (!(pdf > 0)) {
                weight.setZero();
                return t;
            }
            ratio.set(sr * tr / pdf, sg * tg / pdf, sb * tb / pdf);
            weight.set(albedo.r() * ratio.r, albedo.g() * ratio.g, albedo.b() * ratio.b);
            return t;
        }
        double tr = Medium.beerLambert(sr, tMax), tg = Medium.beerLambert(sg, tMax), tb = Medium.beerLambert(sb, tMax);
        double pass = channel == 0 ? tr : channel == 1 ? tg : tb;
        if (!(pass > 0)) {
            weight.setZero();
            return Double.POSITIVE_INFINITY;
        }
        ratio.set(tr / pass, tg / pass, tb / pass);
        weight.set(ratio);
        return Double.POSITIVE_INFINITY;
    }

    @Override
    public void transmittance(Vector3dc o, Vector3dc d, double tMax, TrackingRandom random, MutableRgb tr) {
        tr.r *= Medium.beerLambert(sigmaT.r(), tMax);
        tr.g *= Medium.beerLambert(sigmaT.g(), tMax);
        tr.b *= Medium.beerLambert(sigmaT.b(), tMax);
    }
}
