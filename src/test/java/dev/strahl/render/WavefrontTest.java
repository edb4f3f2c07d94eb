package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.camera.CameraRays;
import dev.strahl.film.Film;
import dev.strahl.image.Rgb;
import dev.strahl.integrator.FeatureTracer;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.PathWavefront;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.Texture;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.units.WorkUnit;
import dev.strahl.world.World;
import java.nio.file.Path;
import java.util.EnumSet;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The path tracer's wavefront gives the scalar path's bits: every sum of every pixel (radiance,
 * squared luminance, feature buffers) equal, on scenes with every kind of surface, an environment
 * map seen through a thin lens, punctual lights, a glTF scene with textures, alpha cut-outs, the
 * teaching option without shadows and a bounded depth; for batches of one path, of 7 (a pixel's
 * samples split between batches) and of the default size, on 1 and 3 threads, and when a render
 * goes on from a film the scalar path began; and in a cluster member's work unit.
 */
class WavefrontTest {
    private static final int W = 40, H = 30, SPP = 5;

    /** The film's state after samples [s0, s1) of every pixel on top of {@code film}, with wavefront batches of {@code batch} (0: none). */
    private static Film render(Scene scene, RenderSettings settings, Film film, int s0, int s1, int batch, int threads) throws Exception {
        World world = World.of(scene);
        Integrator integrator = Integrators.create(world, settings);
        boolean cull = settings.transport().cullBackFaces();
        RenderWorkers workers = new RenderWorkers(film, CameraRays.of(scene.camera(), W, H), integrator, () -> new FeatureTracer(world, cull),
                settings.sampling().seed(), threads, false, "wavefront-test", batch);
        try {
            workers.renderPass(s0, s1, null);
        } finally {
            workers.shutdown();
        }
        return film;
    }

    private static Film render(Scene scene, RenderSettings settings, int batch, int threads) throws Exception {
        return render(scene, settings, new Film(W, H, true), 0, SPP, batch, threads);
    }

