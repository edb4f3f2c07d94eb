package dev.strahl.material;

import dev.strahl.math.MathUtil;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Reflection and refraction at a smooth interface, in the local frame (z = n). Directions point
 * away from the surface (see the package documentation); {@code eta} is always the relative index
 * η = ηt/ηi of the side z &lt; 0 over the side z &gt; 0 (glass in air: η = 1.5). A direction with
 * z &lt; 0 comes from inside, and the functions then use 1/η, as pbrt-v4 does.
 */
public final class Fresnel {
    private Fresnel() {}

    /**
     * Fresnel reflectance of a smooth dielectric for unpolarised light:
     * F = (r∥² + r⊥²) / 2 with
     * r∥ = (η cosθi − cosθt) / (η cosθi + cosθt),
     * r⊥ = (cosθi − η cosθt) / (cosθi + η cosθt),
     * where sin²θt = sin²θi / η² (Snell's law). If cosθi &lt; 0 the light arrives from the inside:
     * η becomes 1/η and cosθi becomes |cosθi|. Returns 1 on total internal reflection
     * (sin²θt ≥ 1). Source: pbrt-v4, §9.3 (the Fresnel equations), {@code FrDielectric}.
     *
     * @param cosThetaI cosine of the angle between the direction and +z, in [−1, 1]
     * @param eta       ηt/ηi of the side z &lt; 0 over the side z &gt; 0, positive
     */
    public static double dielectric(double cosThetaI, double eta) {
        cosThetaI = MathUtil.clamp(cosThetaI, -1, 1);
        if (cosThetaI < 0) {
            eta = 1 / eta;
            cosThetaI = -cosThetaI;
        }
        double sin2ThetaI = 1 - cosThetaI * cosThetaI;
        double sin2ThetaT = sin2ThetaI / (eta * eta);
        if (sin2ThetaT >= 1) {
            return 1;
        }
        double cosThetaT = MathUtil.safeSqrt(1 - sin2ThetaT);
        double rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
        double rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
        return 0.5 * (rParallel * rParallel + rPerpendicular * rPerpendicular);
    }

    /**
     * Fresnel reflectance of a conductor with complex index η + ik (relative to the outside) for
     * unpolarised light, exact: with sin²θt = sin²θi / (η + ik)² and cosθt = √(1 − sin²θt) (complex,
     * principal root), r∥ = ((η+ik) cosθi − cosθt) / ((η+ik) cosθi + cosθt),
     * r⊥ = (cosθi − (η+ik) cosθt) / (cosθi + (η+ik) cosθt), F = (|r∥|² + |r⊥|²) / 2.
     * Source: pbrt-v4 §9.3.6 ({@code FrComplex}). |cosθi| is used (conductors reflect alike on both sides).
     *
     * @param cosThetaI cosine of the angle of incidence
     * @param eta       real part η &gt; 0
     * @param k         imaginary part (absorption) k ≥ 0
     */
    public static double conductor(double cosThetaI, double eta, double k) {
        double c = Math.min(1, Math.abs(cosThetaI));
        double sin2 = 1 - c * c;
        // (η + ik)² = (η² − k²) + i 2ηk; sin²θt = sin²θi / that.
        double e2r = eta * eta - k * k, e2i = 2 * eta * k;
        double den = e2r * e2r + e2i * e2i;
        double s2r = sin2 * e2r / den, s2i = -sin2 * e2i / den;
        // cosθt = sqrt(1 − sin²θt), complex principal square root.
        double ar = 1 - s2r, ai = -s2i;
        double mod = Math.hypot(ar, ai);
        double ctr = Math.sqrt(Math.max(0, (mod + ar) / 2));
        double cti = Math.copySign(Math.sqrt(Math.max(0, (mod - ar) / 2)), ai);
        // r∥ = (e c − ct) / (e c + ct), e = η + ik
        double ecr = eta * c, eci = k * c;
        double parl = ratioNorm2(ecr - ctr, eci - cti, ecr + ctr, eci + cti);
        // r⊥ = (c − e ct) / (c + e ct)
        double ectr = eta * ctr - k * cti, ecti = eta * cti + k * ctr;
        double perp = ratioNorm2(c - ectr, -ecti, c + ectr, ecti);
        return 0.5 * (parl + perp);
    }

