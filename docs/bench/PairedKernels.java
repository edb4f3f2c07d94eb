import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;
import java.util.concurrent.AbstractExecutorService;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * Paired ray-kernel timing of two strahl jars in one JVM: each jar in its own class loader builds
 * the BVH of the same mesh and traces the same ray sets (bench's primary, incoherent and shadow
 * sets, made by each jar's BenchRays from the same seeds); rounds alternate which jar goes first
 * and time the calling thread's CPU time per ray, so that other processes on a shared machine
 * cancel out of the ratios. Prints per set the median of the rounds' ratios NEW/OLD of CPU ns per
 * ray (below 1: NEW is faster) and checks that both jars find the same hits.
 *
 *   java --add-modules jdk.incubator.vector docs/bench/PairedKernels.java OLD.jar[:scalar|:simd] NEW.jar[:scalar|:simd] ROUNDS RAYS MESH [MESH ...]
 *
 * A jar named with ":scalar" or ":simd" has its BVH switched to that kernel ({@code withSimd});
 * without, each jar takes its default for this JVM (with the module: the Vector API where the jar has it).
 */
public class PairedKernels {
    /** Runs every task in the calling thread, so that its CPU time is the kernel's. */
    static final class Inline extends AbstractExecutorService {
        public void execute(Runnable r) { r.run(); }
        public void shutdown() {}
        public List<Runnable> shutdownNow() { return List.of(); }
        public boolean isShutdown() { return false; }
        public boolean isTerminated() { return false; }
        public boolean awaitTermination(long t, TimeUnit u) { return true; }
    }

    record Side(Object bvh, List<?> sets, Method trace, Method hits, Method checksum) {}

    static Side load(String spec, Path mesh, int rays) throws Exception {
        int colon = spec.lastIndexOf(':');
        String jar = colon > 1 ? spec.substring(0, colon) : spec, kernel = colon > 1 ? spec.substring(colon + 1) : "";
        ClassLoader cl = new URLClassLoader(new URL[] {Path.of(jar).toUri().toURL()}, ClassLoader.getPlatformClassLoader());
        Object scene = cl.loadClass("dev.strahl.io.SceneLoader").getMethod("load", Path.class).invoke(null, mesh);
        Class<?> world = cl.loadClass("dev.strahl.world.World");
        Object w = world.getMethod("of", Object.class).invoke(null, scene);
        Object g = world.getMethod("geometry").invoke(w);
        Class<?> geo = cl.loadClass("dev.strahl.geometry.Geometry");
        Object bvh = cl.loadClass("dev.strahl.accel.Bvh").getMethod("build", geo).invoke(null, g);
        if (!kernel.isEmpty()) {
            Method with = bvh.getClass().getDeclaredMethod("withSimd", boolean.class);
            with.setAccessible(true);
            bvh = with.invoke(bvh, kernel.equals("simd"));
        }
        Class<?> br = cl.loadClass("dev.strahl.bench.BenchRays");
        Object cam = scene.getClass().getMethod("camera").invoke(scene);
        int side = (int) Math.max(1, Math.min(512, Math.sqrt(rays / 4.0)));
        List<Object> sets = new ArrayList<>();
        for (Method m : br.getMethods()) {
            if (m.getName().equals("primary")) sets.add(m.invoke(null, cam, side, side, 4, 1L));
        }
        sets.add(br.getMethod("incoherent", cl.loadClass("dev.strahl.geometry.Aabb"), int.class, long.class)
                .invoke(null, geo.getMethod("bounds").invoke(g), rays, 2L));
        sets.add(br.getMethod("shadow", geo, int.class, long.class).invoke(null, g, rays, 3L));
        Class<?> result = cl.loadClass("dev.strahl.bench.BenchRays$Result");
        Method trace = null;
        for (Method m : br.getMethods()) {
            if (m.getName().equals("trace")) trace = m;        // its first parameter is the BVH's class or an interface of it
        }
        return new Side(bvh, sets, trace, result.getMethod("hits"), result.getMethod("checksum"));
    }

    public static void main(String[] args) throws Exception {
        int rounds = Integer.parseInt(args[2]), rays = Integer.parseInt(args[3]);
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        ExecutorService inline = new Inline();
        for (int m = 4; m < args.length; m++) {
            Path mesh = Path.of(args[m]);
            Side[] s = {load(args[0], mesh, rays), load(args[1], mesh, rays)};
            String[] names = {"primary", "incoherent", "shadow"};
            for (int k = 0; k < 3; k++) {
                double[] ratio = new double[rounds];
                double[][] ns = new double[2][rounds];
                long[] hits = new long[2], sums = new long[2];
                for (int warm = 0; warm < 3; warm++) {
                    for (Side x : s) x.trace.invoke(null, x.bvh, x.sets.get(k), 1, inline);
                }
                for (int r = 0; r < rounds; r++) {
                    for (int j = 0; j < 2; j++) {
                        int i = (r + j) % 2;
                        long t0 = mx.getCurrentThreadCpuTime();
                        Object res = s[i].trace.invoke(null, s[i].bvh, s[i].sets.get(k), 1, inline);
                        ns[i][r] = (mx.getCurrentThreadCpuTime() - t0) / (double) rays;
                        hits[i] = (Long) s[i].hits.invoke(res);
                        sums[i] = (Long) s[i].checksum.invoke(res);
                    }
                    ratio[r] = ns[1][r] / ns[0][r];
                }
                Arrays.sort(ratio);
                double[] a = ns[0].clone(), b = ns[1].clone();
                Arrays.sort(a);
                Arrays.sort(b);
                System.out.printf("%-28s %-10s old %7.1f ns/ray  new %7.1f ns/ray  ratio new/old %.3f [%.3f, %.3f]  hits %s%n",
                        mesh.getFileName(), names[k], a[rounds / 2], b[rounds / 2], ratio[rounds / 2], ratio[0], ratio[rounds - 1],
                        hits[0] == hits[1] && sums[0] == sums[1] ? "equal" : "DIFFER " + hits[0] + " vs " + hits[1]);
            }
        }
    }
}
