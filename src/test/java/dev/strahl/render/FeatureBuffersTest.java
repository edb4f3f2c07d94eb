package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.camera.CameraRays;
import dev.strahl.film.Film;
import dev.strahl.geometry.Ray;
import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.testing.Meshes;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.Set;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The feature buffers (AOVs): albedo in a white furnace, through a mirror and through glass;
 * the normals and depth of a known sphere; the image untouched by them; the same bits on any
 * thread count and through a checkpoint.
 */
class FeatureBuffersTest {
    private static final Set<Aov> ALL = EnumSet.allOf(Aov.class);

    private static RenderBuffers render(Scene scene, RenderSettings settings) throws InterruptedException {
        try (RenderJob job = RenderJob.start(scene, settings)) {
            return job.awaitBuffers();
        }
    }

    /** An inward sphere of Lambert albedo 0.5 around the camera, with something in front of it. */
    private static Scene furnace(Material inside) {
        return Scene.builder()
                .addMesh(Meshes.icosphere(2, 5.0, true), Material.diffuse("wall", Rgb.gray(0.5)))
                .addSphere(new Vector3d(0, 0, -2), 1, inside)
                .camera(new Camera(new Vector3d(0, 0, 1), new Vector3d(0, 0, -2), new Vector3d(0, 1, 0), 60))
                .build();
    }

    private static RenderSettings small(int spp) {
        return RenderSettings.defaults().withSize(24, 24).withSamplesPerPixel(spp).withSeed(5).withAovs(ALL);
    }

    @Test
    void albedoSeenThroughGlassInAWhiteFurnaceIsTheWallsEverywhere() throws Exception {
        // Glass tints nothing: reflected or refracted, every path ends on the wall of albedo 0.5.
        Image albedo = render(furnace(Material.dielectric("glass", 1.5)), small(8)).albedo();
        for (int y = 0; y < 24; y++) {
            for (int x = 0; x < 24; x++) {
                for (int c = 0; c < 3; c++) {
                    assertThat((double) albedo.get(x, y, c)).as("pixel %d,%d", x, y).isCloseTo(0.5, within(1e-6));
                }
            }
        }
    }

    @Test
    void albedoInAMirrorIsTheWallsTintedByTheMirror() throws Exception {
        RenderBuffers b = render(furnace(Material.mirror("mirror", new Rgb(0.8, 0.6, 0.4))), small(8));
        Image albedo = b.albedo();
        // the centre pixels see the mirror: 0.5 times its Ks; a corner pixel sees the wall
        for (int c = 0; c < 3; c++) {
            double ks = c == 0 ? 0.8 : c == 1 ? 0.6 : 0.4;
            assertThat((double) albedo.get(12, 12, c)).isCloseTo(0.5 * ks, within(1e-6));
            assertThat((double) albedo.get(0, 0, c)).isCloseTo(0.5, within(1e-6));
        }
        // depth is the distance to the first hit, the mirror itself: 3 − 1 along the axis
        assertThat((double) b.depth().get(12, 12, 0)).isCloseTo(2.0, within(0.01));
    }

    @Test
    void normalsAndDepthOfAKnownSphere() throws Exception {
        Camera camera = new Camera(new Vector3d(0, 0, 4), new Vector3d(0, 0, 0), new Vector3d(0, 1, 0), 30);
        Scene scene = Scene.builder()
                .addSphere(new Vector3d(0, 0, 0), 1, Material.diffuse("grey", Rgb.gray(0.7)))
                .camera(camera)
                .build();
        int size = 32;
        RenderBuffers b = render(scene, RenderSettings.defaults().withSize(size, size).withSamplesPerPixel(4).withAovs(ALL));
        CameraRays rays = Meshes.rays(camera, size, size);
        Ray ray = new Ray();
        int checked = 0;
        for (int y = 1; y < size - 1; y++) {
            for (int x = 1; x < size - 1; x++) {
                rays.generate(x + 0.5, y + 0.5, ray);
                // analytic hit of the pixel centre's ray with the unit sphere at the origin
                double bq = ray.o.dot(ray.d);
                double disc = bq * bq - (ray.o.lengthSquared() - 1);
                if (disc < 0.2) {
                    // a miss, or close to the silhouette: the pixel's samples see differing normals
                    if (disc < -0.2) {
                        assertThat(b.depth().get(x, y, 0)).isZero();
                        assertThat(b.albedo().get(x, y, 0)).isZero();
                        assertThat(b.normal().get(x, y, 2)).isZero();
                    }
                    continue;
                }
                double t = -bq - Math.sqrt(disc);
                Vector3d n = ray.at(t, new Vector3d());        // on the unit sphere: p = n
                Vector3d got = new Vector3d(b.normal().get(x, y, 0), b.normal().get(x, y, 1), b.normal().get(x, y, 2));
                assertThat(got.distance(n)).as("normal at %d,%d", x, y).isLessThan(0.03);
                assertThat((double) b.depth().get(x, y, 0)).as("depth at %d,%d", x, y).isCloseTo(t, within(0.01));
                assertThat((double) b.albedo().get(x, y, 1)).isCloseTo(0.7, within(1e-6));
                checked++;
            }
        }
        assertThat(checked).isGreaterThan(150);
    }

    @Test
    void theImageIsTheSameBitsWithAndWithoutFeatureBuffers() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-sphere.json"));       // glass and mirror
        RenderSettings plain = RenderSettings.defaults().withSize(40, 30).withSamplesPerPixel(4).withSeed(9);
        RenderBuffers without = render(scene, plain);
        RenderBuffers with = render(scene, plain.withAovs(ALL));
        assertThat(with.color().rgb()).isEqualTo(without.color().rgb());
        assertThat(with.variance().rgb()).isEqualTo(without.variance().rgb());
        assertThat(without.albedo()).isNull();
        assertThat(with.albedo()).isNotNull();
        // only the buffers asked for are handed out
        assertThat(render(scene, plain.withAovs(Set.of(Aov.DEPTH))).normal()).isNull();
    }

    @Test
    void featureBuffersAreTheSameBitsOnAnyThreadCountAndThroughACheckpoint() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-sphere.json"));
        RenderSettings s = RenderSettings.defaults().withSize(40, 30).withSamplesPerPixel(6).withSeed(9).withAovs(ALL);
        RenderBuffers one = render(scene, s.withThreads(1));
        RenderBuffers three = render(scene, s.withThreads(3).withSamplesPerPass(1));
        for (Aov a : Aov.values()) {
            assertThat(three.aov(a).rgb()).as(a.id()).isEqualTo(one.aov(a).rgb());
        }
        Film half;
        try (RenderJob job = RenderJob.start(scene, s.withSamplesPerPixel(3))) {
            half = TestJobs.awaitFilm(job);
        }
        RenderBuffers resumed;
        try (RenderJob job = TestJobs.resume(scene, s, half, new RenderListener() {})) {
            resumed = job.awaitBuffers();
        }
        assertThat(resumed.color().rgb()).isEqualTo(one.color().rgb());
        assertThat(resumed.variance().rgb()).isEqualTo(one.variance().rgb());
        for (Aov a : Aov.values()) {
            assertThat(resumed.aov(a).rgb()).as(a.id()).isEqualTo(one.aov(a).rgb());
        }
    }
}
