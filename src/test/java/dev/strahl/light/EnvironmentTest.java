package dev.strahl.light;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import dev.strahl.testing.ChiSquare;
import java.util.SplittableRandom;
import org.joml.Vector2d;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The environment: Mitsuba's orientation and texel placement, the rotation, and the importance
 * sampling of a map (chi-square against its pdf, the pdf integrating to one, a small sun).
 */
class EnvironmentTest {
    private static final double ALPHA = ChiSquare.sidak(0.01, 3);

    /** A W×H map whose texel (x, y) has radiance (x, y, 1): where a direction lands can be read off. */
    static Environment labelled(int w, int h, double rotate) {
        float[] rgb = new float[3 * w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                rgb[3 * (y * w + x)] = x;
                rgb[3 * (y * w + x) + 1] = y;
                rgb[3 * (y * w + x) + 2] = 1;
            }
        }
        return Environment.map(w, h, rgb, 1, rotate, "labelled");
    }

    static MutableRgb eval(Environment env, double x, double y, double z) {
        return env.eval(new Vector3d(x, y, z).normalize(), new MutableRgb());
    }

    @Test
    void theAxesSeeTheColumnsMitsubaSees() {
        // 8 columns: texel x sits at u = (x + ½)/8, so u = ½ (+Z) lies between columns 3 and 4, u = ¼
        // (+X) between 1 and 2, u = ¾ (−X) between 5 and 6, u = 0 (−Z) between 7 and 0 (wrapping).
        Environment env = labelled(8, 5, 0);
        assertThat(eval(env, 0, 0, 1).r).isCloseTo(3.5, within(1e-9));
        assertThat(eval(env, 1, 0, 0).r).isCloseTo(1.5, within(1e-9));
        assertThat(eval(env, -1, 0, 0).r).isCloseTo(5.5, within(1e-9));
        assertThat(eval(env, 0, 0, -1).r).isCloseTo(3.5, within(1e-9));       // halfway between 7 and 0
        // rows at v = y/(H − 1): the top row is +Y, the bottom row −Y, the horizon the middle row
        assertThat(eval(env, 0, 1, 0).g).isCloseTo(0, within(1e-9));
        assertThat(eval(env, 0, -1, 0).g).isCloseTo(4, within(1e-9));
        assertThat(eval(env, 0, 0, 1).g).isCloseTo(2, within(1e-9));
        assertThat(eval(env, 1, 1, 0).g).isCloseTo(1, within(1e-9));           // 45° up: v = ¼
    }

    @Test
    void rotationTurnsTheMapRightHandedAboutY() {
        // Turned by +90° about +Y, what the unturned map shows along +Z is seen along +X.
        Environment plain = labelled(8, 5, 0), turned = labelled(8, 5, 90);
        assertThat(eval(turned, 1, 0.3, 0).r).isCloseTo(eval(plain, 0, 0.3, 1).r, within(1e-9));
        assertThat(eval(turned, 0, 0.3, -1).r).isCloseTo(eval(plain, 1, 0.3, 0).r, within(1e-9));
    }

    @Test
    void constantIsTheSameEverywhereAndBlackIsBlack() {
        Environment c = Environment.constant(new Rgb(1, 2, 3));
        assertThat(eval(c, 0.3, -0.2, 0.9).g).isEqualTo(2);
        assertThat(c.isConstant()).isTrue();
        assertThat(c.power()).isCloseTo(2 * 4 * Math.PI, within(1e-12));
        assertThat(Environment.constant(Rgb.BLACK).isBlack()).isTrue();
        assertThat(Environment.map(2, 2, new float[12], 1, 0, "black").isBlack()).isTrue();
    }

    @Test
    void refusesMapsItCannotPlace() {
        assertThatThrownBy(() -> Environment.map(4, 1, new float[12], 1, 0, "flat")).hasMessageContaining("1x2");
        assertThatThrownBy(() -> Environment.map(2, 2, new float[12], Double.NaN, 0, "x")).hasMessageContaining("scale");
    }

    /** A map with a sky gradient and a small bright sun: what importance sampling is for. */
    static Environment sunny(double rotate) {
        int w = 64, h = 32;
        float[] rgb = new float[3 * w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double sky = y < h / 2 ? 0.2 + 0.02 * y : 0.05;
                boolean sun = x == 20 && y == 9;
                for (int c = 0; c < 3; c++) {
                    rgb[3 * (y * w + x) + c] = (float) (sun ? 500 : sky * (1 + 0.3 * c) * (1 + 0.5 * Math.sin(x * 0.3)));
                }
            }
        }
        return Environment.map(w, h, rgb, 1, rotate, "sunny");
    }

    /**
     * The chi-square test runs in the map's own (u, v) square, where the density is bounded:
     * p(u, v) = pdf(ω) · 2π² sin θ. On the sphere, pdf(ω) grows like 1/sin θ at the poles (as in
     * any latitude–longitude sampling), which the test's quadrature of the expected counts cannot
     * integrate; the change of variables is exact, so nothing is lost.
     */
    @Test
    void samplingFollowsItsPdf() {
        for (double rotate : new double[] {0, 37}) {
            Environment env = sunny(rotate);
            double[] uv = new double[2];
            MutableRgb radiance = new MutableRgb();
            Vector3d w = new Vector3d();
            ChiSquare.test2d((u1, u2, dest) -> {
                if (!(env.sample(u1, u2, uv, w, radiance) > 0)) {
                    return false;
                }
                toUv(w, rotate, dest);
                return true;
            }, (u, v) -> uvPdf(env, rotate, u, v), cells(64), 64, 31, 2_000_000, 11).assertAccepted(ALPHA);
        }
    }

    /** The map's (u, v) of a world direction, the map turned by {@code rotate} degrees about +Y. */
    static void toUv(Vector3d w, double rotate, Vector2d dest) {
        double a = Math.toRadians(rotate);
        double x = w.x * Math.cos(a) - w.z * Math.sin(a), z = w.x * Math.sin(a) + w.z * Math.cos(a);
        double u = Math.atan2(x, -z) / (2 * Math.PI);
        dest.set(u < 0 ? u + 1 : u, Math.acos(Math.max(-1, Math.min(1, w.y))) / Math.PI);
    }

    /** The density of {@link Environment#sample} over the map's (u, v): pdf(ω) · 2π² sin θ. */
    static double uvPdf(Environment env, double rotate, double u, double v) {
        double phi = 2 * Math.PI * u, theta = Math.PI * v, a = Math.toRadians(rotate);
        double x = Math.sin(phi) * Math.sin(theta), y = Math.cos(theta), z = -Math.cos(phi) * Math.sin(theta);
        Vector3d w = new Vector3d(x * Math.cos(a) + z * Math.sin(a), y, -x * Math.sin(a) + z * Math.cos(a));
        return env.pdf(w) * 2 * Math.PI * Math.PI * Math.sin(theta);
    }

    /**
     * The map's (u, v) square charted so that the sampling distribution's cells, which run between
     * texel centres (u from (i + ½)/W, v from j/(H − 1)), fall exactly on the chart's bins of a
     * W × (H − 1) grid: s = u − ½/W (wrapping), t = v. The density jumps only on bin edges then,
     * which the expected counts' quadrature integrates exactly.
     */
    static ChiSquare.Chart cells(int width) {
        double half = 0.5 / width;
        return new ChiSquare.Chart() {
            @Override
            public boolean toChart(double u, double v, Vector2d dest) {
                double s = u - half;
                dest.set(s < 0 ? s + 1 : s, v);
                return u >= 0 && u <= 1 && v >= 0 && v <= 1;
            }

            @Override
            public double fromChart(double s, double t, Vector2d dest) {
                double u = s + half;
                dest.set(u >= 1 ? u - 1 : u, t);
                return 1;
            }
        };
    }

    @Test
    void samplingReturnsThePdfAndRadianceOfItsDirection() {
        Environment env = sunny(20);
        double[] uv = new double[2];
        MutableRgb radiance = new MutableRgb();
        Vector3d wi = new Vector3d();
        SplittableRandom random = new SplittableRandom(3);
        for (int i = 0; i < 10_000; i++) {
            double pdf = env.sample(random.nextDouble(), random.nextDouble(), uv, wi, radiance);
            assertThat(pdf).isPositive();
            assertThat(wi.length()).isCloseTo(1, within(1e-12));
            assertThat(env.pdf(wi)).isCloseTo(pdf, within(1e-6 * pdf));
            MutableRgb direct = env.eval(wi, new MutableRgb());
            assertThat(direct.r).isCloseTo(radiance.r, within(1e-5 * (1 + radiance.r)));
        }
    }

    @Test
    void pdfIntegratesToOne() {
        Environment sunny = sunny(0), labelled = labelled(16, 9, 10);
        assertThat(integrateOverCells(sunny, 0, 64, 32)).isCloseTo(1, within(1e-6));
        assertThat(integrateOverCells(labelled, 10, 16, 9)).isCloseTo(1, within(1e-6));
    }

    /** ∫ p(u, v) du dv by the midpoint rule on each sampling cell (exact: p is constant on each). */
    static double integrateOverCells(Environment env, double rotate, int width, int height) {
        ChiSquare.Chart chart = cells(width);
        Vector2d p = new Vector2d();
        double sum = 0;
        for (int j = 0; j < height - 1; j++) {
            for (int i = 0; i < width; i++) {
                chart.fromChart((i + 0.5) / width, (j + 0.5) / (height - 1), p);
                sum += uvPdf(env, rotate, p.x, p.y) / (width * (height - 1.0));
            }
        }
        return sum;
    }

    /**
     * A small sun must not make fireflies: the estimate of the irradiance of an upward surface,
     * E = ∫ L cos⁺ dω, by light sampling alone, has a relative standard deviation per sample that
     * stays below 1.5, and more than five times below that of uniform sphere sampling of the same map.
     */
    @Test
    void aSmallSunIsFoundBySamplingNotByLuck() {
        Environment env = sunny(0);
        double[] uv = new double[2];
        MutableRgb radiance = new MutableRgb();
        Vector3d wi = new Vector3d();
        SplittableRandom random = new SplittableRandom(5);
        int n = 200_000;
        double sum = 0, sum2 = 0, sumU = 0, sumU2 = 0;
        for (int i = 0; i < n; i++) {
            double pdf = env.sample(random.nextDouble(), random.nextDouble(), uv, wi, radiance);
            double f = pdf > 0 ? radiance.g * Math.max(0, wi.y) / pdf : 0;
            sum += f;
            sum2 += f * f;
            wi.set(random.nextDouble() * 2 - 1, 0, 0);
            double z = wi.x, r = Math.sqrt(1 - z * z), phi = 2 * Math.PI * random.nextDouble();
            wi.set(r * Math.cos(phi), z, r * Math.sin(phi));
            double g = env.eval(wi, radiance).g * Math.max(0, wi.y) * 4 * Math.PI;
            sumU += g;
            sumU2 += g * g;
        }
        double mean = sum / n, sd = Math.sqrt(sum2 / n - mean * mean);
        double meanU = sumU / n, sdU = Math.sqrt(sumU2 / n - meanU * meanU);
        assertThat(mean).isCloseTo(meanU, within(0.05 * meanU));          // the same irradiance
        assertThat(sd / mean).isLessThan(1.5);
        assertThat(sdU / meanU).isGreaterThan(5 * sd / mean);
    }
}
