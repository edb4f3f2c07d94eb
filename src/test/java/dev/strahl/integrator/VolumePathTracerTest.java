package dev.strahl.integrator;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.camera.CameraRays;
import dev.strahl.geometry.Ray;
import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.io.SceneLoader;
import dev.strahl.color.MutableRgb;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderSettings;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.StratifiedSampler;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.testing.Meshes;
import dev.strahl.testing.Renders;
import dev.strahl.world.World;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The volumetric path tracer against closed forms: a furnace (a medium of albedo 1 inside an
 * invisible sphere under a uniform sky is the sky, grey or chromatic), Beer–Lambert along camera
 * rays (an absorbing slab, a camera inside a medium) and along shadow rays (a slab between a
 * point light and a floor), Mitsuba's rule that a surface without interior and exterior leaves a
 * ray in its medium, and what the other integrators do with media; no allocation per sample.
 */
class VolumePathTracerTest {
    private static final RenderSettings SMALL = RenderSettings.defaults().withSize(24, 24).withSeed(3);

    /** A quad of half-size h in the plane z = z0, facing +z (towards a camera on +z). */
    static TriangleMesh quadZ(double h, double z0) {
        float z = (float) z0, s = (float) h;
        return new TriangleMesh(new float[] {-s, -s, z, s, -s, z, s, s, z, -s, s, z}, new int[] {0, 1, 2, 0, 2, 3}, null);
    }

    /** An axis-aligned box with outward faces. */
    static TriangleMesh box(double x0, double y0, double z0, double x1, double y1, double z1) {
        float a = (float) x0, b = (float) y0, c = (float) z0, d = (float) x1, e = (float) y1, f = (float) z1;
        return new TriangleMesh(new float[] {a, b, c, d, b, c, d, e, c, a, e, c, a, b, f, d, b, f, d, e, f, a, e, f},
                new int[] {0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5, 0, 1, 5, 0, 5, 4, 3, 7, 6, 3, 6, 2}, null);
    }

    private static final Camera FRONT = new Camera(new Vector3d(0, 0, 5), new Vector3d(0, 0, 0), new Vector3d(0, 1, 0), 10);

    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void aMediumOfAlbedoOneUnderAUniformSkyIsTheSky(boolean chromatic) {
        Rgb sky = new Rgb(0.5, 0.7, 0.9);
        Scene scene = Scene.builder()
                .homogeneousMedium("cloud", chromatic ? new Rgb(1, 3, 6) : Rgb.gray(3), Rgb.WHITE, 0.6)
                .mediumBoundary("cloud", null)
                .addSphere(new Vector3d(0, 0, 0), 1, Material.nullSurface("boundary"))
                .environment(sky)
                .camera(new Camera(new Vector3d(0, 0, 4), new Vector3d(0, 0, 0), new Vector3d(0, 1, 0), 20))
                .build();
        Image img = Renders.render(scene, SMALL.withSamplesPerPixel(chromatic ? 64 : 16));
        double[] mean = img.mean();
        assertThat(mean[0]).isCloseTo(0.5, within(0.5 * (chromatic ? 0.01 : 0.005)));
        assertThat(mean[1]).isCloseTo(0.7, within(0.7 * (chromatic ? 0.01 : 0.005)));
        assertThat(mean[2]).isCloseTo(0.9, within(0.9 * (chromatic ? 0.01 : 0.005)));
        if (!chromatic) {
            // every path leaves the cloud with weight 1 until the roulette: the centre pixel, deep inside, too
            assertThat((double) img.get(12, 12, 1)).isCloseTo(0.7, within(0.7 * 0.05));
        }
    }

    @Test
    void anAbsorbingSlabTransmitsBeerLambertPerChannel() {
        Rgb sigma = new Rgb(0.9, 0.4, 0.05);
        for (double thickness : new double[] {0.5, 1.5}) {
            Scene scene = Scene.builder()
                    .addMesh(quadZ(3, -2), Material.emissive("lamp", Rgb.BLACK, new Rgb(2, 3, 4)))
                    .homogeneousMedium("ink", sigma, Rgb.BLACK, 0)
                    .mediumBoundary("ink", null)
                    .addMesh(box(-2, -2, -thickness / 2, 2, 2, thickness / 2), Material.nullSurface("slab"))
                    .mediumBoundary(null, null)
                    // a pane of nothing inside the slab: no interior, no exterior, so the ray stays in the ink
                    .addMesh(quadZ(2, 0.1 * thickness), Material.nullSurface("pane"))
                    .camera(FRONT)
                    .build();
            Image img = Renders.render(scene, SMALL.withSamplesPerPixel(2));
            // the middle pixels' rays are within 0.4° of the axis: their path in the slab is thickness / cos < thickness * 1.00003
            assertThat((double) img.get(11, 12, 0)).isCloseTo(2 * Math.exp(-0.9 * thickness), within(2 * Math.exp(-0.9 * thickness) * 1e-4));
            assertThat((double) img.get(12, 11, 1)).isCloseTo(3 * Math.exp(-0.4 * thickness), within(3 * Math.exp(-0.4 * thickness) * 1e-4));
            assertThat((double) img.get(12, 12, 2)).isCloseTo(4 * Math.exp(-0.05 * thickness), within(4 * 1e-4));
        }
    }

