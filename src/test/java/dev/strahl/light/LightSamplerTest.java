package dev.strahl.light;

import dev.strahl.testing.MeshGeometry;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.Sphere;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.image.Rgb;
import dev.strahl.testing.ChiSquare;
import java.util.SplittableRandom;
import org.joml.Vector3d;
import org.joml.Vector3dc;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Light selection, the solid-angle density of light sampling seen from a point, one-sidedness and
 * the degenerate cases of {@link LightSampler}.
 *
 * <p>The scene: a reference point at the origin under four emissive triangles of different areas
 * and radiances, three facing it (normal −z) and overlapping in direction (one light seen through
 * another: the density of a direction is the sum over the lights on its ray), one facing away (its
 * samples must all fail), and one non-emissive triangle among them (never sampled).
 */
class LightSamplerTest {
    /** Chi-square tests in this class; together they keep a 1 % false-alarm level. */
    private static final double ALPHA = ChiSquare.sidak(0.01, 4);

    private static final Rgb[] EMISSION = {
        Rgb.BLACK,                  // 0: not a light
        new Rgb(4, 4, 4),           // 1: mean 4
        new Rgb(1, 2, 6),           // 2: mean 3
        new Rgb(0.5, 0, 1)};        // 3: mean 0.5

    private static final float[] TRIANGLES = {
        -1, -1, 1, -1, 1, 1, 1, -1, 1,                         // A, material 1, z = 1, area 2, faces -z
        -0.3f, -0.3f, 1.5f, -0.3f, 1.5f, 1.5f, 1.5f, -0.3f, 1.5f, // B, material 2, z = 1.5, area 1.62, faces -z, partly behind A
        0.3f, 0.3f, 0.8f, 0.3f, 0.7f, 0.8f, 0.7f, 0.3f, 0.8f,  // C, material 3, z = 0.8, area 0.08, faces -z, in front of B
        -0.8f, 0.4f, 1.2f, -0.4f, 0.4f, 1.2f, -0.8f, 0.8f, 1.2f, // D, material 1, z = 1.2, area 0.08, faces +z (away from the origin)
        0.5f, 0.5f, 1.1f, 0.5f, 0.9f, 1.1f, 0.9f, 0.5f, 1.1f}; // E, material 0, not a light
    private static final int[] MATERIALS = {1, 2, 3, 1, 0};
    /** Areas and mean radiances of A..E, worked out by hand. */
    private static final double[] AREA = {2, 1.62, 0.08, 0.08, 0.08};
    private static final double[] MEAN_LE = {4, 3, 0.5, 4, 0};
    private static final int FACING_AWAY = 3;

    private static final Vector3dc ORIGIN = new Vector3d();

    private static Geometry triangles(MeshGeometry builder) {
        int[] idx = new int[TRIANGLES.length / 3];
        for (int i = 0; i < idx.length; i++) {
            idx[i] = i;
        }
        return builder.addMesh(new TriangleMesh(TRIANGLES, idx, null), MATERIALS, false).build();
    }

    private static Geometry scene() {
        return triangles(new MeshGeometry());
    }

    private static double totalPower() {
        double sum = 0;
        for (int i = 0; i < AREA.length; i++) {
            sum += AREA[i] * MEAN_LE[i];
        }
        return sum;
    }

    // ---------------------------------------------------------------------------------------------
    // Power and selection

    @Test
    void totalPowerIsTheSumOfAreaTimesMeanRadiance() {
        LightSampler lights = areaLights(scene(), EMISSION);
        assertThat(lights.totalPower()).isCloseTo(totalPower(), within(1e-6));
        assertThat(lights.lightCount()).as("A, B, C, D; not E").isEqualTo(4);
        assertThat(lights.isEmpty()).isFalse();

        Geometry withSphere = triangles(new MeshGeometry().addSphere(new Vector3d(0, 0, -3), 0.3, 2));
        LightSampler all = areaLights(withSphere, EMISSION);
        assertThat(all.totalPower()).isCloseTo(totalPower() + 4 * Math.PI * 0.09 * 3, within(1e-6));
        assertThat(all.lightCount()).isEqualTo(5);
    }

