package dev.strahl.integrator;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import dev.strahl.accel.Bvh;
import dev.strahl.accel.Simd;
import dev.strahl.camera.CameraRays;
import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Ray;
import dev.strahl.io.SceneLoader;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.StratifiedSampler;
import dev.strahl.scene.Scene;
import dev.strahl.world.World;
import java.lang.management.ManagementFactory;
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
        Ray ray = new Ray();
        Sample2D film = new Sample2D();
        MutableRgb out = new MutableRgb();
        var threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long allocated = Long.MAX_VALUE;
        double sum = 0;
        // Rounds until the path tracer around the kernel is compiled too; the best round must be clean.
        for (int round = 0; round < 30 && allocated > 0; round++) {
            StratifiedSampler sampler = new StratifiedSampler(round);
            long before = threads.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < 20_000; i++) {
                int x = i % 64, y = (i / 64) % 64;
                sampler.startPixelSample(x, y, i / 4096);
                sampler.getPixel2D(film);
                camera.generate(x + film.u1, y + film.u2, ray);
                worker.radiance(ray, sampler, out);
                sum += out.g;
            }
            allocated = Math.min(allocated, threads.getCurrentThreadAllocatedBytes() - before);
        }
        assertThat(sum).isPositive();
        assertThat(allocated).as("bytes allocated by 20 000 samples with the warm SIMD kernel").isLessThan(1024);
    }
}