    /** |a / b|² for complex a = (ar, ai), b = (br, bi). */
    private static double ratioNorm2(double ar, double ai, double br, double bi) {
        double nb = br * br + bi * bi;
        return nb == 0 ? 1 : (ar * ar + ai * ai) / nb;
    }

    /**
     * Refraction of {@code wo} through a microfacet with unit normal {@code m} (either side), by
     * Snell's law with ηt/ηi = η on the side m points to and 1/η on the other, as {@link #refract}
     * does for m = +z. Writes the refracted direction into {@code dest} and returns the relative
     * index η' used (η entering, 1/η leaving), or 0 on total internal reflection.
     */
    static double refract(Vector3dc wo, double mx, double my, double mz, double eta, Vector3d dest) {
        double cosI = wo.x() * mx + wo.y() * my + wo.z() * mz;
        double e = eta;
        if (cosI < 0) {
            e = 1 / eta;
            cosI = -cosI;
            mx = -mx;
            my = -my;
            mz = -mz;
        }
        double sin2T = Math.max(0, 1 - cosI * cosI) / (e * e);
        if (sin2T >= 1) {
            return 0;
        }
        double cosT = Math.sqrt(1 - sin2T);
        double a = cosI / e - cosT;
        dest.set(-wo.x() / e + a * mx, -wo.y() / e + a * my, -wo.z() / e + a * mz);
        return e;
    }

    /**
     * Mirror direction about the normal z: (−w.x, −w.y, w.z), the local form of
     * wr = 2 (n·w) n − w. Writes into and returns {@code dest} (which may be {@code w}).
     */
    public static Vector3d reflect(Vector3dc w, Vector3d dest) {
        return dest.set(-w.x(), -w.y(), w.z());
    }

    /**
     * Refracted direction by Snell's law (ηi sinθi = ηt sinθt):
     * wt = −wi/η + (cosθi/η − cosθt) n, with cosθt = sqrt(1 − sin²θi/η²), where n = +z and η as
     * given if wi.z &gt; 0, and n = −z, η → 1/η if wi comes from inside (wi.z &lt; 0). The result
     * is a unit vector on the other side. Source: pbrt-v4, §9.3 (Snell's law), {@code Refract}.
     *
     * @param wi  unit direction away from the surface on the incident side
     * @param eta ηt/ηi of the side z &lt; 0 over the side z &gt; 0
     * @return false (and {@code dest} untouched) on total internal reflection
     */
    public static boolean refract(Vector3dc wi, double eta, Vector3d dest) {
        double cosThetaI = wi.z();
        double nz = 1;
        if (cosThetaI < 0) {
            eta = 1 / eta;
            cosThetaI = -cosThetaI;
            nz = -1;
        }
        double sin2ThetaI = Math.max(0, 1 - cosThetaI * cosThetaI);
        double sin2ThetaT = sin2ThetaI / (eta * eta);
        if (sin2ThetaT >= 1) {
            return false;
        }
        double cosThetaT = MathUtil.safeSqrt(1 - sin2ThetaT);
        double invEta = 1 / eta;
        dest.set(-wi.x() * invEta, -wi.y() * invEta, -wi.z() * invEta + (cosThetaI * invEta - cosThetaT) * nz);
        return true;
    }

    /**
     * The relative index ηt/ηi that {@link #refract} uses for a direction with the given cosθ:
     * η on the outside (cosθ ≥ 0, refracting inwards), 1/η on the inside (refracting outwards).
     */
    public static double relativeEta(double cosTheta, double eta) {
        return cosTheta >= 0 ? eta : 1 / eta;
    }
}
