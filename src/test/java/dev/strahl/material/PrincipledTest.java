package dev.strahl.material;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import dev.strahl.testing.BsdfAssert;
import dev.strahl.testing.ChiSquare;
import dev.strahl.texture.TextureLookup;
import java.util.List;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The glTF metallic–roughness BRDF: the formula of the specification's Appendix B at chosen points,
 * sampling against pdf (chi-square), weight = f·cos/pdf, reciprocity, energy ≤ 1 where the model
 * conserves it (metals; specular 0), and the Lambertian limit.
 */
class PrincipledTest {
    private static final double ALPHA = ChiSquare.sidak(0.01, 5 * 3);

    private static Principled material(Rgb base, double metallic, double roughness, double specular, double transmission) {
        return new Principled(TextureLookup.of(base), TextureLookup.of(metallic), TextureLookup.of(roughness), TextureLookup.of(specular), TextureLookup.of(Rgb.WHITE),
                TextureLookup.of(transmission), 1.5);
    }

    private static final List<Principled> CASES = List.of(
            material(new Rgb(0.8, 0.3, 0.1), 0, 0.5, 1, 0),
            material(new Rgb(0.9, 0.7, 0.3), 1, 0.3, 1, 0),
            material(new Rgb(0.5, 0.5, 0.5), 0.5, 0.8, 1, 0),
            material(new Rgb(0.9, 0.9, 0.9), 0, 0.4, 1, 0.8),
            material(new Rgb(0.6, 0.6, 0.6), 0, 1, 0.5, 0));

    @Test
    void samplingMatchesPdf() {
        int i = 0;
        for (Principled p : CASES) {
            int bins = p.roughness().value(0, 0) <= 0.4 ? 80 : 40;
            for (double t : new double[] {10, 50, 80}) {
                BsdfAssert.chiSquare(p, BsdfAssert.direction(t, 40), 1_000_000, 31 + i++, bins, 2 * bins).assertAccepted(ALPHA);
            }
        }
    }

    @Test
    void sampleEvalPdfAgreeAndAreReciprocal() {
        for (Principled p : CASES) {
            for (double t : new double[] {0, 30, 70, 89}) {
                BsdfAssert.assertSampleConsistent(p, BsdfAssert.direction(t, 20), 20_000, 2);
                BsdfAssert.assertPdfCoversEval(p, BsdfAssert.direction(t, 20), 20_000, 3);
            }
            BsdfAssert.assertReciprocal(p, 20_000, 4);
        }
    }

    @Test
    void metalsAndPureDiffuseConserveEnergy() {
        BsdfAssert.assertEnergyAtMostOne(material(Rgb.WHITE, 1, 0.3, 1, 0), 20, 20_000, 5);
        BsdfAssert.assertEnergyAtMostOne(material(Rgb.WHITE, 1, 0.9, 1, 0), 20, 20_000, 6);
        BsdfAssert.assertEnergyAtMostOne(material(Rgb.WHITE, 0, 0.5, 0, 0), 20, 20_000, 7);
        BsdfAssert.assertEnergyAtMostOne(material(new Rgb(0.8, 0.8, 0.8), 0, 0.5, 1, 0), 20, 20_000, 8);
    }

    /** specular = 0 leaves the Lambertian base exactly: f = baseColor/π, and the white furnace gives 1. */
    @Test
    void specularZeroIsLambertian() {
        Principled p = material(new Rgb(0.2, 0.5, 0.9), 0, 0.3, 0, 0);
        MutableRgb f = new MutableRgb();
        p.eval(BsdfAssert.direction(30, 0), BsdfAssert.direction(60, 120), f);
        assertThat(f.r).isCloseTo(0.2 / Math.PI, within(1e-15));
        assertThat(f.b).isCloseTo(0.9 / Math.PI, within(1e-15));
        var e = BsdfAssert.albedoBySampling(material(Rgb.WHITE, 0, 0.3, 0, 0), BsdfAssert.direction(40, 0), 100_000, 3);
        assertThat(e.r()).isCloseTo(1, within(1e-12));
    }

    /** The Appendix B formula at one point, written out independently. */
    @Test
    void matchesTheSpecificationsFormula() {
        Rgb base = new Rgb(0.7, 0.4, 0.2);
        double metallic = 0.3, roughness = 0.6;
        Principled p = material(base, metallic, roughness, 1, 0);
        Vector3d wo = BsdfAssert.direction(35, 0), wi = BsdfAssert.direction(50, 150);
        Vector3d h = new Vector3d(wo).add(wi).normalize();
        double a = roughness * roughness, a2 = a * a;
        double nDotH = h.z, vDotH = wo.dot(h), nDotL = wi.z, nDotV = wo.z;
        double d = a2 / (Math.PI * Math.pow(nDotH * nDotH * (a2 - 1) + 1, 2));
        double v = 1 / ((nDotL + Math.sqrt(a2 + (1 - a2) * nDotL * nDotL)) * (nDotV + Math.sqrt(a2 + (1 - a2) * nDotV * nDotV)));
        double spec = v * d;
        double f0 = 0.04, fr = f0 + (1 - f0) * Math.pow(1 - vDotH, 5);
        double[] c = {base.r(), base.g(), base.b()};
        MutableRgb f = new MutableRgb();
        p.eval(wo, wi, f);
        double[] got = {f.r, f.g, f.b};
        for (int k = 0; k < 3; k++) {
            double dielectric = (1 - fr) * c[k] / Math.PI + fr * spec;
            double metal = spec * (c[k] + (1 - c[k]) * Math.pow(1 - vDotH, 5));
            assertThat(got[k]).as("channel %d", k).isCloseTo((1 - metallic) * dielectric + metallic * metal, within(1e-12));
        }
    }
}
