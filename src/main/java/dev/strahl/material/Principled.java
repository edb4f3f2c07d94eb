package dev.strahl.material;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import dev.strahl.sampling.Warp;
import dev.strahl.texture.TextureLookup;
import java.util.Objects;
import org.joml.Vector2dc;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * The glTF 2.0 metallic–roughness material as the glTF 2.0 specification's Appendix B defines it,
 * with the parameters of KHR_materials_specular and KHR_materials_transmission (thin-walled: without
 * KHR_materials_volume a transmitted ray keeps its direction through the surface). Every parameter
 * is a texture. With α = roughness², h = normalize(wo + wi), VdotH = wo·h, and the GGX lobe
 * S(wo, wi) = D(h) G1(wo) G1(wi) / (4 cosθo cosθi) (the specification's V_GGX · D_GGX, {@link Ggx}):
 * <pre>
 *   f         = (1 − metallic) · dielectric + metallic · metal
 *   metal     = S · (baseColor + (1 − baseColor) (1 − VdotH)⁵)                (conductor_fresnel)
 *   dielectric = (1 − specular · max(fr)) · base + specular · fr · S          (fresnel_mix)
 *   fr        = f0 + (1 − f0) (1 − VdotH)⁵,  f0 = min(((ior − 1)/(ior + 1))² · specularColor, 1)
 *   base      = (1 − transmission) · baseColor/π + transmission · baseColor · S(wo, wi')
 * </pre>
 * where the transmission lobe is the specular lobe with wi mirrored through the surface
 * (wi' = (wi.x, wi.y, −wi.z), for wi below; its fr uses that lobe's half vector). With specular = 0
 * the dielectric is a pure Lambertian base. The model is the specification's, not an
 * energy-conserving one: its dielectric mix can reflect slightly more than it receives at grazing
 * angles (see the tests). Two-sided.
 *
 * <p><b>Sampling.</b> One of three lobes by {@code uc}, with probabilities proportional to
 * estimates of their albedos at wo (Schlick's term at cosθo for the specular part), each lobe
 * kept above a small floor wherever it can be non-zero: the diffuse lobe cosine-weighted, the
 * specular lobe by visible normals ({@link Ggx#sampleVisible}) and reflection, the transmission lobe
 * likewise and then mirrored below. pdf is the mixture of the three densities.
 *
 * @param baseColor     baseColor, linear RGB in [0, 1]
 * @param metallic      metallic in [0, 1]
 * @param roughness     perceptual roughness in [0, 1] (α = roughness²)
 * @param specular      KHR_materials_specular's specularFactor in [0, 1] (1 by default)
 * @param specularColor KHR_materials_specular's specularColorFactor (white by default)
 * @param transmission  KHR_materials_transmission's transmissionFactor in [0, 1]
 * @param ior           index of refraction (1.5 by default), positive
 */
public record Principled(TextureLookup baseColor, TextureLookup metallic, TextureLookup roughness, TextureLookup specular, TextureLookup specularColor,
                         TextureLookup transmission, double ior) implements Bsdf {
    private static final double INV_PI = 1 / Math.PI;
    /** Smallest probability of a lobe that may be non-zero. */
    private static final double FLOOR = 0.05;

    /** Checks that every parameter has its texture (a constant or an image) and the index of refraction. */
    public Principled {
        for (TextureLookup parameter : new TextureLookup[] {baseColor, metallic, roughness, specular, specularColor, transmission}) {
            Objects.requireNonNull(parameter, "a principled parameter without texture");
        }
        if (!(ior > 0) || !Double.isFinite(ior)) {
            throw new IllegalArgumentException("index of refraction must be a positive finite number, got " + ior);
        }
    }

    /** A glTF material with the default extension parameters: white specular, no transmission, ior 1.5. */
    public static Principled of(Rgb baseColor, double metallic, double roughness) {
        return new Principled(TextureLookup.of(baseColor), TextureLookup.of(metallic), TextureLookup.of(roughness), TextureLookup.of(1), TextureLookup.of(Rgb.WHITE),
                TextureLookup.of(0), 1.5);
    }

    private double f0Ior() {
        double r = (ior - 1) / (ior + 1);
        return r * r;
    }

    /**
     * The probability of lobe {@code which} (0 diffuse, 1 specular, 2 transmission) at (uv, wo),
     * from estimates of the lobes' albedos (the colour textures' scalar values: their mean or
     * luminance); all three 0 where the surface is black.
     */
    private double lobe(Vector2dc uv, double cosO, int which) {
        double u = uv.x(), v = uv.y();
        double m = clamp01(metallic.value(u, v)), s = clamp01(specular.value(u, v)), t = clamp01(transmission.value(u, v));
        double base = clamp01(baseColor.value(u, v));
        double schlick = pow5(1 - cosO);
        double metalF = base + (1 - base) * schlick;
        double f0 = Math.min(1, f0Ior() * specularColor.value(u, v));
        double fd = s * (f0 + (1 - f0) * schlick);
        double wSpec = (1 - m) * fd + m * metalF;
        double wDiff = (1 - m) * (1 - fd) * (1 - t) * base;
        double wTr = (1 - m) * (1 - fd) * t * base;
        if ((1 - m) * s > 0 || m > 0) {
            wSpec = Math.max(wSpec, FLOOR);
        }
        double sum = wSpec + wDiff + wTr;
        if (!(sum > 0)) {
            return 0;
        }
        return (which == 0 ? wDiff : which == 1 ? wSpec : wTr) / sum;
    }

    /**
     * f(wo, wi); for wo below the surface the mirror image of the pair (both z negated), so that the
     * two-sided BSDF is reciprocal for every pair (the integrator only asks with wo above).
     */
    @Override
    public void eval(Vector2dc uv, Vector3dc wo, Vector3dc wi, MutableRgb dest) {
        double side = wo.z() < 0 ? -1 : 1;
        double cosO = side * wo.z(), cosI = side * wi.z();
        if (!(cosO > 0) || cosI == 0) {
            dest.setZero();
            return;
        }
        double u = uv.x(), v = uv.y();
        double m = clamp01(metallic.value(u, v)), s = clamp01(specular.value(u, v)), t = clamp01(transmission.value(u, v));
        double r = clamp01(roughness.value(u, v));
        double a = Math.max(Ggx.MIN_ALPHA, r * r);
        boolean transmit = cosI < 0;
        double ix = wi.x(), iy = wi.y(), iz = Math.abs(cosI);
        double hx = wo.x() + ix, hy = wo.y() + iy, hz = cosO + iz;
        double len = Math.sqrt(hx * hx + hy * hy + hz * hz);
        double vDotH = (wo.x() * hx + wo.y() * hy + cosO * hz) / len;
        double lobe = Ggx.d(hz / len, a) * Ggx.g1(wo, a) * Ggx.g1(wi, a) / (4 * cosO * iz);    // G1 uses |cosθ|: either side
        double schlick = pow5(1 - Math.max(0, vDotH));
        specularColor.rgb(u, v, dest);
        double f0 = f0Ior();
        double f0r = Math.min(1, f0 * dest.r), f0g = Math.min(1, f0 * dest.g), f0b = Math.min(1, f0 * dest.b);
        double frr = f0r + (1 - f0r) * schlick, frg = f0g + (1 - f0g) * schlick, frb = f0b + (1 - f0b) * schlick;
        double keep = 1 - s * Math.max(frr, Math.max(frg, frb));
        baseColor.rgb(u, v, dest);
        double br = dest.r, bg = dest.g, bb = dest.b;
        if (transmit) {
            double w = (1 - m) * keep * t * lobe;
            dest.set(w * br, w * bg, w * bb);
            return;
        }
        double diffuse = (1 - m) * keep * (1 - t) * INV_PI;
        double ds = (1 - m) * s * lobe, ms = m * lobe;
        dest.set(diffuse * br + ds * frr + ms * (br + (1 - br) * schlick),
                diffuse * bg + ds * frg + ms * (bg + (1 - bg) * schlick),
                diffuse * bb + ds * frb + ms * (bb + (1 - bb) * schlick));
    }

    @Override
    public double pdf(Vector2dc uv, Vector3dc wo, Vector3dc wi) {
        double cosO = wo.z(), cosI = wi.z();
        if (!(cosO > 0) || cosI == 0) {
            return 0;
        }
        double r = clamp01(roughness.value(uv.x(), uv.y()));
        double a = Math.max(Ggx.MIN_ALPHA, r * r);
        double iz = Math.abs(cosI);
        double hx = wo.x() + wi.x(), hy = wo.y() + wi.y(), hz = cosO + iz;
        double len = Math.sqrt(hx * hx + hy * hy + hz * hz);
        hx /= len;
        hy /= len;
        hz /= len;
        double woDotH = wo.x() * hx + wo.y() * hy + cosO * hz;
        double specular = woDotH > 0 ? Ggx.visiblePdf(wo, hx, hy, hz, a) / (4 * woDotH) : 0;
        if (cosI < 0) {
            return specular > 0 ? lobe(uv, cosO, 2) * specular : 0;
        }
        return lobe(uv, cosO, 0) * Warp.cosineHemispherePdf(cosI) + (specular > 0 ? lobe(uv, cosO, 1) * specular : 0);
    }

    @Override
    public boolean sample(Vector2dc uv, Vector3dc wo, double uc, double u1, double u2, BsdfSample out) {
        double cosO = wo.z();
        if (!(cosO > 0)) {
            return false;
        }
        double pDiffuse = lobe(uv, cosO, 0), pSpecular = lobe(uv, cosO, 1);
        if (!(pDiffuse + pSpecular + lobe(uv, cosO, 2) > 0)) {
            return false;
        }
        if (uc < pDiffuse) {
            Warp.cosineHemisphere(u1, u2, out.wi);
        } else {
            double r = clamp01(roughness.value(uv.x(), uv.y()));
            double a = Math.max(Ggx.MIN_ALPHA, r * r);
            Vector3d m = Ggx.sampleVisible(wo, a, u1, u2, out.wi);
            double mx = m.x, my = m.y, mz = m.z;
            double d = wo.x() * mx + wo.y() * my + cosO * mz;
            out.wi.set(2 * d * mx - wo.x(), 2 * d * my - wo.y(), 2 * d * mz - cosO).normalize();
            if (!(out.wi.z > 0)) {
                return false;
            }
            if (uc >= pDiffuse + pSpecular) {
                out.wi.z = -out.wi.z;
            }
        }
        out.delta = false;
        out.eta = 1;
        return weighByPdf(uv, wo, out);
    }

    private static double clamp01(double x) {
        return x < 0 ? 0 : x > 1 ? 1 : x;
    }

    private static double pow5(double x) {
        double x2 = x * x;
        return x2 * x2 * x;
    }

    /** The base colour at uv: the colour of the diffuse base and the tint of a metal alike. */
    @Override
    public void albedo(Vector2dc uv, Vector3dc wo, MutableRgb dest) {
        baseColor.rgb(uv.x(), uv.y(), dest);
    }
}
