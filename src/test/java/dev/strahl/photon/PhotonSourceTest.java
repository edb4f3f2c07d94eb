package dev.strahl.photon;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.world.World;
import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.Sphere;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.sampling.IndependentSampler;
import dev.strahl.scene.Scene;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/** Photon emission: total and per-light flux, directions, and the environment's photons. */
class PhotonSourceTest {
    private static final int N = 200_000;

    /** A square of edge {@code size} at height y, centred on (cx, cz), facing down (-y). */
    static TriangleMesh downQuad(double cx, double y, double cz, double size) {
        float x0 = (float) (cx - size / 2), x1 = (float) (cx + size / 2), z0 = (float) (cz - size / 2), z1 = (float) (cz + size / 2);
        float fy = (float) y;
        return new TriangleMesh(new float[] {x0, fy, z0, x1, fy, z0, x1, fy, z1, x0, fy, z1}, new int[] {0, 1, 2, 0, 2, 3}, null);
    }

    /** Two lights: A (edge 1, Le 4 white, at y = 2) and B (edge 0.5, Le (8, 2, 2), at y = 3); power 4 : 1 by mean Le. */
    private static Scene twoLights() {
        return Scene.builder()
                .addMesh(downQuad(0, 2, 0, 1), Material.emissive("a", Rgb.gray(0.5), Rgb.gray(4)))
                .addMesh(downQuad(2, 3, 0, 0.5), Material.emissive("b", Rgb.gray(0.5), new Rgb(8, 2, 2)))
                .build();
    }

    @Test
    void photonsCarryTheLightsPowerInTotalAndPerLight() {
        PhotonSource source = new PhotonSource(World.of(twoLights()));
        IndependentSampler sampler = new IndependentSampler(0);
        Ray ray = new Ray();
        MutableRgb flux = new MutableRgb();
        double[] sum = new double[3], sum2 = new double[3];
        int fromB = 0;
        double[] sumB = new double[3];
        for (int j = 0; j < N; j++) {
            sampler.startStream(PhotonTracer.streamSeed(9, 0, j));
            assertThat(source.emit(sampler, ray, flux)).isFalse();
            double[] f = {flux.r, flux.g, flux.b};
            boolean b = ray.o.y > 2.5;
            fromB += b ? 1 : 0;
            for (int c = 0; c < 3; c++) {
                sum[c] += f[c];
                sum2[c] += f[c] * f[c];
                sumB[c] += b ? f[c] : 0;
            }
        }
        // Σ Le·area·π: A = 4·1·π (each channel), B = (8, 2, 2)·0.25·π.
        double[] expected = {Math.PI * (4 + 2), Math.PI * (4 + 0.5), Math.PI * (4 + 0.5)};
        for (int c = 0; c < 3; c++) {
            double mean = sum[c] / N;
            double sigma = Math.sqrt((sum2[c] / N - mean * mean) / N);
            assertThat(mean).as("channel %d", c).isCloseTo(expected[c], within(4 * sigma + 1e-12));
        }
        // Light B is chosen with probability 1/5 (power 1 of 5) and carries its own flux.
        double p = 0.2;
        assertThat((double) fromB).isCloseTo(N * p, within(4 * Math.sqrt(N * p * (1 - p))));
        assertThat(sumB[0] / fromB).isCloseTo(8 * 0.25 * Math.PI / p, within(1e-9));
        assertThat(sumB[1] / fromB).isCloseTo(2 * 0.25 * Math.PI / p, within(1e-9));
    }

