package dev.strahl.integrator;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import dev.strahl.accel.Bvh;
import dev.strahl.accel.Simd;
import dev.strahl.camera.CameraRays;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import dev.strahl.world.World;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * The per-sample loop allocates nothing with the SIMD ray kernel answering, as with its scalar
 * twin ({@link PathTracerAllocationTest}, which runs with whichever kernel is ready). The kernel is
 * compiled by its warm-up first, as in a render: the warm-up's rays gave C2 a profile under which
 * the leaf-block test merged vectors across a branch and allocated two of them per block, in every
 * render once the kernel was ready (docs/performance.md, round 7); a path tracer that compiled
 * the kernel itself did not show it. Skipped where the SIMD kernel cannot run.
 */
class WarmSimdAllocationTest {

    @Test
    void radianceAllocatesNothingPerSampleOnceTheSimdKernelIsWarm() throws Exception {
        assumeTrue(Simd.awaitWarmUp(120_000), "the SIMD kernel is not available or did not get faster than the scalar one");
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        World world = World.of(scene);
        assertThat(((Bvh) world.bvh()).usesSimd()).isTrue();
        Integrator.Worker worker = new PathTracer(world, -1, false, false, PathTracer.Strategy.MIS).newWorker();
        CameraRays camera = CameraRays.pinholeOf(scene.camera(), 64, 64);
        // Rounds until the path tracer around the kernel is compiled too; the best round must be clean.
        SampleAllocation.Result r = SampleAllocation.bestRound(worker, camera, 64, 20_000, 30);
        assertThat(r.greenSum()).isPositive();
        assertThat(r.bestRoundBytes()).as("bytes allocated by 20 000 samples with the warm SIMD kernel").isLessThan(1024);
    }
}