    /**
     * With stratified uLight = (i + ½)/n every light is chosen n·p ± 1 times, p = area·mean(Le) /
     * total power; the sphere (material 2, radius 0.3) included. The chosen primitive is read from
     * the scratch surface record, which {@code sample} fills before it tests the facing.
     */
    @Test
    void selectsLightsInProportionToAreaTimesMeanRadiance() {
        Geometry geometry = triangles(new MeshGeometry().addSphere(new Vector3d(0, 0, -3), 0.3, 2));
        LightSampler lights = areaLights(geometry, EMISSION);
        double sphereArea = 4 * Math.PI * 0.09;
        double[] power = {AREA[0] * 4, AREA[1] * 3, AREA[2] * 0.5, AREA[3] * 4, 0, sphereArea * 3};
        double total = totalPower() + sphereArea * 3;
        int n = 200_000;
        int[] count = new int[geometry.primitiveCount()];
        SurfacePoint scratch = new SurfacePoint();
        LightSample out = new LightSample();
        SplittableRandom random = new SplittableRandom(1);
        for (int i = 0; i < n; i++) {
            scratch.prim = -1;
            lights.sample(ORIGIN, null, (i + 0.5) / n, random.nextDouble(), random.nextDouble(), false, scratch, out);
            assertThat(scratch.prim).as("a primitive was chosen").isNotNegative();
            count[scratch.prim]++;
        }
        for (int prim = 0; prim < count.length; prim++) {
            assertThat((double) count[prim]).as("selections of primitive %s", prim).isCloseTo(n * power[prim] / total, within(1.0 + 1e-6));
        }
        assertThat(count[4]).as("the non-emissive triangle").isZero();
    }

    // ---------------------------------------------------------------------------------------------
    // The solid-angle density

    /**
     * Density of the directions {@code sample} produces at {@code ref}, per unit solid angle: the
     * sum of {@code pdf(material, distance, cosLight)} over every primitive the ray from ref meets
     * (a point of any of them may be chosen, whatever lies in front), cosLight = −ng·w. One-sided
     * and non-emissive primitives contribute 0 through {@code pdf} itself.
     */
    private static double directionPdf(LightSampler lights, Geometry geometry, Vector3dc ref, Vector3dc n, Vector3dc w) {
        Ray ray = new Ray();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        double sum = 0;
        for (int prim = 0; prim < geometry.primitiveCount(); prim++) {
            ray.set(ref, w, Double.POSITIVE_INFINITY);
            if (geometry.intersect(prim, ray, hit.reset(), false)) {
                geometry.surface(ray, hit, sp);
                sum += lights.pdf(ref, n, hit.prim, hit.t, -sp.ng.dot(w));
            }
        }
        return sum;
    }

    /**
     * {@code sample} as a 2-D direction sampler for the chi-square test: (u1, u2) place the point on
     * the light and uLight, which picks the light, is drawn inside the lambda from its own seeded
     * stream. The three numbers are independent uniforms, so the directions follow the 3-D →
     * direction map of {@code sample} exactly as the integrator uses it.
     */
    private static ChiSquare.DirectionSampler asDirectionSampler(LightSampler lights, Vector3dc ref, Vector3dc n, long seed) {
        SplittableRandom lightChoice = new SplittableRandom(seed);
        SurfacePoint scratch = new SurfacePoint();
        LightSample out = new LightSample();
        return (u1, u2, dest) -> {
            if (!lights.sample(ref, n, lightChoice.nextDouble(), u1, u2, false, scratch, out)) {
                return false;
            }
            dest.set(out.wi);
            return true;
        };
    }

    private static final int S_BINS = 16, T_BINS = 48, QUADRATURE = 24;
    /** The cap of directions the chi-square test bins: every light of the scene lies within w.z ≥ 1/√3. */
    private static final double Z_MIN = 0.5;

    /**
     * ∫ pdf dω over each equal-area cell (cosθ, φ) of the cap cosθ = w.z ≥ {@link #Z_MIN} around +z:
     * {@value #S_BINS} cells in cosθ by {@value #T_BINS} in φ, a {@value #QUADRATURE}² midpoint rule
     * per cell. Not {@link ChiSquare#test}'s Simpson rule: the density jumps at every light's
     * silhouette, and Simpson's alternating weights misjudge a cell cut by such an edge by a few per
     * cent, which a million samples detect.
     */
    private static double[] capMasses(ChiSquare.DirectionPdf pdf) {
        double[] mass = new double[S_BINS * T_BINS];
        Vector3d w = new Vector3d();
        double dOmega = (1 - Z_MIN) * 2 * Math.PI / ((double) S_BINS * QUADRATURE * T_BINS * QUADRATURE);
        for (int a = 0; a < S_BINS; a++) {
            for (int b = 0; b < T_BINS; b++) {
                double sum = 0;
                for (int i = 0; i < QUADRATURE; i++) {
                    double z = 1 - (1 - Z_MIN) * (a + (i + 0.5) / QUADRATURE) / S_BINS;
                    double r = Math.sqrt(Math.max(0, 1 - z * z));
                    for (int j = 0; j < QUADRATURE; j++) {
                        double phi = 2 * Math.PI * (b + (j + 0.5) / QUADRATURE) / T_BINS;
                        sum += pdf.pdf(w.set(r * Math.cos(phi), r * Math.sin(phi), z));
                    }
                }
                mass[a * T_BINS + b] = sum * dOmega;
            }
        }
        return mass;
    }