    @Test
    void aCameraInsideAMediumSeesThroughItAll() {
        Scene scene = Scene.builder()
                .addMesh(quadZ(3, -2), Material.emissive("lamp", Rgb.BLACK, Rgb.gray(5)))
                .homogeneousMedium("murk", new Rgb(0.2, 0.3, 0.4), Rgb.BLACK, 0)
                .cameraMedium("murk")
                .camera(FRONT)
                .build();
        Image img = Renders.render(scene, SMALL.withSamplesPerPixel(2));
        assertThat((double) img.get(12, 12, 0)).isCloseTo(5 * Math.exp(-0.2 * 7), within(5 * Math.exp(-0.2 * 7) * 3e-4));
        assertThat((double) img.get(12, 12, 2)).isCloseTo(5 * Math.exp(-0.4 * 7), within(5 * Math.exp(-0.4 * 7) * 3e-4));
    }

    /** A floor under a point light, seen from below a slab of ink that lies between them: shadow rays through a medium. */
    @Test
    void shadowRaysThroughAMediumAreAttenuatedByBeerLambert() {
        double sigma = 1.3, h = 0.4;
        Image with = Renders.render(floorUnderSlab(sigma, h), SMALL.withSamplesPerPixel(2).withMaxDepth(2));
        Image without = Renders.render(floorUnderSlab(0, h), SMALL.withSamplesPerPixel(2).withMaxDepth(2));
        // the camera sees a patch of floor within 0.02 of the axis under the light: the path in the slab is h / cos θ, cos θ > 0.9997
        double expected = Math.exp(-sigma * h);
        for (int[] px : new int[][] {{12, 12}, {2, 2}, {21, 5}}) {
            assertThat((double) with.get(px[0], px[1], 1) / without.get(px[0], px[1], 1)).isCloseTo(expected, within(expected * 4e-4));
        }
        assertThat((double) without.get(12, 12, 1)).isPositive();
    }

    private static Scene floorUnderSlab(double sigma, double h) {
        TriangleMesh floor = new TriangleMesh(new float[] {-5, 0, -5, -5, 0, 5, 5, 0, 5, 5, 0, -5}, new int[] {0, 1, 2, 0, 2, 3}, null);
        return Scene.builder()
                .addMesh(floor, Material.diffuse("floor", Rgb.gray(0.5)))
                .pointLight(new Vector3d(0, 3, 0), Rgb.gray(10))
                .homogeneousMedium("ink", Rgb.gray(sigma), Rgb.BLACK, 0)
                .mediumBoundary("ink", null)
                .addMesh(box(-4, 1.5, -4, 4, 1.5 + h, 4), Material.nullSurface("slab"))
                .camera(new Camera(new Vector3d(0, 1, 0), new Vector3d(0, 0, 0), new Vector3d(0, 0, -1), 2))
                .build();
    }

    @Test
    void theIntegratorsThatCannotRenderMediaSaySo() throws Exception {
        Scene scene = SceneLoader.load(Path.of("src/test/resources/golden/media/tint.json"));
        for (IntegratorKind kind : new IntegratorKind[] {IntegratorKind.WHITTED, IntegratorKind.PHOTON}) {
            assertThatThrownBy(() -> Renders.render(scene, SMALL.withIntegrator(kind).withSamplesPerPixel(1)))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("the " + kind.id() + " integrator does not render participating media or null surfaces; this scene has"
                            + " them: use path or direct");
        }
        Image direct = Renders.render(scene, SMALL.withIntegrator(IntegratorKind.DIRECT).withSamplesPerPixel(4));
        Image depth2 = Renders.render(scene, SMALL.withMaxDepth(2).withSamplesPerPixel(4));
        assertThat(direct.rgb()).as("direct is the volumetric path tracer at max depth 2").isEqualTo(depth2.rgb());
    }

    @ParameterizedTest
    @ValueSource(strings = {"fog", "smoke", "subsurface"})
    void radianceAllocatesNothingPerSample(String name) throws Exception {
        Scene scene = SceneLoader.load(Path.of("src/test/resources/golden/media/" + name + ".json"));
        Integrator.Worker worker = new VolumePathTracer(World.of(scene), -1, false, 1, true).newWorker();
        CameraRays camera = Meshes.rays(scene.camera(), 32, 32);
        SampleAllocation.Result r = SampleAllocation.bestRound(worker, camera, 32, 5_000, 20);
        assertThat(r.greenSum()).isPositive();
        assertThat(r.bestRoundBytes()).as("bytes allocated by 5 000 samples").isLessThan(1024);
    }
}
