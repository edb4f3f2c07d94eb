package dev.strahl.integrator;

import dev.strahl.world.World;
import dev.strahl.testing.Meshes;
import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.color.MutableRgb;
import dev.strahl.camera.CameraRays;
import dev.strahl.geometry.Ray;
import dev.strahl.image.Rgb;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.StratifiedSampler;
import dev.strahl.scene.Scene;
import dev.strahl.io.SceneLoader;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The per-sample loop allocates nothing (STYLE.md habit 4): once compiled, tracing paths through
 * the Cornell Box (BVH traversal, shading, light sampling, the stratified sampler), and through
 * instances (rays moved into each one's coordinates, hits moved back), leaves the
 * thread's allocated-bytes counter where it was.
 */
class PathTracerAllocationTest {

    @ParameterizedTest
    @ValueSource(strings = {"scenes/cornell-box.json", "src/test/resources/golden/envmap-sphere.json", "src/test/resources/golden/instances.json"})
    void radianceAllocatesNothingPerSample(String file) throws Exception {
        Scene scene = SceneLoader.load(Path.of(file));
        Integrator.Worker worker = new PathTracer(World.of(scene), -1, false, false, PathTracer.Strategy.MIS).newWorker();
        CameraRays camera = Meshes.rays(scene.camera(), 64, 64);
        SampleAllocation.Result r = SampleAllocation.bestRound(worker, camera, 64, 20_000, 30);
        assertThat(r.greenSum()).isPositive();
        assertThat(r.bestRoundBytes()).as("bytes allocated by 20 000 samples").isLessThan(1024);
    }

    /** The wavefront allocates nothing per batch either, once compiled (its arrays and objects are made with it). */
    @ParameterizedTest
    @ValueSource(strings = {"scenes/cornell-box.json", "scenes/showcase-spheres.json"})
    void theWavefrontAllocatesNothingPerBatch(String file) throws Exception {
        Scene scene = SceneLoader.load(Path.of(file));
        StratifiedSampler[] samplers = new StratifiedSampler[256];
        for (int i = 0; i < samplers.length; i++) {
            samplers[i] = new StratifiedSampler(1);
        }
        PathWavefront wavefront = new PathTracer(World.of(scene), -1, false, false, PathTracer.Strategy.MIS).newWavefront(samplers);
        CameraRays camera = Meshes.rays(scene.camera(), 64, 64);
        Ray ray = new Ray();
        Sample2D film = new Sample2D();
        var threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long allocated = Long.MAX_VALUE;
        double sum = 0;
        for (int round = 0; round < 30 && allocated > 0; round++) {
            long before = threads.getCurrentThreadAllocatedBytes();
            for (int batch = 0; batch < 40; batch++) {
                for (int slot = 0; slot < samplers.length; slot++) {
                    int i = batch * samplers.length + slot, x = i % 64, y = (i / 64) % 64;
                    wavefront.sampler(slot).startPixelSample(x, y, round);
                    wavefront.sampler(slot).getPixel2D(film);
                    camera.generate(x + film.u1, y + film.u2, ray);
                    wavefront.start(slot, ray);
                }
                wavefront.run(samplers.length);
                for (int slot = 0; slot < samplers.length; slot++) {
                    sum += wavefront.green(slot);
                }
            }
            allocated = Math.min(allocated, threads.getCurrentThreadAllocatedBytes() - before);
        }
        assertThat(sum).isPositive();
        assertThat(allocated).as("bytes allocated by 40 batches of 256 paths").isLessThan(1024);
    }
}
