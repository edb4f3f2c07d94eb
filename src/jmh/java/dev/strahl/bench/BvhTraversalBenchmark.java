package dev.strahl.bench;

import dev.strahl.accel.Bvh;
import dev.strahl.accel.TraversalStack;
import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.io.SceneLoader;
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
 * BVH traversal: closest hit and any hit of incoherent rays (origins uniform in the scene's
 * bounds, directions uniform on the sphere). {@code scene} is any scene file strahl loads, e.g.
 * {@code -p scene=DATA/meshes/bunny/bun_zipper.ply} (DATA: the folder of {@code strahl bench --data}),
 * on the SIMD kernel (from the first call: JMH's warm-up compiles it) and on its scalar twin.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(value = 1, jvmArgsAppend = {"--add-modules", "jdk.incubator.vector"})
public class BvhTraversalBenchmark {
    private static final int RAYS = 1 << 16;

    @Param("scenes/cornell-box.json")
    public String scene;

    @Param({"simd", "scalar"})
    public String kernel;

    private Bvh bvh;
    private final double[] rays = new double[6 * RAYS];
    private final Ray ray = new Ray();
    private final Hit hit = new Hit();
    private final TraversalStack stack = Bvh.newStack();
    private int next;

    @Setup
    public void setUp() throws Exception {
        World world = World.of(SceneLoader.load(Path.of(scene)));
        bvh = ((Bvh) world.bvh()).withSimd(kernel.equals("simd"));
        Aabb box = world.bounds();
        SplittableRandom random = new SplittableRandom(3);
        for (int i = 0; i < RAYS; i++) {
            double z = 1 - 2 * random.nextDouble(), r = Math.sqrt(1 - z * z), phi = 2 * Math.PI * random.nextDouble();
            rays[6 * i] = box.minX + random.nextDouble() * box.extent(0);
            rays[6 * i + 1] = box.minY + random.nextDouble() * box.extent(1);
            rays[6 * i + 2] = box.minZ + random.nextDouble() * box.extent(2);
            rays[6 * i + 3] = r * Math.cos(phi);
            rays[6 * i + 4] = r * Math.sin(phi);
            rays[6 * i + 5] = z;
        }
    }

    private Ray nextRay(double tMax) {
        int k = 6 * (next++ & (RAYS - 1));
        ray.o.set(rays[k], rays[k + 1], rays[k + 2]);
        ray.d.set(rays[k + 3], rays[k + 4], rays[k + 5]);
        ray.tMax = tMax;
        return ray;
    }

    @Benchmark
    public int closestHit() {
        hit.reset();
        return bvh.intersect(nextRay(Double.POSITIVE_INFINITY), hit, stack, false) ? hit.prim : -1;
    }

    /** Any hit within half the scene's size: some rays blocked, some not. */
    @Benchmark
    public boolean anyHit() {
        return bvh.occluded(nextRay(0.5), stack);
    }
}
