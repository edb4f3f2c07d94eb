package dev.strahl.medium;

import dev.strahl.image.Rgb;
import dev.strahl.math.MutableRgb;
import org.joml.Vector3dc;

/**
 * A medium of the same extinction σt (per scene unit, per channel) and albedo everywhere, as
 * Mitsuba 3's {@code homogeneous} with an {@code hg} phase function.
 *
 * <p><b>Chromatic extinction.</b> Where σt differs between channels, a distance sampled in
 * proportion to one channel's e^(−σt·t) would weigh the others by ratios of exponentials that grow
 * without bound (colour noise). So each segment picks a channel uniformly and samples its
 * exponential, and the weight divides by the density of the three strategies together, the mean
 * of the channels' densities: one-sample MIS with the balance heuristic over the channels (the
 * spectral MIS of Mitsuba's {@code volpathmis} and pbrt-v4, per segment). Every weight is then at
 * most 3·albedo. For a grey σt this is plain free-flight sampling, weight = albedo.
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
    public double sampleScattering(Vector3dc o, Vector3dc d, double tMax, double u1, double u2, TrackingRandom random, MutableRgb weight) {
        double sr = sigmaT.r(), sg = sigmaT.g(), sb = sigmaT.b();
        if (!albedo.isBlack()) {
            double chosen = u1 < 1.0 / 3 ? sr : u1 < 2.0 / 3 ? sg : sb;
            double t = chosen > 0 ? -Math.log1p(-u2) / chosen : Double.POSITIVE_INFINITY;
            if (t < tMax) {
                double tr = Math.exp(-sr * t), tg = Math.exp(-sg * t), tb = Math.exp(-sb * t);
                double pdf = (sr * tr + sg * tg + sb * tb) / 3;
                if (!(pdf > 0)) {
                    weight.setZero();
                } else {
                    weight.set(albedo.r() * sr * tr / pdf, albedo.g() * sg * tg / pdf, albedo.b() * sb * tb / pdf);
                }
                return t;
            }
        }
        double tr = Medium.beerLambert(sr, tMax), tg = Medium.beerLambert(sg, tMax), tb = Medium.beerLambert(sb, tMax);
        double pass = albedo.isBlack() ? 1 : (tr + tg + tb) / 3;
        if (!(pass > 0)) {
            weight.setZero();
        } else {
            weight.set(tr / pass, tg / pass, tb / pass);
        }
        return Double.POSITIVE_INFINITY;
    }

    @Override
    public void transmittance(Vector3dc o, Vector3dc d, double tMax, TrackingRandom random, MutableRgb tr) {
        tr.r *= Medium.beerLambert(sigmaT.r(), tMax);
        tr.g *= Medium.beerLambert(sigmaT.g(), tMax);
        tr.b *= Medium.beerLambert(sigmaT.b(), tMax);
    }
}
