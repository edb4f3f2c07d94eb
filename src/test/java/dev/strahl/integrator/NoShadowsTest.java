package dev.strahl.integrator;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.PhotonParameters;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.testing.Meshes;
import dev.strahl.testing.Renders;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The teaching option without shadows ({@code RenderSettings.withShadows(false)}, {@code --shadows
 * off}): every light sample counts as visible. The scene: a diffuse floor of albedo ρ at y = 0, a
 * light above it and, between them, a large opaque board that hides the light from every point
 * the camera sees; the camera hangs under the board, looking down, so no camera ray meets it.
 * With shadows the floor is black. Without, it shows exactly the light it would get without the
 * board: under a point light of intensity I, ρ/π · I cosθ / d² (the closed form, integrated over
 * each pixel), the same bits as the scene without the board; under an area light, the
 * unoccluded soft light.
 *
 * <p>The area light is one triangle, not a square of two, because the light sampler numbers the
 * emissive triangles in the BVH's leaf order ({@code World}: the primitives come back reordered),
 * and that order is the builder's to choose from the whole scene. With a two-triangle square the
 * board's two triangles changed the splits, the builder's in-place partition swapped the
 * square's halves, and each light sample's random numbers landed on the other half: the same
 * estimator (the means agreed to 1e-5), other bits in every pixel. With one emissive triangle
 * there is no order to change, so the bits must still agree exactly.
 */
class NoShadowsTest {
    private static final int SIZE = 16;
    private static final double ALBEDO = 0.5;
    private static final Camera CAMERA = new Camera(new Vector3d(0, 0.5, 0), new Vector3d(0, 0, 0), new Vector3d(0, 0, -1), 60);
    private static final Vector3d LIGHT = new Vector3d(0.4, 1.2, -0.3);
    private static final double INTENSITY = 3;

    /** A square of half-size r at height y, wound so that its normal points down (towards the floor). */
    private static TriangleMesh quad(double y, double r) {
        float h = (float) y, s = (float) r;
        return new TriangleMesh(new float[] {-s, h, -s, s, h, -s, s, h, s, -s, h, s}, new int[] {0, 1, 2, 0, 2, 3}, null);
    }

    /** One triangle at y = 1.2 of the 0.6 × 0.6 square's area (0.36), its normal pointing down. */
    private static TriangleMesh triangleLight() {
        float h = 1.2f;
        return new TriangleMesh(new float[] {-0.6f, h, -0.3f, 0.6f, h, -0.3f, 0, h, 0.3f}, new int[] {0, 1, 2}, null);
    }

    private static TriangleMesh floor() {
        return new TriangleMesh(new float[] {-5, 0, -5, -5, 0, 5, 5, 0, 5, 5, 0, -5}, new int[] {0, 1, 2, 0, 2, 3}, null);
    }

    /** The floor, the light (a point light, or else {@link #triangleLight}, facing down) and, if asked, the board at y = 0.8. */
    private static Scene scene(boolean pointLight, boolean board) {
        Scene.Builder b = Scene.builder().addMesh(floor(), Material.diffuse("floor", Rgb.gray(ALBEDO))).camera(CAMERA);
        if (board) {
            b.addMesh(quad(0.8, 2), Material.diffuse("board", Rgb.gray(0.5)));
        }
        if (pointLight) {
            b.pointLight(LIGHT, Rgb.gray(INTENSITY));
        } else {
            b.addMesh(triangleLight(), Material.emissive("light", Rgb.gray(0), Rgb.gray(5)));
        }
        return b.build();
    }

    /** Max depth 2: direct light only, so that no light bounced off the board's underside reaches the floor. */
    private static RenderSettings settings(IntegratorKind kind) {
        return RenderSettings.defaults().withSize(SIZE, SIZE).withSamplesPerPixel(16).withSeed(3).withIntegrator(kind).withMaxDepth(2)
                .withPhotons(new PhotonParameters(2000, 0)).withThreads(2);
    }

    /** ρ/π · I cosθ / d² integrated over each pixel. */
    private static Image closedForm() {
        return Meshes.floorRadiance(CAMERA, SIZE, ALBEDO, p -> {
            double d2 = p.distanceSquared(LIGHT);
            return INTENSITY * LIGHT.y / Math.sqrt(d2) / d2;
        });
    }

    private static double worstRelativeDifference(Image actual, Image expected) {
        double worst = 0;
        for (int i = 0; i < actual.rgb().length; i++) {
            worst = Math.max(worst, Math.abs(actual.rgb()[i] - expected.rgb()[i]) / expected.rgb()[i]);
        }
        return worst;
    }

    @ParameterizedTest
    @EnumSource(IntegratorKind.class)
    void underAPointLightTheBoardCastsNoShadowAndTheFloorShowsTheUnoccludedLight(IntegratorKind kind) {
        Image shadowed = Renders.render(scene(true, true), settings(kind));
        assertThat(shadowed.mean()).as("%s with shadows: the board hides the light", kind).containsExactly(0.0, 0.0, 0.0);

        Image noShadows = Renders.render(scene(true, true), settings(kind).withShadows(false));
        Image noBoard = Renders.render(scene(true, false), settings(kind));
        assertThat(noShadows.rgb()).as("%s: without shadows, the bits of the scene without the board", kind).isEqualTo(noBoard.rgb());
        assertThat(worstRelativeDifference(noShadows, closedForm())).as("%s: the worst pixel against ρ/π · I cosθ / d²", kind)
                .isLessThan(0.01);
    }

    /**
     * Whitted samples the area light alone in both cases, so the board's absence and the skipped
     * shadow rays give the same bits; direct lighting and the path tracer without shadows sample
     * the light alone, where with shadows they weight it against a BSDF sample: the same light in
     * the mean.
     */
    @Test
    void underAnAreaLightTheFloorGetsTheUnoccludedSoftLight() {
        for (IntegratorKind kind : new IntegratorKind[] {IntegratorKind.WHITTED, IntegratorKind.DIRECT, IntegratorKind.PATH}) {
            RenderSettings s = settings(kind).withSamplesPerPixel(64);
            Image shadowed = Renders.render(scene(false, true), s);
            assertThat(shadowed.mean()).as("%s with shadows", kind).containsExactly(0.0, 0.0, 0.0);
            Image noShadows = Renders.render(scene(false, true), s.withShadows(false));
            Image noBoard = Renders.render(scene(false, false), s);
            if (kind == IntegratorKind.WHITTED) {
                assertThat(noShadows.rgb()).as("Whitted: the bits of the scene without the board").isEqualTo(noBoard.rgb());
            }
            double expected = noBoard.mean()[1];
            assertThat(expected).as("%s: the floor is lit", kind).isGreaterThan(0.1);
            assertThat(Math.abs(noShadows.mean()[1] - expected) / expected).as("%s: mean against the scene without the board", kind)
                    .isLessThan(0.01);
        }
    }

    /** Only the shadow rays are skipped: a camera ray and 3 shadow rays per sample with shadows, the camera ray alone without. */
    @Test
    void noShadowRayIsTraced() throws InterruptedException {
        RenderSettings s = settings(IntegratorKind.WHITTED).withLightSamples(3);
        long with = rays(scene(true, true), s);
        long without = rays(scene(true, true), s.withShadows(false));
        long cameraRays = (long) SIZE * SIZE * 16;
        assertThat(with).isEqualTo(4 * cameraRays);
        assertThat(without).isEqualTo(cameraRays);
    }

    private static long rays(Scene scene, RenderSettings s) throws InterruptedException {
        try (RenderJob job = RenderJob.start(scene, s)) {
            return job.awaitStats().rays();
        }
    }
}
