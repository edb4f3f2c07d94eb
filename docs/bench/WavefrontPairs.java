import dev.strahl.io.SceneLoader;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The path tracer's scalar loop and its wavefront side by side in one warm JVM (issue 28, stage 2):
 * after one warm-up render of each, ROUNDS rounds of a render with each mode in turn (A B A B),
 * at SIZE² and SPP samples per pixel on THREADS threads. Prints each render's samples per wall
 * second and per process-CPU second (the latter less sensitive to a shared machine's load), then
 * the medians with min and max, and one JSON line. The mode is the system property
 * strahl.wavefront (off / on), read when a render job starts; "on:N" sets the batch size too.
 *
 *   java --add-modules jdk.incubator.vector -cp target/strahl.jar docs/bench/WavefrontPairs.java \
 *        scenes/cornell-box.json 512 16 5 2 [off,on]
 */
public class WavefrontPairs {
    public static void main(String[] a) throws Exception {
        Scene scene = SceneLoader.load(Path.of(a[0]));
        int size = Integer.parseInt(a[1]), spp = Integer.parseInt(a[2]), rounds = Integer.parseInt(a[3]), threads = Integer.parseInt(a[4]);
        String[] modes = a.length > 5 ? a[5].split(",") : new String[] {"off", "on"};
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        RenderSettings s = RenderSettings.defaults().withSize(size, size).withSamplesPerPixel(spp).withThreads(threads);
        Map<String, List<double[]>> results = new LinkedHashMap<>();
        for (int round = -1; round < rounds; round++) {            // round -1: the warm-up
            for (String m : modes) {
                String[] kv = m.split(":");
                System.setProperty("strahl.wavefront", kv[0]);
                if (kv.length > 1) {
                    System.setProperty("strahl.wavefront.batch", kv[1]);
                } else {
                    System.clearProperty("strahl.wavefront.batch");
                }
                long c0 = os.getProcessCpuTime(), t0 = System.nanoTime();
                try (RenderJob job = RenderJob.start(scene, s)) {
                    job.awaitCompletion();
                }
                double cpu = (os.getProcessCpuTime() - c0) * 1e-9, wall = (System.nanoTime() - t0) * 1e-9;
                double n = (double) size * size * spp;
                if (round >= 0) {
                    results.computeIfAbsent(m, k -> new ArrayList<>()).add(new double[] {n / wall, n / cpu});
                }
                System.err.printf(Locale.ROOT, "round %d %s: %.0f k samples/s, %.0f k samples/CPU-s%n", round, m, n / wall / 1e3, n / cpu / 1e3);
            }
        }
        StringBuilder json = new StringBuilder("{");
        for (var e : results.entrySet()) {
            double[] wall = e.getValue().stream().mapToDouble(x -> x[0]).sorted().toArray();
            double[] cpu = e.getValue().stream().mapToDouble(x -> x[1]).sorted().toArray();
            System.out.printf(Locale.ROOT, "%s: samples/s median %.0f k (min %.0f, max %.0f); per CPU-s median %.0f k (min %.0f, max %.0f)%n",
                    e.getKey(), median(wall) / 1e3, wall[0] / 1e3, wall[wall.length - 1] / 1e3, median(cpu) / 1e3, cpu[0] / 1e3, cpu[cpu.length - 1] / 1e3);
            json.append(json.length() > 1 ? ", " : "").append(String.format(Locale.ROOT,
                    "\"%s\": {\"samples_per_second\": %s, \"samples_per_cpu_second\": %s}", e.getKey(), stat(wall), stat(cpu)));
        }
        System.out.println(json.append("}"));
    }

    private static double median(double[] sorted) {
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }

    private static String stat(double[] sorted) {
        return String.format(Locale.ROOT, "{\"median\": %.1f, \"min\": %.1f, \"max\": %.1f, \"runs\": %d}", median(sorted), sorted[0],
                sorted[sorted.length - 1], sorted.length);
    }
}
