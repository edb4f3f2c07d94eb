package dev.strahl.io.ply;

import dev.strahl.world.World;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * Load time and heap of a PLY mesh, for docs and reports (not a test):
 * <pre>
 * mvn -B -q test-compile
 * java -Xmx1g -cp target/classes:target/test-classes:$HOME/.m2/repository/org/joml/joml/1.10.8/joml-1.10.8.jar \
 *      dev.strahl.io.ply.PlyLoadFigures DATA/meshes/bunny/bunny_midpoint-sub2_1.1M.ply 7     (DATA: the folder of strahl bench --data)
 * </pre>
 * Prints the first (cold) load, the median and minimum of the following loads, the heap the mesh
 * keeps (used heap after a GC with the mesh alive, minus before) and the peak heap of the pools
 * during one load, and the whole SceneLoader.load (PLY + BVH build) once.
 */
public final class PlyLoadFigures {
    private PlyLoadFigures() {}

    public static void main(String[] args) throws Exception {
        Path file = Path.of(args[0]);
        int runs = args.length > 1 ? Integer.parseInt(args[1]) : 7;
        long before = usedAfterGc();
        resetPeaks();
        long t0 = System.nanoTime();
        PlyReader.PlyModel model = PlyReader.read(file);
        double cold = (System.nanoTime() - t0) * 1e-6;
        long peak = peakUsed();
        long retained = usedAfterGc() - before;
        double[] warm = new double[runs];
        for (int i = 0; i < runs; i++) {
            long t = System.nanoTime();
            PlyReader.read(file);
            warm[i] = (System.nanoTime() - t) * 1e-6;
        }
        Arrays.sort(warm);
        System.out.printf("%s: %d triangles, %d vertices%n", file.getFileName(), model.mesh().triangleCount(), model.mesh().vertexCount());
        System.out.printf("load: first %.0f ms, then median %.0f ms, min %.0f ms (%d runs)%n", cold, warm[runs / 2], warm[0], runs);
        System.out.printf("heap: mesh keeps %.1f MiB (%.1f bytes per triangle); peak of all pools during the first load %.1f MiB above the start%n",
                retained / 1048576.0, (double) retained / model.mesh().triangleCount(), (peak - before) / 1048576.0);
        long t = System.nanoTime();
        Scene scene = SceneLoader.load(file);
        System.out.printf("SceneLoader.load (PLY + BVH): %.0f ms, of which BVH %.0f ms%n", (System.nanoTime() - t) * 1e-6,
                World.of(scene).bvhBuildSeconds() * 1e3);
    }

    private static long usedAfterGc() {
        for (int i = 0; i < 3; i++) {
            System.gc();
        }
        Runtime r = Runtime.getRuntime();
        return r.totalMemory() - r.freeMemory();
    }

    private static void resetPeaks() {
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP) {
                pool.resetPeakUsage();
            }
        }
    }

    /** Sum of the pools' peaks: an upper bound of the peak heap (pools peak at different times). */
    private static long peakUsed() {
        long sum = 0;
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP) {
                sum += pool.getPeakUsage().getUsed();
            }
        }
        return sum;
    }
}
