package dev.strahl.photon;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.scene.TestScenes;
import dev.strahl.world.World;
import dev.strahl.integrator.Shading;
import dev.strahl.integrator.Tracer;
import dev.strahl.geometry.Sphere;
import dev.strahl.material.Dielectric;
import dev.strahl.scene.Material;
import dev.strahl.image.Rgb;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.scene.Scene;
import dev.strahl.testing.Meshes;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * Photon tracing conserves flux: in closed scenes every landing on a diffuse surface is known in
 * expectation, so the stored flux, summed, is a closed-form multiple of the emitted power.
 */
class PhotonTracerTest {
    private static final int N = 40_000;
    private static final double RHO = 0.5;

    private static PhotonList trace(Scene scene, int maxDepth) {
        PhotonTracer tracer = new PhotonTracer(new Tracer(World.of(scene), Shading.bsdfs(World.of(scene), false), false),
                new PhotonSource(World.of(scene)), maxDepth);
        PhotonList out = new PhotonList();
        tracer.trace(11, 0, 0, N, 1.0 / N, out);
        return out;
    }

    /** Σ flux (green) of the stored photons with the given segment count; all of them for 0. */
    private static double storedFlux(PhotonList photons, int segments) {
        double sum = 0;
        float[] d = photons.data();
        for (int i = 0; i < photons.size(); i++) {
            if (segments == 0 || d[i * PhotonList.STRIDE + PhotonList.SEGMENTS] == segments) {
                sum += d[i * PhotonList.STRIDE + PhotonList.R + 1];
            }
        }
        return sum;
    }

    /** A closed sphere of radius 1, albedo ρ, emitting Le = 1 inwards everywhere: flux π·4π. */
    private static Scene furnace() {
        return Scene.builder().addMesh(Meshes.icosphere(3, 1.0, true), Material.emissive("furnace", Rgb.gray(RHO), Rgb.gray(1))).build();
    }

    @Test
    void furnaceStoresFluxTimesAlbedoPowersPerBounce() {
        Scene scene = furnace();
        double area = area(scene);
        double phi = Math.PI * area;
        PhotonList photons = trace(scene, -1);
        assertThat(storedFlux(photons, 1)).as("photons straight from the light are not stored").isZero();
        // Landing s carries Φ·ρ^(s−1) in expectation; the photons keep their flux under Russian roulette.
        for (int s = 2; s <= 5; s++) {
            double expected = phi * Math.pow(RHO, s - 1);
            assertThat(storedFlux(photons, s)).as("segments %d", s).isCloseTo(expected, within(expected * 5 / Math.sqrt(N * Math.pow(RHO, s - 1))));
        }
        assertThat(storedFlux(photons, 0)).isCloseTo(phi * RHO / (1 - RHO), within(0.03 * phi));
    }

    @Test
    void boundedDepthStoresOnlyPhotonsThatACameraSegmentCanStillUse() {
        PhotonList photons = trace(furnace(), 4);
        float[] d = photons.data();
        int[] perSegments = new int[8];
        for (int i = 0; i < photons.size(); i++) {
            perSegments[(int) d[i * PhotonList.STRIDE + PhotonList.SEGMENTS]]++;
        }
        assertThat(perSegments[2]).isPositive();
        assertThat(perSegments[3]).isPositive();          // 3 photon segments + 1 camera segment = max depth 4
        assertThat(perSegments[4] + perSegments[5] + perSegments[6] + perSegments[7]).isZero();
        assertThat(trace(furnace(), 2).size()).isZero();   // max depth 2 is direct light: no photons at all
    }

    /**
     * A light inside glass inside a closed diffuse sphere: every photon crosses the glass before
     * its first diffuse landing, and the glass neither absorbs nor creates flux, so the stored
     * flux is Φ/(1−ρ). Radiance transport's 1/η² per crossing would make it wrong by η² for the
     * photons that leave the glass.
     */
    @Test
    void glassTransmitsFluxWithoutTheRadianceScaling() {
        double lightRadius = 0.1;
        Scene scene = Scene.builder()
                .addSphere(new Vector3d(), lightRadius, Material.emissive("light", Rgb.gray(RHO), Rgb.gray(1)))
                .addSphere(new Vector3d(), 0.4, TestScenes.material("glass", new Dielectric(1.5), Rgb.BLACK))
                .addMesh(Meshes.icosphere(3, 1.0, true), Material.diffuse("walls", Rgb.gray(RHO)))
                .build();
        double phi = Math.PI * 4 * Math.PI * lightRadius * lightRadius;
        PhotonList photons = trace(scene, -1);
        double expected = phi / (1 - RHO);
        assertThat(storedFlux(photons, 1)).isZero();
        assertThat(storedFlux(photons, 0)).isCloseTo(expected, within(0.03 * expected));
    }

    private static double area(Scene scene) {
        double a = 0;
        for (int p = 0; p < World.of(scene).geometry().primitiveCount(); p++) {
            a += World.of(scene).geometry().area(p);
        }
        return a;
    }
}