    private static double sum(double[] values) {
        double s = 0;
        for (double v : values) {
            s += v;
        }
        return s;
    }

    /**
     * Chi-square test of directions from {@code sampler} against {@code pdf} over the cells of
     * {@link #capMasses}. Samples outside the cap fail the test at once (expected count 0); failed
     * samples form one more cell with {@code absorbedProbability}. Cells whose quadrature finds no
     * mass get a floor of 1e-6 expected samples, so that a light edge clipping a cell's corner between
     * the quadrature nodes is pooled with other small cells instead of counted as impossible.
     */
    private static ChiSquare.Result capChiSquare(ChiSquare.DirectionSampler sampler, ChiSquare.DirectionPdf pdf,
                                                 double absorbedProbability, int n, long seed) {
        double[] mass = capMasses(pdf);
        int cells = mass.length, outside = cells, absorbed = cells + 1;
        double[] expected = new double[cells + 2];
        long[] observed = new long[cells + 2];
        for (int c = 0; c < cells; c++) {
            expected[c] = Math.max(n * mass[c], 1e-6);
        }
        expected[absorbed] = n * absorbedProbability;

        Vector3d w = new Vector3d();
        SplittableRandom random = new SplittableRandom(seed);
        for (int i = 0; i < n; i++) {
            if (!sampler.sample(random.nextDouble(), random.nextDouble(), w)) {
                observed[absorbed]++;
                continue;
            }
            assertThat(w.length()).isCloseTo(1, within(1e-9));
            if (w.z < Z_MIN) {
                observed[outside]++;
                continue;
            }
            int a = Math.min(S_BINS - 1, (int) ((1 - w.z) / (1 - Z_MIN) * S_BINS));
            double phi = Math.atan2(w.y, w.x);
            int b = Math.min(T_BINS - 1, (int) ((phi < 0 ? phi + 2 * Math.PI : phi) / (2 * Math.PI) * T_BINS));
            observed[a * T_BINS + b]++;
        }
        return ChiSquare.fromCounts(expected, observed);
    }

    private static double absorbedProbability() {
        return AREA[FACING_AWAY] * MEAN_LE[FACING_AWAY] / totalPower();
    }

    /** The probability of choosing the light facing away from ref (its samples all fail): by power, or the tree's at (ref, n). */
    private static double absorbedProbability(LightSampler lights, Vector3dc ref, Vector3dc n) {
        return lights.usesTree() ? lights.treeSelection().treeProbability(FACING_AWAY, ref, n) : absorbedProbability();
    }

    /** A normal tilted away from the lights' direction, so that the tree's cosine at the shading point matters. */
    private static final Vector3dc TILTED = new Vector3d(0.6, 0, 0.8);

    /**
     * The directions follow the density that {@code pdf} gives a BSDF sample's hit, by power and
     * by the light tree (whose choice depends on the shading point and its normal).
     */
    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void sampledDirectionsFollowTheSolidAnglePdfChiSquare(boolean tree) {
        Geometry geometry = scene();
        LightSampler lights = tree ? new LightSampler(geometry, Emission.constants(EMISSION), Environment.BLACK, java.util.List.of()) : areaLights(geometry, EMISSION);
        capChiSquare(asDirectionSampler(lights, ORIGIN, TILTED, 2), w -> directionPdf(lights, geometry, ORIGIN, TILTED, w),
                absorbedProbability(lights, ORIGIN, TILTED), 1_000_000, 3).assertAccepted(ALPHA);
    }

    /** The density integrates to the probability that a sample succeeds (all but the light facing away). */
    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void solidAnglePdfIntegratesToTheSuccessProbability(boolean tree) {
        Geometry geometry = scene();
        LightSampler lights = tree ? new LightSampler(geometry, Emission.constants(EMISSION), Environment.BLACK, java.util.List.of()) : areaLights(geometry, EMISSION);
        assertThat(sum(capMasses(w -> directionPdf(lights, geometry, ORIGIN, TILTED, w))))
                .isCloseTo(1 - absorbedProbability(lights, ORIGIN, TILTED), within(1e-3));
    }

