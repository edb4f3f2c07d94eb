package dev.strahl.integrator;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.render.TestJobs;
import dev.strahl.world.World;
import dev.strahl.scene.Camera;
import dev.strahl.image.Image;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.scene.Scene;
import dev.strahl.io.SceneLoader;
import dev.strahl.testing.TestData;
import java.nio.file.Path;
import org.joml.Vector3d;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Independent estimators of the same integral must agree: the MIS path tracer, a path tracer
 * that only samples BSDFs and one that only samples lights (where no specular chain leads to a
 * light), and the path tracer at max depth 2 against the direct-lighting integrator. A wrong pdf
 * or MIS weight makes one of them converge elsewhere.
 *
 * <p>"Within the noise" is measured, not guessed: each estimator renders {@value #RUNS} images
 * with different seeds; per 8×8-pixel block of a 64×64 image, the spread of the runs gives the
 * standard error of the block's mean luminance, and the two estimators' block means must differ
 * by less than {@value #Z_MAX} combined standard errors. The seeds are fixed, so the test is
 * deterministic; with {@value #RUNS} runs the ratio is about Student-t distributed with some 15 to
 * 30 degrees of freedom, whose tails are heavier than the normal's: over 64 blocks a worst |z| of 3
 * to 4.5 is usual for agreeing estimators.
 *
 * <p>BSDF-only paths find the small light only by hitting it, so their block means are
 * heavy-tailed: a run that misses the rare hits comes out low with a small spread. They get
 * {@value #BSDF_ONLY_SPP} samples per pixel over all runs, against MIS's
 * {@value #MIS_SPP_AGAINST_BSDF_ONLY}. With 8 runs and 512 against 128, the worst block reached
 * z = 4.2 on the old sampler's numbers, and 5.4 (Empty-RG) and 8.6 (Sphere) once the sampler's
 * stream positions changed, in dark corners where the BSDF-only runs had missed the rare hits;
 * with the budgets here the worst block of the five variants was 4.3, 4.3 and 5.5 for the seeds
 * 1000, 5000 and 9000 (over all blocks the mean z within ±0.3 and the rms z 0.9 to 1.1, as for
 * unbiased estimators), and the Sphere at four times these budgets 3.3.
 *
 * <p>The renders use independent random streams ({@code strahl.sampler=independent}), for which
 * the spread of the runs is an honest standard error. The default stratified sampler shrinks the
 * first bounce's error so much that what remains of BSDF-only paths, rare hits of the small light
 * after later bounces, is heavy-tailed: eight runs then understate the error (at 64 spp a run the
 * BSDF-only block means came out 7 standard errors below MIS, at 1024 spp they agreed, as they
 * do with independent streams). The golden tests check the stratified sampler's image.
 */
class EstimatorAgreementTest {
    @org.junit.jupiter.api.BeforeAll
    static void independentStreams() {
        System.setProperty("strahl.sampler", "independent");
    }

    @org.junit.jupiter.api.AfterAll
    static void defaultSampler() {
        System.clearProperty("strahl.sampler");
    }

    private static final int SIZE = 64;
    private static final int BLOCK = 8;
    private static final int RUNS = 16;
    private static final int BSDF_ONLY_SPP = 4096;
    private static final int MIS_SPP_AGAINST_BSDF_ONLY = 512;
    private static final double Z_MAX = 5;

    static Scene variant(String name) throws Exception {
        Scene scene = SceneLoader.load(TestData.cornell("CornellBox-" + name + ".obj"));
        double y = name.equals("Sphere") || name.equals("Glossy") ? 0.8 : 1;
        return scene.withCamera(new Camera(new Vector3d(0, y, 3.9), new Vector3d(0, y, 0), new Vector3d(0, 1, 0), 40));
    }

    static Image render(Scene scene, Integrator integrator, int spp, long seed) {
        RenderSettings settings = RenderSettings.defaults().withSize(SIZE, SIZE).withSamplesPerPixel(spp).withSeed(seed);
        try (RenderJob job = TestJobs.start(scene, settings, integrator, new RenderListener() {})) {
            return job.awaitCompletion();
        } catch (InterruptedException e) {
            throw new AssertionError(e);
        }
    }

    /** Block means of luminance over {@link #RUNS} renders, with their standard errors. */
    record Estimate(double[] mean, double[] standardError) {
        static Estimate of(Scene scene, Integrator integrator, int totalSpp) {
            int blocks = (SIZE / BLOCK) * (SIZE / BLOCK);
            double[][] runs = new double[RUNS][];
            for (int r = 0; r < RUNS; r++) {
                runs[r] = blockLuminance(render(scene, integrator, totalSpp / RUNS, 1000 + r));
            }
            double[] mean = new double[blocks];
            double[] se = new double[blocks];
            for (int b = 0; b < blocks; b++) {
                double s = 0;
                for (double[] run : runs) {
                    s += run[b];
                }
                mean[b] = s / RUNS;
                double v = 0;
                for (double[] run : runs) {
                    v += (run[b] - mean[b]) * (run[b] - mean[b]);
                }
                se[b] = Math.sqrt(v / (RUNS - 1) / RUNS);
            }
            return new Estimate(mean, se);
        }
    }

    static double[] blockLuminance(Image img) {
        int n = SIZE / BLOCK;
        double[] out = new double[n * n];
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                out[(y / BLOCK) * n + x / BLOCK] += (0.2126 * img.get(x, y, 0) + 0.7152 * img.get(x, y, 1)
                        + 0.0722 * img.get(x, y, 2)) / (BLOCK * BLOCK);
            }
        }
        return out;
    }

    /** The largest |difference| / combined standard error over all blocks. */
    static double worstZ(Estimate a, Estimate b) {
        double worst = 0;
        for (int i = 0; i < a.mean().length; i++) {
            double se = Math.hypot(a.standardError()[i], b.standardError()[i]);
            double diff = Math.abs(a.mean()[i] - b.mean()[i]);
            // Blocks where both estimators are exactly equal (black background) have se = 0.
            double z = diff == 0 ? 0 : diff / Math.max(se, 1e-6 * Math.abs(b.mean()[i]));
            worst = Math.max(worst, z);
        }
        return worst;
    }

    private static PathTracer path(Scene scene, int depth, PathTracer.Strategy strategy) {
        return new PathTracer(World.of(scene), depth, false, false, strategy);
    }

    /**
     * The costliest check (BSDF-only paths need 4096 spp), so on three variants that cover every
     * material: diffuse (Original), mirror and glass (Sphere), glossy (Glossy). Empty-RG and Mirror
     * add no material of their own and are covered by the light-only and depth-two checks.
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"Original", "Sphere", "Glossy"})
    void misAndBsdfOnlyPathTracersAgree(String name) throws Exception {
        Scene scene = variant(name);
        Estimate mis = Estimate.of(scene, path(scene, 5, PathTracer.Strategy.MIS), MIS_SPP_AGAINST_BSDF_ONLY);
        Estimate bsdf = Estimate.of(scene, path(scene, 5, PathTracer.Strategy.BSDF), BSDF_ONLY_SPP);
        assertThat(worstZ(bsdf, mis)).as("BSDF-only vs MIS, %s", name).isLessThan(Z_MAX);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"Original", "Empty-RG", "Glossy"})
    void misAndLightOnlyPathTracersAgree(String name) throws Exception {
        Scene scene = variant(name);
        Estimate mis = Estimate.of(scene, path(scene, 5, PathTracer.Strategy.MIS), 128);
        Estimate light = Estimate.of(scene, path(scene, 5, PathTracer.Strategy.LIGHT), 128);
        assertThat(worstZ(light, mis)).as("light-only vs MIS, %s", name).isLessThan(Z_MAX);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"Original", "Mirror", "Sphere", "Glossy"})
    void directLightingEqualsPathTracingAtDepthTwo(String name) throws Exception {
        Scene scene = variant(name);
        Estimate path = Estimate.of(scene, path(scene, 2, PathTracer.Strategy.MIS), 128);
        Estimate direct = Estimate.of(scene, new DirectLighting(World.of(scene), false, false, 4, true), 64);
        assertThat(worstZ(direct, path)).as("direct vs path at depth 2, %s", name).isLessThan(Z_MAX);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"Original", "Glossy"})
    void uniformAndCosineHemisphereSamplingAgree(String name) throws Exception {
        Scene scene = variant(name);
        Estimate cosine = Estimate.of(scene, path(scene, 5, PathTracer.Strategy.MIS), 128);
        Estimate uniform = Estimate.of(scene, new PathTracer(World.of(scene), 5, true, false, PathTracer.Strategy.MIS), 128);
        assertThat(worstZ(uniform, cosine)).as("uniform vs cosine, %s", name).isLessThan(Z_MAX);
        double seCosine = java.util.Arrays.stream(cosine.standardError()).sum();
        double seUniform = java.util.Arrays.stream(uniform.standardError()).sum();
        assertThat(seUniform).as("uniform hemisphere sampling is noisier").isGreaterThan(seCosine);
    }

    /** The test can fail: the same estimate 3 % brighter is caught. */
    @org.junit.jupiter.api.Test
    void aThreePercentBiasIsDetected() throws Exception {
        Scene scene = variant("Original");
        Estimate mis = Estimate.of(scene, path(scene, 5, PathTracer.Strategy.MIS), 128);
        double[] brighter = mis.mean().clone();
        for (int i = 0; i < brighter.length; i++) {
            brighter[i] *= 1.03;
        }
        assertThat(worstZ(new Estimate(brighter, mis.standardError()), mis)).isGreaterThan(Z_MAX);
    }
}
