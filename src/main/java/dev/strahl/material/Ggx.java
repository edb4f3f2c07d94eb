package dev.strahl.material;

import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * The isotropic GGX (Trowbridge–Reitz) distribution of microfacet normals and its Smith masking,
 * with sampling of the visible normals. α is the roughness (the glTF and Mitsuba α: glTF's
 * α = roughness²); α → 0 is a mirror. Static functions of the local frame (z = n).
 *
 * <ul>
 *   <li>D(m) = α² / (π (cos²θm (α² − 1) + 1)²) for a unit m above the surface, 0 below; normalised so
 *       that ∫ D(m) cosθm dωm = 1 (Walter et al., "Microfacet Models for Refraction through Rough
 *       Surfaces", EGSR 2007, eq. 33).</li>
 *   <li>Λ(v) = (√(1 + α² tan²θv) − 1) / 2 and G1(v) = 1 / (1 + Λ(v)) (Walter et al. 2007, eq. 34;
 *       Heitz 2014, "Understanding the Masking-Shadowing Function"); the BSDFs use the separable
 *       G(wo, wi) = G1(wo) G1(wi), as Mitsuba 3 and the glTF 2.0 specification's V_GGX do.</li>
 *   <li>Visible normals: m is drawn from D_wo(m) = G1(wo) max(0, wo·m) D(m) / cosθo by Heitz's
 *       method ("Sampling the GGX Distribution of Visible Normals", JCGT 7(4), 2018): stretch wo to
 *       the hemisphere configuration, sample a projected disk warped towards wo, unstretch.</li>
 * </ul>
 * For a wo below the surface, the functions use −wo (the distribution is symmetric), as pbrt-v4 does.
 */
final class Ggx {
    /** Smallest α the rough BSDFs use: below it D overflows to infinity in double precision near m = n. */
    static final double MIN_ALPHA = 1e-4;

    private Ggx() {}

    /** D(m) for a unit microfacet normal m (its z component suffices). */
    static double d(double mz, double alpha) {
        if (!(mz > 0)) {
            return 0;
        }
        double a2 = alpha * alpha;
        double cos2 = mz * mz;
        double t = cos2 * (a2 - 1) + 1;
        return a2 / (Math.PI * t * t);
    }

    /** Λ(v) for a unit direction v (either hemisphere: |cosθ| is used). */
    static double lambda(Vector3dc v, double alpha) {
        double cos2 = v.z() * v.z();
        double sin2 = Math.max(0, 1 - cos2);
        if (sin2 == 0) {
            return 0;
        }
        if (cos2 == 0) {
            return Double.POSITIVE_INFINITY;
        }
        double alpha2Tan2 = alpha * alpha * sin2 / cos2;
        return (Math.sqrt(1 + alpha2Tan2) - 1) / 2;
    }

    /** G1(v) = 1 / (1 + Λ(v)). */
    static double g1(Vector3dc v, double alpha) {
        return 1 / (1 + lambda(v, alpha));
    }

    /** The separable Smith G(wo, wi) = G1(wo) G1(wi). */
    static double g(Vector3dc wo, Vector3dc wi, double alpha) {
        return g1(wo, alpha) * g1(wi, alpha);
    }

    /**
     * The density of visible normals D_wo(m) = G1(wo) |wo·m| D(m) / |cosθo| for a unit m above the
     * surface (the density {@link #sampleVisible} draws m with).
     */
    static double visiblePdf(Vector3dc wo, double mx, double my, double mz, double alpha) {
        double cosO = Math.abs(wo.z());
        if (cosO == 0) {
            return 0;
        }
        double dot = Math.abs(wo.x() * mx + wo.y() * my + wo.z() * mz);
        return g1(wo, alpha) * dot * d(mz, alpha) / cosO;
    }

    /**
     * A microfacet normal m (unit, above the surface) from the visible normals seen from wo (or −wo
     * if wo is below), Heitz 2018, into {@code dest}.
     */
    static Vector3d sampleVisible(Vector3dc wo, double alpha, double u1, double u2, Vector3d dest) {
        double sign = wo.z() < 0 ? -1 : 1;
        // Stretch: the view direction in the configuration where α = 1.
        double vx = alpha * wo.x() * sign, vy = alpha * wo.y() * sign, vz = wo.z() * sign;
        double len = Math.sqrt(vx * vx + vy * vy + vz * vz);
        vx /= len;
        vy /= len;
        vz /= len;
        // An orthonormal basis (T1, T2, V) around the stretched view direction.
        double lensq = vx * vx + vy * vy;
        double t1x, t1y, t1z;
        if (lensq > 0) {
            double inv = 1 / Math.sqrt(lensq);
            t1x = -vy * inv;
            t1y = vx * inv;
            t1z = 0;
        } else {
            t1x = 1;
            t1y = 0;
            t1z = 0;
        }
        double t2x = vy * t1z - vz * t1y, t2y = vz * t1x - vx * t1z, t2z = vx * t1y - vy * t1x;
        // A point on the disk, its upper half squeezed towards the part of the hemisphere V sees.
        double r = Math.sqrt(u1);
        double phi = 2 * Math.PI * u2;
        double p1 = r * Math.cos(phi);
        double p2 = r * Math.sin(phi);
        double s = 0.5 * (1 + vz);
        p2 = (1 - s) * Math.sqrt(Math.max(0, 1 - p1 * p1)) + s * p2;
        double p3 = Math.sqrt(Math.max(0, 1 - p1 * p1 - p2 * p2));
        double nx = p1 * t1x + p2 * t2x + p3 * vx;
        double ny = p1 * t1y + p2 * t2y + p3 * vy;
        double nz = p1 * t1z + p2 * t2z + p3 * vz;
        // Unstretch.
        dest.set(alpha * nx, alpha * ny, Math.max(1e-12, nz));
        return dest.normalize();
    }
}
