package dev.strahl.bench;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/** What {@code strahl bench} measured, as plain values for the table and the JSON file. */
public final class BenchResults {

    /** Median, minimum and maximum of repeated measurements of one rate or time. */
    public record Stat(double median, double min, double max, int runs) {
        public static Stat of(double[] values) {
            double[] v = values.clone();
            Arrays.sort(v);
            int n = v.length;
            double median = n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
            return new Stat(median, v[0], v[n - 1], n);
        }
    }

    /** The Cornell Box render at one thread count. */
    public record Render(int threads, Stat samplesPerSecond, Stat raysPerSecond, double raysPerSample) {}

    /**
     * One ray set traced at one thread count: rays per second of wall time, and per second of the
     * tracing threads' CPU time (per core; on a shared machine what other processes take from the
     * cores does not count in it, so it compares runs minutes apart better).
     */
    public record Rays(String set, int threads, Stat raysPerSecond, long hits, long rays, Stat raysPerCpuSecond) {
        public Rays(String set, int threads, Stat raysPerSecond, long hits, long rays) {
            this(set, threads, raysPerSecond, hits, rays, null);
        }
    }

    /** One mesh: loading, BVH build, memory and ray rates. */
    public record Mesh(String name, String file, int triangles, double loadSeconds, Stat buildSeconds, double bytesPerTriangle,
                List<Rays> rays, String check) {
        Stat buildRate() {
            return new Stat(triangles / buildSeconds.median(), triangles / buildSeconds.max(), triangles / buildSeconds.min(), buildSeconds.runs());
        }

        Rays find(String set, int threads) {
            for (Rays r : rays) {
                if (r.set().equals(set) && r.threads() == threads) {
                    return r;
                }
            }
            return null;
        }
    }

    /**
     * A target of the performance issue: the measured value against its anchor, and whether the
     * ratio reaches the goal (at least {@code goal}, or at most it for {@code atMost}).
     */
    public record Target(String name, double measured, double anchor, String anchorSource, double goal, boolean atMost) {
        double ratio() {
            return measured / anchor;
        }

        boolean reached() {
            return atMost ? ratio() <= goal : ratio() >= goal;
        }
    }

    String date;
    String cpu;
    int cores;
    String os;
    String jvm;
    boolean vectorApi;
    /** What traced the rays and renders ({@code Aggregate.kernel()}). */
    String kernel;
    /** Seconds the bench waited for the SIMD kernel to be compiled before timing (0 for the scalar kernel). */
    public double simdWarmUpSeconds;
    long maxHeapMiB;
    boolean quick;
    int runs;
    public int raysPerSet;
    public String cornellScene;
    public int cornellSpp;
    public double[] cornellMean;
    public double[] cornellReferenceMean;
    public String cornellCheck;
    public Stat previewFps;
    public final List<Render> cornell = new ArrayList<>();
    public final List<Mesh> meshes = new ArrayList<>();
    public final List<String> skipped = new ArrayList<>();
    final List<Target> targets = new ArrayList<>();
    public double seconds;
    /** What the targets are compared with: {@code --anchors FILE}, or the constants. */
    public BenchAnchors anchors = BenchAnchors.fallback();
}