    /** Every pixel's sample count and sums. */
    private static double[] state(Film film) {
        int n = film.stateSums();
        double[] all = new double[W * H * (n + 1)];
        double[] sums = new double[n];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int i = (y * W + x) * (n + 1);
                all[i] = film.pixelState(x, y, sums);
                System.arraycopy(sums, 0, all, i + 1, n);
            }
        }
        return all;
    }

    private static void assertSameBits(Scene scene, RenderSettings settings, String what) throws Exception {
        double[] scalar = state(render(scene, settings, 0, 1));
        assertThat(java.util.Arrays.stream(scalar).max().orElse(0)).as("%s: something rendered", what).isGreaterThan(0);
        assertThat(state(render(scene, settings, 1, 1))).as("%s, batches of 1", what).isEqualTo(scalar);
        assertThat(state(render(scene, settings, 7, 3))).as("%s, batches of 7 on 3 threads", what).isEqualTo(scalar);
        assertThat(state(render(scene, settings, WavefrontLoop.DEFAULT_BATCH, 1))).as("%s, default batches", what).isEqualTo(scalar);
    }

    private static RenderSettings settings() {
        return RenderSettings.defaults().withSize(W, H).withSamplesPerPixel(SPP).withSeed(7).withAovs(EnumSet.allOf(Aov.class));
    }

    @Test
    void theCornellBoxesGiveTheScalarBits() throws Exception {
        for (String name : new String[] {"cornell-box", "cornell-sphere", "cornell-glossy", "showcase-spheres"}) {
            assertSameBits(SceneLoader.load(Path.of("scenes/" + name + ".json")), settings(), name);
        }
    }

    @Test
    void anEnvironmentMapThroughAThinLensPunctualLightsAndTexturesGiveTheScalarBits() throws Exception {
        Scene env = SceneLoader.load(Path.of("src/test/resources/golden/envmap-sphere.json"));
        assertSameBits(env.withCamera(env.camera().withLens(0.2, 3.5)), settings(), "environment map, thin lens");
        assertSameBits(SceneLoader.load(Path.of("src/test/resources/golden/punctual.json")), settings(), "punctual lights");
        assertSameBits(SceneLoader.load(Path.of("src/test/resources/golden/materials/texture.json")), settings(), "textures");
        assertSameBits(SceneLoader.load(Path.of("scenes/gltf-showcase.glb")), settings(), "glTF showcase");
    }

    @Test
    void theTeachingStrategiesAndABoundedDepthGiveTheScalarBits() throws Exception {
        Scene cornell = SceneLoader.load(Path.of("scenes/cornell-sphere.json"));
        assertSameBits(cornell, settings().withShadows(false), "without shadows");
        assertSameBits(cornell, settings().withMaxDepth(3), "max depth 3");
        assertSameBits(cornell, settings().withHemisphere(HemisphereSampling.UNIFORM).withCullBackFaces(true), "uniform, culled");
    }

    /** A floor under a screen with holes (a checker's luminance as alpha), lit from above: shadow rays and camera rays pass the holes. */
    @Test
    void alphaCutoutsGiveTheScalarBits() throws Exception {
        Texture checker = Texture.image(Path.of("src/test/resources/golden/materials/checker.png")).withUvScale(4, 4);
        Material screen = Material.diffuse("screen", Rgb.gray(0.8)).withAlphaCutout(checker, 0.5);
        Scene scene = Scene.builder()
                .addMesh(square(3, 0, true), Material.diffuse("floor", Rgb.gray(0.5)))
                .addMesh(square(0.6, 2, false), Material.emissive("lamp", Rgb.BLACK, Rgb.gray(4)))
                .addMesh(square(2, 1, true), screen)
                .camera(new Camera(new Vector3d(0, -2.5, 1.6), new Vector3d(0, 0, 0), new Vector3d(0, 0, 1), 55))
                .build();
        assertSameBits(scene, settings(), "alpha cut-outs");
    }

    /** A render the scalar path began and the wavefront goes on with, and one that goes on from pixels with more samples than the pass starts at. */
    @Test
    void goingOnFromAFilmGivesTheScalarBits() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-sphere.json"));
        RenderSettings s = settings();
        double[] scalar = state(render(scene, s, 0, 1));
        Film film = render(scene, s, new Film(W, H, true), 0, 2, 0, 1);
        assertThat(state(render(scene, s, film, 2, SPP, 7, 2))).isEqualTo(scalar);
        Film ahead = render(scene, s, new Film(W, H, true), 0, 3, 5, 1);
        assertThat(state(render(scene, s, ahead, 1, SPP, 7, 2))).as("pixels ahead of the pass").isEqualTo(scalar);
    }

    /** The other integrators, and the path tracer of scenes with media, have no wavefront: they render one sample at a time whatever the batch. */
    @Test
    void otherIntegratorsRenderOneSampleAtATime() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        for (IntegratorKind kind : new IntegratorKind[] {IntegratorKind.DIRECT, IntegratorKind.WHITTED}) {
            Integrator integrator = Integrators.create(World.of(scene), settings().withIntegrator(kind));
            assertThat(WavefrontLoop.of(integrator, 64, true, 1)).as("%s", kind).isNull();
            assertSameBits(scene, settings().withIntegrator(kind), kind.toString());
        }
        assertThat(WavefrontLoop.of(Integrators.create(World.of(scene), settings()), 64, true, 1)).isNotNull();
        Scene media = SceneLoader.load(Path.of("scenes/media-showcase.json"));
        assertThat(WavefrontLoop.of(Integrators.create(World.of(media), settings()), 64, true, 1)).as("media: the scalar path").isNull();
        assertThat(WavefrontLoop.of(Integrators.create(World.of(scene), settings()), 0, true, 1)).isNull();
    }

    /** A cluster member's unit (a tile away from the image's corner, with state it goes on from) gives the scalar bits through the wavefront too. */
    @Test
    void aClusterUnitGivesTheScalarBits() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-sphere.json"));
        RenderSettings s = settings();
        int sums = new Film(W, H, true).stateSums();
        String before = System.getProperty(PathWavefront.PROPERTY);
        try {
            double[][] results = new double[2][];
            for (String mode : new String[] {"off", "on"}) {
                System.setProperty(PathWavefront.PROPERTY, mode);
                var renderer = new UnitRenderers().open(scene, UnitRenderers.encode(s, true), Checkpoint.of(scene, s).sceneDigestBytes(), 1);
                WorkUnit unit = new WorkUnit(9, 5, 17, 11, 0, 2, new int[17 * 11], new double[17 * 11 * sums]);
                renderer.render(unit);
                WorkUnit next = new WorkUnit(9, 5, 17, 11, 2, SPP, unit.counts(), unit.sums());
                renderer.render(next);
                double[] all = new double[17 * 11 * (sums + 1)];
                System.arraycopy(next.sums(), 0, all, 0, next.sums().length);
                for (int i = 0; i < 17 * 11; i++) {
                    all[next.sums().length + i] = next.counts()[i];
                }
                results[mode.equals("on") ? 1 : 0] = all;
            }
            assertThat(results[0][results[0].length - 1]).isEqualTo(SPP);
            assertThat(results[1]).isEqualTo(results[0]);
        } finally {
            if (before == null) {
                System.clearProperty(PathWavefront.PROPERTY);
            } else {
                System.setProperty(PathWavefront.PROPERTY, before);
            }
        }
    }

    /** A square of half-size h at height z with uvs over [0, 1]², facing up or down. */
    private static TriangleMesh square(double h, double z, boolean up) {
        float a = (float) h, zz = (float) z;
        float[] p = {-a, -a, zz, a, -a, zz, a, a, zz, -a, a, zz};
        int[] i = up ? new int[] {0, 1, 2, 0, 2, 3} : new int[] {0, 2, 1, 0, 3, 2};
        return new TriangleMesh(p, i, null, new float[] {0, 0, 1, 0, 1, 1, 0, 1});
    }
}
