package dev.strahl.golden;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import dev.strahl.io.SceneLoader;
import dev.strahl.testing.Golden;
import dev.strahl.testing.Golden.Region;
import dev.strahl.testing.Renders;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The Cornell Box shipped in scenes/ against the Mitsuba 3 references (128×128, box-downsampled
 * from 512×512), at unbounded depth and at max depth 5.
 *
 * <p>Tolerance: each visible face's mean luminance within {@value #REGION_TOLERANCE} (relative)
 * of the reference, and relMSE below {@value #MAX_REL_MSE}. The noise of a {@value #SPP} spp
 * render keeps every face within 0.7 % of the reference (measured with seeds 1, 2, 3: worst face
 * 0.51, 0.35, 0.62 % unbounded, 0.27, 0.10, 0.26 % at depth 5; relMSE 7.8–8.0·10⁻⁵ and
 * 4.9·10⁻⁵; at 2048 spp the worst face was 0.37 %, for twice the test's time), and the mutation
 * tests below show that a 2 % brighter or darker face, wall or light fails.
 */
class CornellGoldenTest {
    static final int SIZE = 128;
    static final int SPP = 1024;
    static final double REGION_TOLERANCE = 0.01;
    static final double MAX_REL_MSE = 4e-4;

    static Scene scene;
    static List<Region> regions;
    static Image unbounded;
    static Image depth5;

    @BeforeAll
    static void render() throws Exception {
        scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        regions = Golden.faceRegions(scene, SIZE, SIZE);
        RenderSettings settings = RenderSettings.defaults().withSize(SIZE, SIZE).withSamplesPerPixel(SPP).withSeed(1);
        unbounded = Renders.render(scene, settings);
        depth5 = Renders.render(scene, settings.withMaxDepth(5));
    }

    @Test
    void unboundedDepthMatchesReference() {
        Image ref = Golden.reference("cornell-original_maxdepth-inf_128.pfm");
        Golden.assertClose(unbounded, ref, regions, REGION_TOLERANCE, MAX_REL_MSE, "cornell-original_maxdepth-inf");
    }

    @Test
    void maxDepthFiveMatchesReference() {
        Image ref = Golden.reference("cornell-original_maxdepth-5_128.pfm");
        Golden.assertClose(depth5, ref, regions, REGION_TOLERANCE, MAX_REL_MSE, "cornell-original_maxdepth-5");
    }

    @Test
    void everyWallBoxFaceAndTheLightIsJudged() {
        List<String> judged = regions.stream().filter(r -> r.pixels().length >= Golden.MIN_REGION_PIXELS).map(Region::name).toList();
        for (String material : List.of("floor", "ceiling", "backWall", "leftWall", "rightWall", "light")) {
            assertThat(judged).anyMatch(n -> n.startsWith(material + "("));
        }
        assertThat(judged.stream().filter(n -> n.startsWith("shortBox("))).hasSizeGreaterThanOrEqualTo(3);
        assertThat(judged.stream().filter(n -> n.startsWith("tallBox("))).hasSizeGreaterThanOrEqualTo(2);
    }

    /**
     * Adaptive sampling keeps every face's mean within the same 1 % of the reference: a noise
     * threshold of 3 % (at most {@value #SPP} spp) stops pixels early where they are clean, and the
     * relMSE stays below T², the noise the threshold allows.
     */
    @Test
    void aNoiseThresholdKeepsEveryFaceWithinTheTolerance() {
        double t = 0.03;
        RenderSettings settings = RenderSettings.defaults().withSize(SIZE, SIZE).withSamplesPerPixel(SPP).withSeed(1).withNoiseThreshold(t);
        Image adaptive = Renders.render(scene, settings);
        Image ref = Golden.reference("cornell-original_maxdepth-inf_128.pfm");
        Golden.assertClose(adaptive, ref, regions, REGION_TOLERANCE, t * t, "cornell-original adaptive");
    }

    /** A 2 % change of any single face's brightness must fail the comparison. */
    @Test
    void twoPercentChangeOfAnyFaceFails() {
        Image ref = Golden.reference("cornell-original_maxdepth-inf_128.pfm");
        for (Region r : regions) {
            if (r.pixels().length < Golden.MIN_REGION_PIXELS) {
                continue;
            }
            for (double factor : new double[] {1.02, 0.98}) {
                Image mutant = Golden.scaleRegion(ref, r, factor);
                assertThat(Golden.differences(unbounded, mutant, regions, REGION_TOLERANCE, MAX_REL_MSE))
                        .as("region %s scaled by %s", r.name(), factor)
                        .contains(r.name());
            }
        }
    }
}