    /**
     * The test has power: a density that forgets the 1/cosLight of the area-to-solid-angle change
     * (renormalised to the same total, so only its shape is wrong) is rejected with fewer samples.
     */
    @Test
    void chiSquareRejectsADensityWithoutTheLightCosine() {
        Geometry geometry = scene();
        LightSampler lights = areaLights(geometry, EMISSION);
        // Every light faces -z, so cosLight = w.z: pdf·w.z drops the 1/cosLight.
        ChiSquare.DirectionPdf shapeOnly = w -> directionPdf(lights, geometry, ORIGIN, null, w) * w.z();
        double scale = (1 - absorbedProbability()) / sum(capMasses(shapeOnly));
        capChiSquare(asDirectionSampler(lights, ORIGIN, null, 2), w -> scale * shapeOnly.pdf(w), absorbedProbability(), 200_000, 3)
                .assertRejected(ALPHA);
    }

    /**
     * Every field of a successful sample, against values worked out from the scene alone: the
     * direction and distance to the point, the light's normal and radiance, and the density
     * p = (area·mean(Le) / total) · (1/area) · d² / cosLight.
     */
    @Test
    void sampleFieldsAreConsistent() {
        Geometry geometry = scene();
        LightSampler lights = areaLights(geometry, EMISSION);
        SurfacePoint scratch = new SurfacePoint();
        LightSample out = new LightSample();
        SplittableRandom random = new SplittableRandom(4);
        Vector3dc ref = new Vector3d(0.1, -0.2, 0.05);
        int successes = 0;
        for (int i = 0; i < 10_000; i++) {
            if (!lights.sample(ref, null, random.nextDouble(), random.nextDouble(), random.nextDouble(), false, scratch, out)) {
                assertThat(scratch.prim).as("only the light facing away fails").isEqualTo(FACING_AWAY);
                continue;
            }
            successes++;
            int prim = scratch.prim;
            assertThat(prim).isNotEqualTo(FACING_AWAY);
            Vector3d toPoint = new Vector3d(out.p).sub(ref);
            assertThat(out.distance).isCloseTo(toPoint.length(), within(1e-12));
            assertThat(out.wi.distance(toPoint.normalize())).isLessThan(1e-12);
            assertThat(out.ng.distance(0, 0, -1)).as("normal of the light").isLessThan(1e-12);
            assertThat(out.p.z).as("point on the plane of light %s", prim).isCloseTo(TRIANGLES[9 * prim + 2], within(1e-6));
            assertThat(out.radiance.toRgb()).isEqualTo(EMISSION[MATERIALS[prim]]);
            double cosLight = -out.ng.dot(out.wi);
            double expected = AREA[prim] * MEAN_LE[prim] / totalPower() / AREA[prim] * out.distance * out.distance / cosLight;
            assertThat(out.pdf).isCloseTo(expected, within(1e-6 * expected));
            assertThat(lights.pdf(ref, null, prim, out.distance, cosLight)).isEqualTo(out.pdf);
        }
        assertThat(successes).isGreaterThan(9_000);
    }

    // ---------------------------------------------------------------------------------------------
    // One-sidedness

    @Test
    void lightsAreOneSided() {
        float[] a = java.util.Arrays.copyOf(TRIANGLES, 9);
        Geometry geometry = new MeshGeometry().addMesh(new TriangleMesh(a, new int[] {0, 1, 2}, null), new int[] {1}, false).build();
        LightSampler lights = areaLights(geometry, EMISSION);
        SurfacePoint scratch = new SurfacePoint();
        LightSample out = new LightSample();
        SplittableRandom random = new SplittableRandom(5);
        Vector3dc behind = new Vector3d(0.1, 0.1, 2), inFront = new Vector3d(0.1, 0.1, 0);
        for (int i = 0; i < 10_000; i++) {
            double ul = random.nextDouble(), u1 = random.nextDouble(), u2 = random.nextDouble();
            assertThat(lights.sample(behind, null, ul, u1, u2, false, scratch, out)).as("behind the light").isFalse();
            assertThat(lights.sample(inFront, null, ul, u1, u2, false, scratch, out)).as("in front of the light").isTrue();
        }
        assertThat(lights.pdf(inFront, null, 0, 1, -0.5)).isZero();
        assertThat(lights.pdf(inFront, null, 0, 1, 0)).isZero();
        assertThat(lights.pdf(inFront, null, 0, 1, 0.5)).isPositive();
    }

