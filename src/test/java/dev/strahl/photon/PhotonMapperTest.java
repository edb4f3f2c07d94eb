package dev.strahl.photon;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.scene.TestScenes;
import dev.strahl.world.World;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.Parallel;
import dev.strahl.integrator.Shading;
import dev.strahl.integrator.Tracer;
import dev.strahl.render.PhotonParameters;
import dev.strahl.color.MutableRgb;
import dev.strahl.render.IntegratorKind;
import dev.strahl.scene.Camera;
import dev.strahl.image.Image;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.Sphere;
import dev.strahl.material.Lambert;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.sampling.IndependentSampler;
import dev.strahl.sampling.Sample2D;
import dev.strahl.scene.Scene;
import dev.strahl.testing.Meshes;
import dev.strahl.testing.Renders;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The photon mapper on scenes whose answer is known in closed form, and its radius schedule. */
class PhotonMapperTest {

    /** A closed sphere of albedo ρ emitting Le = 1 inwards, camera inside (as in FurnaceTest). */
    private static Scene furnace(double albedo) {
        Material wall = TestScenes.material("furnace", new Lambert(Rgb.gray(albedo)), Rgb.gray(1));
        return Scene.builder()
                .addMesh(Meshes.icosphere(3, 1.0, true), wall)
                .camera(new Camera(new Vector3d(0.1, -0.2, 0.05), new Vector3d(0.3, 0.4, -1), new Vector3d(0, 1, 0), 60))
                .build();
    }

    private static RenderSettings photonSettings(int maxDepth, int iterations, int photons, double radius) {
        return RenderSettings.defaults().withSize(24, 24).withSamplesPerPixel(iterations).withMaxDepth(maxDepth).withSeed(3)
                .withIntegrator(IntegratorKind.PHOTON).withPhotons(new PhotonParameters(photons, radius));
    }

    /**
     * Le·(1 + ρ + … + ρ^(d−1)): segment 1 is the emission seen, 2 direct light (next-event
     * estimation), 3 and beyond the photons, counted with camera and photon segments together.
     */
    @ParameterizedTest(name = "albedo {0}, maxDepth {1}")
    @CsvSource({"0.5, 1", "0.5, 2", "0.5, 3", "0.5, 5", "0.5, -1", "0.8, -1"})
    void closedEmittingSphereGivesGeometricSeries(double albedo, int maxDepth) {
        Image img = Renders.render(furnace(albedo), photonSettings(maxDepth, 8, 10_000, 0.1));
        double expected = maxDepth < 0 ? 1 / (1 - albedo) : (1 - Math.pow(albedo, maxDepth)) / (1 - albedo);
        for (int c = 0; c < 3; c++) {
            assertThat(img.mean()[c]).as("channel %d", c).isCloseTo(expected, within(0.015 * expected));
        }
    }

    /**
     * A diffuse sphere under a uniform environment L: it sees only the environment, so its
     * radiance is ρ·L everywhere. No area light: all its light comes from environment photons,
     * stored from their first hit, so that max depth 2 (one bounce) already has all of it, and
     * max depth 1 none. Tolerance 3 %: over seeds 1–6 the image mean scatters by
     * 1.7 % (σ) around 1.217.
     */
    @ParameterizedTest(name = "maxDepth {0}")
    @CsvSource({"-1, 1.2", "2, 1.2", "1, 0"})
    void sphereUnderUniformEnvironmentReflectsAlbedoTimesRadiance(int maxDepth, double expected) {
        Scene scene = Scene.builder()
                .addSphere(new Vector3d(), 1, Material.diffuse("ball", Rgb.gray(0.6)))
                .environment(Rgb.gray(2))
                .camera(new Camera(new Vector3d(0, 0, 4), new Vector3d(), new Vector3d(0, 1, 0), 10))     // only the sphere in view
                .build();
        Image img = Renders.render(scene, photonSettings(maxDepth, 8, 100_000, 0.1));
        for (int c = 0; c < 3; c++) {
            assertThat(img.mean()[c]).isCloseTo(expected, within(0.03 * expected));
        }
    }

    @Test
    void sceneWithoutAnythingEmittingIsBlackAndTracesNoPhotons() {
        Scene scene = Scene.builder()
                .addSphere(new Vector3d(), 1, Material.diffuse("ball", Rgb.gray(0.6)))
                .environment(Rgb.BLACK)
                .camera(new Camera(new Vector3d(0, 0, 4), new Vector3d(), new Vector3d(0, 1, 0), 40))
                .build();
        PhotonMapper pm = new PhotonMapper(World.of(scene), -1, false, false, PhotonParameters.DEFAULT_PHOTONS, 0, true);
        Integrator.Worker w = pm.newWorker();
        pm.prepareSample(0, 0, Parallel.sequential(w));
        assertThat(pm.storedPhotons()).isZero();
        assertThat(w.rayCount()).isZero();
        Image img = Renders.render(scene, photonSettings(-1, 2, 1000, 0));
        assertThat(img.mean()).containsExactly(0, 0, 0);
    }

