package dev.strahl.accel;

import dev.strahl.geometry.Ray;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import dev.strahl.world.World;
import java.nio.file.Path;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Ray against the four boxes of a BVH node (per-ray set-up included), on the scalar and the
 * Vector API path. In this package because the node test is package-private. Needs
 * {@code --add-modules jdk.incubator.vector} for {@code simd=true}.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(value = 1, jvmArgsAppend = {"--add-modules", "jdk.incubator.vector"})
public class RayBoxBenchmark {
    private static final int RAYS = 1024;

    @Param({"false", "true"})
    public boolean simd;

    private Bvh bvh;
    private final Ray[] rays = new Ray[RAYS];
    private final TraversalStack stack = new TraversalStack();
    private int next;

    @Setup
    public void setUp() throws Exception {
        Scene scene = SceneLoader.load(Path.of("scenes/cornell-box.json"));
        bvh = World.of(scene).bvh().withSimd(simd);
        SplittableRandom random = new SplittableRandom(1);
        for (int i = 0; i < RAYS; i++) {
            rays[i] = new Ray();
            rays[i].o.set(random.nextDouble(-0.9, 0.9), random.nextDouble(0.1, 1.9), random.nextDouble(-0.9, 0.9));
            rays[i].d.set(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
        }
    }

    /** One node (the root's four children), one ray; returns something the JIT cannot drop. */
    @Benchmark
    public int fourBoxes() {
        Ray ray = rays[next++ & (RAYS - 1)];
        bvh.testNode(0, ray, stack);
        return stack.lanes[0] ^ stack.lanes[1] ^ stack.lanes[2] ^ stack.lanes[3];
    }
}