    // ---------------------------------------------------------------------------------------------
    // Spheres

    /**
     * Points on an emissive sphere are uniform by area: the normals of the samples are uniform over
     * the sphere where the point faces the reference point (n_z &gt; r/d = 0.2 for a reference on the
     * axis at distance d = 5r, an edge that coincides with a cell edge of the chi-square chart), and
     * the rest, 60 %, fails as facing away.
     */
    @Test
    void sphereIsSampledUniformlyByArea() {
        Vector3dc center = new Vector3d(1, 2, 3);
        double radius = 0.5;
        Geometry geometry = new MeshGeometry().addSphere(center, radius, 1).build();
        LightSampler lights = areaLights(geometry, EMISSION);
        Vector3dc ref = new Vector3d(center).add(0, 0, 5 * radius);
        SplittableRandom lightChoice = new SplittableRandom(6);
        SurfacePoint scratch = new SurfacePoint();
        LightSample out = new LightSample();
        ChiSquare.DirectionSampler normals = (u1, u2, dest) -> {
            if (!lights.sample(ref, null, lightChoice.nextDouble(), u1, u2, false, scratch, out)) {
                return false;
            }
            // The point and its density as the sole light: d²/(cos·area).
            double area = 4 * Math.PI * radius * radius;
            double cos = -out.ng.dot(out.wi);
            assertThat(out.p.distance(center)).isCloseTo(radius, within(1e-12));
            assertThat(out.pdf).isCloseTo(out.distance * out.distance / (cos * area), within(1e-9 * out.pdf));
            dest.set(out.ng);
            return true;
        };
        ChiSquare.test(normals, n -> n.z() > 0.2 ? 1 / (4 * Math.PI) : 0, 1_000_000, 7).assertAccepted(ALPHA);
        assertThat(lights.totalPower()).isCloseTo(4 * Math.PI * radius * radius * 4, within(1e-12));
    }

    @Test
    void nothingIsSampledFromInsideAnEmissiveSphere() {
        Geometry geometry = new MeshGeometry().addSphere(new Vector3d(), 1, 1).build();
        LightSampler lights = areaLights(geometry, EMISSION);
        SurfacePoint scratch = new SurfacePoint();
        LightSample out = new LightSample();
        SplittableRandom random = new SplittableRandom(8);
        for (int i = 0; i < 1000; i++) {
            assertThat(lights.sample(new Vector3d(0.1, 0.2, -0.3), null, random.nextDouble(), random.nextDouble(), random.nextDouble(), false, scratch, out))
                    .as("every point of the sphere faces away from its inside").isFalse();
        }
    }

    // ---------------------------------------------------------------------------------------------
    // No lights

    @Test
    void emptySamplerSamplesNothing() {
        float[] e = java.util.Arrays.copyOfRange(TRIANGLES, 36, 45);
        Geometry dark = new MeshGeometry().addMesh(new TriangleMesh(e, new int[] {0, 1, 2}, null), new int[] {0}, false).build();
        for (Geometry geometry : new Geometry[] {dark, new MeshGeometry().build()}) {
            LightSampler lights = areaLights(geometry, EMISSION);
            assertThat(lights.isEmpty()).isTrue();
            assertThat(lights.lightCount()).isZero();
            assertThat(lights.totalPower()).isZero();
            assertThat(lights.sample(ORIGIN, null, 0.5, 0.5, 0.5, true, new SurfacePoint(), new LightSample())).isFalse();
            
        }
    }

    @Test
    void blackEmissionMakesNoLight() {
        LightSampler lights = areaLights(scene(), new Rgb[] {Rgb.BLACK, Rgb.BLACK, Rgb.BLACK, Rgb.BLACK});
        assertThat(lights.isEmpty()).isTrue();
        assertThat(lights.sample(ORIGIN, null, 0.5, 0.5, 0.5, true, new SurfacePoint(), new LightSample())).isFalse();
    }

    /** Area lights of constant radiance per material chosen by power, no environment, no punctual lights. */
    private static LightSampler areaLights(Geometry geometry, Rgb[] emission) {
        return new LightSampler(geometry, Emission.constants(emission), Environment.BLACK, java.util.List.of()).byPower();
    }
}