    @Test
    void radiusShrinksByKnausZwickersSchedule() {
        double r1 = 0.05;
        assertThat(PhotonMapper.radiusSquared(r1, 1)).isEqualTo(r1 * r1);
        for (int i = 1; i < 50; i++) {
            double ratio = PhotonMapper.radiusSquared(r1, i + 1) / PhotonMapper.radiusSquared(r1, i);
            assertThat(ratio).isCloseTo((i + 2.0 / 3) / (i + 1), within(1e-12));
        }
        // r_i² ∝ i^(α−1) = i^(−1/3) for large i.
        double ratio = PhotonMapper.radiusSquared(r1, 20_000) / PhotonMapper.radiusSquared(r1, 10_000);
        assertThat(ratio).isCloseTo(Math.pow(2, -1.0 / 3), within(1e-4));
    }

    @Test
    void automaticRadiusIsAHundredthOfTheDiagonal() {
        Scene scene = furnace(0.5);
        PhotonMapper pm = new PhotonMapper(World.of(scene), -1, false, false, PhotonParameters.DEFAULT_PHOTONS, 0, true);
        assertThat(pm.initialRadius()).isCloseTo(0.01 * World.of(scene).geometry().bounds().diagonal(), within(1e-12));
        assertThat(new PhotonMapper(World.of(scene), -1, false, false, 10, 0.2, true).initialRadius()).isEqualTo(0.2);
    }

    @Test
    void radianceBeforeAnyPreparedIterationIsRefused() {
        PhotonMapper pm = new PhotonMapper(World.of(furnace(0.5)), -1, false, false, PhotonParameters.DEFAULT_PHOTONS, 0, true);
        Integrator.Worker w = pm.newWorker();
        assertThatThrownBy(() -> w.radiance(new Ray(), new IndependentSampler(1), new MutableRgb())).isInstanceOf(IllegalStateException.class);
        assertThat(pm.preparesEachSample()).isTrue();
    }

    @Test
    void photonRaysAreCountedByTheWorkersThatTracedThem() {
        PhotonMapper pm = new PhotonMapper(World.of(furnace(0.5)), -1, false, false, 5000, 0.1, true);
        Integrator.Worker w = pm.newWorker();
        pm.prepareSample(0, 0, Parallel.sequential(w));
        assertThat(w.rayCount()).isGreaterThanOrEqualTo(5000);                 // at least one ray per photon
        assertThat(pm.storedPhotons()).isGreaterThan(2000);
    }

    /** Camera paths with their density estimates, and photon tracing into a grown list, allocate nothing. */
    @Test
    void radianceAndPhotonTracingAllocateNothing() throws Exception {
        Scene scene = dev.strahl.io.SceneLoader.load(java.nio.file.Path.of("scenes/cornell-sphere.json"));
        PhotonMapper pm = new PhotonMapper(World.of(scene), -1, false, false, 20_000, 0, true);
        Integrator.Worker w = pm.newWorker();
        pm.prepareSample(1, 0, Parallel.sequential(w));
        var rays = Meshes.rays(scene.camera(), 64, 64);
        Ray ray = new Ray();
        IndependentSampler sampler = new IndependentSampler(1);
        Sample2D film = new Sample2D();
        MutableRgb out = new MutableRgb();
        Runnable frame = () -> {
            for (int p = 0; p < 64 * 64; p++) {
                sampler.startPixelSample(p % 64, p / 64, 0);
                sampler.getPixel2D(film);
                rays.generate(p % 64 + film.u1, p / 64 + film.u2, ray);
                w.radiance(ray, sampler, out);
            }
        };
        frame.run();                                        // warm up
        var mx = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long before = mx.getCurrentThreadAllocatedBytes();
        frame.run();
        assertThat(mx.getCurrentThreadAllocatedBytes() - before).as("bytes allocated by 4096 camera paths").isLessThan(1024);

        PhotonTracer tracer = new PhotonTracer(new Tracer(World.of(scene), Shading.bsdfs(World.of(scene), false), false), new PhotonSource(World.of(scene)), -1);
        PhotonList list = new PhotonList(100_000);
        tracer.trace(1, 0, 0, 20_000, 1e-4, list);           // warm up
        list.clear();
        before = mx.getCurrentThreadAllocatedBytes();
        tracer.trace(1, 1, 0, 20_000, 1e-4, list);
        assertThat(mx.getCurrentThreadAllocatedBytes() - before).as("bytes allocated tracing 20 000 photons").isLessThan(1024);
    }

    @Test
    void parametersAreValidated() {
        assertThatThrownBy(() -> new PhotonParameters(0, 0)).hasMessageContaining("photons per iteration");
        assertThatThrownBy(() -> new PhotonParameters(PhotonParameters.MAX_PHOTONS + 1, 0)).hasMessageContaining("photons per iteration");
        assertThatThrownBy(() -> new PhotonParameters(10, -1)).hasMessageContaining("photon radius");
        assertThatThrownBy(() -> new PhotonParameters(10, Double.NaN)).hasMessageContaining("photon radius");
        assertThatThrownBy(() -> new PhotonParameters(10, Double.POSITIVE_INFINITY)).hasMessageContaining("photon radius");
        assertThatThrownBy(() -> new PhotonMapper(World.of(furnace(0.5)), 0, false, false, PhotonParameters.DEFAULT_PHOTONS, 0, true))
                .hasMessageContaining("maxDepth");
    }
}