    @Test
    void directionsAreCosineDistributedIntoTheLightsHemisphere() {
        Scene scene = Scene.builder().addMesh(downQuad(0, 2, 0, 1), Material.emissive("a", Rgb.gray(0.5), Rgb.gray(1))).build();
        PhotonSource source = new PhotonSource(World.of(scene));
        IndependentSampler sampler = new IndependentSampler(0);
        Ray ray = new Ray();
        MutableRgb flux = new MutableRgb();
        int bins = 10;
        int[] count = new int[bins];
        for (int j = 0; j < N; j++) {
            sampler.startStream(PhotonTracer.streamSeed(3, 1, j));
            source.emit(sampler, ray, flux);
            double cos = -ray.d.y;                          // the light faces -y
            assertThat(cos).isPositive();
            assertThat(ray.o.y).isLessThan(2).isGreaterThan(2 - 1e-5);     // moved off the light, to its emitting side
            assertThat(Math.abs(ray.o.x)).isLessThanOrEqualTo(0.5 + 1e-6);
            assertThat(ray.d.length()).isCloseTo(1, within(1e-12));
            count[Math.min(bins - 1, (int) (cos * cos * bins))]++;          // cosine-weighted: cos² is uniform
        }
        double chi2 = 0;
        for (int c : count) {
            chi2 += (c - N / (double) bins) * (c - N / (double) bins) / (N / (double) bins);
        }
        assertThat(chi2).as("chi-square of cos² in %d bins", bins).isLessThan(27.9);      // df 9, p = 0.001
    }

    @Test
    void environmentPhotonsCarryTheFluxASphereReceives() {
        double s = 0.5;
        Rgb env = new Rgb(1, 2, 0.5);
        Scene scene = Scene.builder().addSphere(new Vector3d(), s, Material.diffuse("ball", Rgb.gray(0.5))).environment(env).build();
        PhotonSource source = new PhotonSource(World.of(scene));
        assertThat(source.boundingRadius()).isCloseTo(Math.sqrt(3) * s, within(1e-5));
        IndependentSampler sampler = new IndependentSampler(0);
        Ray ray = new Ray();
        MutableRgb flux = new MutableRgb();
        double sum = 0, sum2 = 0;
        for (int j = 0; j < N; j++) {
            sampler.startStream(PhotonTracer.streamSeed(4, 2, j));
            assertThat(source.emit(sampler, ray, flux)).isTrue();
            assertThat(ray.o.length()).isGreaterThanOrEqualTo(source.boundingRadius() * (1 - 1e-9));   // starts outside the scene
            double f = hitsSphere(ray, s) ? flux.g : 0;
            sum += f;
            sum2 += f * f;
        }
        // A sphere of radius s in uniform radiance L receives the flux L·π·4πs².
        double expected = env.g() * Math.PI * 4 * Math.PI * s * s;
        double mean = sum / N;
        double sigma = Math.sqrt((sum2 / N - mean * mean) / N);
        assertThat(mean).isCloseTo(expected, within(4 * sigma));
    }

    @Test
    void lightsAndEnvironmentShareThePhotonsByPower() {
        Scene scene = Scene.builder()
                .addMesh(downQuad(0, 2, 0, 1), Material.emissive("a", Rgb.gray(0.5), Rgb.gray(4)))
                .addSphere(new Vector3d(0, 0, 0), 0.5, Material.diffuse("ball", Rgb.gray(0.5)))
                .environment(Rgb.gray(0.1))
                .build();
        PhotonSource source = new PhotonSource(World.of(scene));
        double lightPower = Math.PI * 4;
        double envPower = 0.1 * 4 * Math.PI * Math.PI * Math.pow(source.boundingRadius(), 2);
        IndependentSampler sampler = new IndependentSampler(0);
        Ray ray = new Ray();
        MutableRgb flux = new MutableRgb();
        double sumLight = 0, sumEnv = 0;
        for (int j = 0; j < N; j++) {
            sampler.startStream(PhotonTracer.streamSeed(5, 0, j));
            if (source.emit(sampler, ray, flux)) {
                sumEnv += flux.r;
            } else {
                sumLight += flux.r;
            }
        }
        // Each photon's flux is divided by its source's probability: each share estimates its own power.
        double p = lightPower / (lightPower + envPower);
        assertThat(sumLight / N).isCloseTo(lightPower, within(4 * Math.sqrt(p * (1 - p) / N) * lightPower / p));
        assertThat(sumEnv / N).isCloseTo(envPower, within(4 * Math.sqrt(p * (1 - p) / N) * envPower / (1 - p)));
    }

    private static boolean hitsSphere(Ray ray, double radius) {
        double b = ray.o.dot(ray.d);
        double c = ray.o.lengthSquared() - radius * radius;
        return b * b - c >= 0 && -b + Math.sqrt(Math.max(0, b * b - c)) > 0;
    }
}
