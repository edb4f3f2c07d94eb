package dev.strahl.bench;

import dev.strahl.accel.Simd;
import dev.strahl.io.json.JsonFile;
import dev.strahl.io.text.NumberText;
import com.fasterxml.jackson.core.JsonGenerator;
import dev.strahl.bench.BenchResults.Mesh;
import dev.strahl.bench.BenchResults.Rays;
import dev.strahl.bench.BenchResults.Render;
import dev.strahl.bench.BenchResults.Stat;
import dev.strahl.bench.BenchResults.Target;
import java.io.IOException;
import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.List;
import java.util.Locale;

/**
 * The machine description, the targets of the performance issue with their anchors, and the
 * table and JSON of {@code strahl bench}.
 */
public final class BenchReport {
    private BenchReport() {}

    static final String CORNELL = "cornell-box";

    /** A result record describing this machine and JVM. */
    public static BenchResults machine(boolean quick, int runs) {
        BenchResults r = new BenchResults();
        r.date = LocalDate.now().toString();
        r.cpu = cpuModel();
        r.cores = Runtime.getRuntime().availableProcessors();
        r.os = System.getProperty("os.name") + " " + System.getProperty("os.version") + " (" + System.getProperty("os.arch") + ")";
        r.jvm = System.getProperty("java.vm.name") + " " + System.getProperty("java.runtime.version", System.getProperty("java.version"))
                + " (" + System.getProperty("java.vm.vendor") + ")";
        r.vectorApi = Simd.enabled();
        r.kernel = "bvh8, " + Simd.describe(r.vectorApi);
        r.maxHeapMiB = Runtime.getRuntime().maxMemory() >> 20;
        r.quick = quick;
        r.runs = runs;
        return r;
    }

    /** Waits for the SIMD kernel to be compiled ({@code Simd.awaitWarmUp}); returns the seconds waited, NaN if it did not get there. */
    public static double awaitSimd() throws InterruptedException {
        long t0 = System.nanoTime();
        boolean warm = Simd.awaitWarmUp(120_000);
        return warm || !Simd.enabled() ? (System.nanoTime() - t0) * 1e-9 : Double.NaN;
    }

    /** The vector extensions among the processor's flags (Linux), for the record of what the kernel ran on. */
    static String cpuFlags() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/cpuinfo"))) {
                if (line.startsWith("flags")) {
                    StringBuilder b = new StringBuilder();
                    for (String f : line.substring(line.indexOf(':') + 1).trim().split(" ")) {
                        if (f.startsWith("avx") || f.equals("fma") || f.startsWith("sse4") || f.equals("neon") || f.startsWith("asimd")) {
                            b.append(b.length() == 0 ? "" : " ").append(f);
                        }
                    }
                    return b.toString();
                }
            }
        } catch (IOException | SecurityException e) {
            // not Linux
        }
        return "";
    }

    private static String cpuModel() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/cpuinfo"))) {
                if (line.startsWith("model name")) {
                    return line.substring(line.indexOf(':') + 1).trim();
                }
            }
        } catch (IOException | SecurityException e) {
            // not Linux: fall through
        }
        String id = System.getenv("PROCESSOR_IDENTIFIER");
        return id != null ? id : System.getProperty("os.arch");
    }

    /**
     * The targets that this run measured, each against its anchor ({@code r.anchors}: the
     * side-by-side file of {@code --anchors}, or the constants); a target whose anchor is not
     * there is left out.
     */
    public static void targets(BenchResults r, int oneThread, int allThreads) {
        BenchAnchors a = r.anchors;
        String side = a.sideBySide() ? ", side by side" : ", constant";
        Render one = find(r.cornell, oneThread), all = find(r.cornell, allThreads);
        if (all != null) {
            String t = allThreads + " threads";
            add(r, new Target("Cornell Box samples/s, " + t, all.samplesPerSecond().median(), a.get(BenchAnchors.MITSUBA_LLVM),
                    "Mitsuba 3 LLVM, 2 threads" + side, 1.5, false));
            add(r, new Target("Cornell Box samples/s, " + t, all.samplesPerSecond().median(), a.get(BenchAnchors.MITSUBA_SCALAR),
                    "Mitsuba 3 scalar, 2 threads" + side, 1.0, false));
        }
        if (one != null && all != null && allThreads > oneThread) {
            r.targets.add(new Target("thread scaling, " + allThreads + " vs " + oneThread, all.samplesPerSecond().median(),
                    one.samplesPerSecond().median(), "strahl, " + oneThread + " thread", 0.95 * allThreads / oneThread, false));
        }
        if (r.previewFps != null) {
            r.targets.add(new Target("viewer preview 128², 1 spp, frames/s", r.previewFps.median(), 30, "30 frames/s", 1.0, false));
        }
        for (Mesh m : r.meshes) {
            for (String set : new String[] {"incoherent", "primary", "shadow"}) {
                Rays x = m.find(set, oneThread);
                if (x != null && oneThread == 1) {
                    // Issue 28: incoherent rays per core at least Embree's in the Cornell Box, three quarters on the large meshes.
                    double goal = set.equals("incoherent") ? (m.name().equals(CORNELL) ? 1.0 : 0.75) : set.equals("primary") ? 0.75 : Double.NaN;
                    add(r, new Target(m.name() + " " + set + (set.equals("shadow") ? " any-hit" : " closest-hit") + " rays/s, 1 thread",
                            x.raysPerSecond().median(), a.get(BenchAnchors.embreeRays(m.name(), set)), "Embree 4, per core" + side, goal, false));
                }
            }
            add(r, new Target(m.name() + " BVH build triangles/s, " + r.cores + " threads", m.buildRate().median(),
                    a.get(BenchAnchors.embreeBuild(m.name())), "Embree 4 commit, " + r.cores + " threads" + side, 0.75, false));
            if (!m.name().equals(CORNELL)) {
                r.targets.add(new Target(m.name() + " BVH + mesh bytes per triangle", m.bytesPerTriangle(), 96, "96 bytes", 1.0, true));
            }
        }
    }

    private static void add(BenchResults r, Target t) {
        if (!Double.isNaN(t.anchor())) {
            r.targets.add(t);
        }
    }

    private static Render find(List<Render> list, int threads) {
        for (Render x : list) {
            if (x.threads() == threads) {
                return x;
            }
        }
        return null;
    }

    public static void printTable(PrintWriter out, BenchResults r) {
        out.printf(Locale.ROOT, "strahl bench, %s: %s, %d cores, %s, kernel %s; %d timed run%s after a warm-up%s%n", r.date, r.cpu, r.cores, r.jvm,
                r.kernel, r.runs, r.runs == 1 ? "" : "s", r.quick ? " (--quick: not for citing)" : "");
        if (!r.cornell.isEmpty()) {
            out.printf(Locale.ROOT, "%nCornell Box (%s), 512x512, unbounded depth, path tracer, %d spp per run; median [min, max]%n", r.cornellScene, r.cornellSpp);
            for (Render c : r.cornell) {
                out.printf(Locale.ROOT, "  %2d thread%s  %s samples/s   %s rays/s   %.2f rays/sample%n", c.threads(), c.threads() == 1 ? " " : "s",
                        stat(c.samplesPerSecond(), 1e6, "M"), stat(c.raysPerSecond(), 1e6, "M"), c.raysPerSample());
            }
            if (r.previewFps != null) {
                out.printf(Locale.ROOT, "  viewer preview, 128x128 at 1 spp per frame: %s frames/s%n", stat(r.previewFps, 1, ""));
            }
            out.printf(Locale.ROOT, "  check: image mean %s vs reference %s: %s%n", vec(r.cornellMean), vec(r.cornellReferenceMean), r.cornellCheck);
        }
        if (!r.meshes.isEmpty()) {
            out.printf(Locale.ROOT, "%n%-26s %10s %8s %22s %8s  %s%n", "Meshes", "triangles", "load s", "BVH build M tris/s", "B/tri", "check");
            for (Mesh m : r.meshes) {
                out.printf(Locale.ROOT, "  %-24s %10d %8.2f %22s %8.1f  %s%n", m.name(), m.triangles(), m.loadSeconds(),
                        stat(m.buildRate(), 1e6, ""), m.bytesPerTriangle(), m.check());
            }
            out.printf(Locale.ROOT, "%nRays, M rays/s, median [min, max]%n");
            for (Mesh m : r.meshes) {
                for (String set : new String[] {"primary", "incoherent", "shadow"}) {
                    StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "  %-24s %-10s", m.name(), set.equals("shadow") ? "shadow*" : set));
                    for (Rays x : m.rays()) {
                        if (x.set().equals(set)) {
                            line.append(String.format(Locale.ROOT, "  %2dT %-22s", x.threads(), stat(x.raysPerSecond(), 1e6, "")));
                        }
                    }
                    out.println(line);
                }
            }
            out.printf(Locale.ROOT, "  (* any hit, between random surface points)%n");
        }
        for (String s : r.skipped) {
            out.printf(Locale.ROOT, "%nskipped: %s%n", s);
        }
        if (!r.targets.isEmpty()) {
            out.printf(Locale.ROOT, "%nAnchors: %s%n", r.anchors.source());
            out.printf(Locale.ROOT, "%-64s %12s %12s  %-46s %7s %8s %s%n", "Targets", "measured", "anchor", "", "ratio", "goal", "reached");
            for (Target t : r.targets) {
                out.printf(Locale.ROOT, "  %-62s %12s %12s  %-46s %7.2f %8s %s%n", t.name(), num(t.measured()), num(t.anchor()), t.anchorSource(), t.ratio(),
                        Double.isNaN(t.goal()) ? "-" : (t.atMost() ? "<= " : ">= ") + String.format(Locale.ROOT, "%.2f", t.goal()),
                        Double.isNaN(t.goal()) ? "-" : t.reached() ? "yes" : "no");
            }
        }
        out.printf(Locale.ROOT, "%nbench took %.0f s%n", r.seconds);
    }

    private static String stat(Stat s, double unit, String suffix) {
        return String.format(Locale.ROOT, "%.2f%s [%.2f, %.2f]", s.median() / unit, suffix.isEmpty() ? "" : " " + suffix, s.min() / unit, s.max() / unit);
    }

    private static String num(double v) {
        return v >= 1e5 ? NumberText.si(v) : String.format(Locale.ROOT, "%.2f", v);
    }

    private static String vec(double[] v) {
        return v == null ? "-" : String.format(Locale.ROOT, "(%.4f, %.4f, %.4f)", v[0], v[1], v[2]);
    }

    public static void writeJson(Path file, BenchResults r) throws IOException {
        JsonFile.write(file, json -> {
            json.writeStartObject();
            json.writeStringField("date", r.date);
            json.writeObjectFieldStart("machine");
            json.writeStringField("cpu", r.cpu);
            json.writeNumberField("cores", r.cores);
            json.writeStringField("os", r.os);
            json.writeStringField("jvm", r.jvm);
            json.writeStringField("jvm_arguments", String.join(" ", ManagementFactory.getRuntimeMXBean().getInputArguments()));
            json.writeBooleanField("vector_api", r.vectorApi);
            json.writeStringField("kernel", r.kernel);
            json.writeStringField("cpu_flags", cpuFlags());
            json.writeNumberField("simd_warm_up_seconds", r.simdWarmUpSeconds);
            json.writeNumberField("max_heap_mib", r.maxHeapMiB);
            json.writeEndObject();
            json.writeBooleanField("quick", r.quick);
            json.writeNumberField("runs", r.runs);
            json.writeNumberField("rays_per_set", r.raysPerSet);
            if (!r.cornell.isEmpty()) {
                json.writeObjectFieldStart("cornell");
                json.writeStringField("scene", r.cornellScene);
                json.writeNumberField("width", 512);
                json.writeNumberField("height", 512);
                json.writeNumberField("max_depth", -1);
                json.writeNumberField("spp_per_run", r.cornellSpp);
                json.writeArrayFieldStart("renders");
                for (Render c : r.cornell) {
                    json.writeStartObject();
                    json.writeNumberField("threads", c.threads());
                    stat(json, "samples_per_second", c.samplesPerSecond());
                    stat(json, "rays_per_second", c.raysPerSecond());
                    json.writeNumberField("rays_per_sample", c.raysPerSample());
                    json.writeEndObject();
                }
                json.writeEndArray();
                if (r.previewFps != null) {
                    stat(json, "viewer_preview_frames_per_second", r.previewFps);
                }
                array(json, "image_mean", r.cornellMean);
                array(json, "reference_mean", r.cornellReferenceMean);
                json.writeStringField("check", r.cornellCheck);
                json.writeEndObject();
            }
            json.writeArrayFieldStart("meshes");
            for (Mesh m : r.meshes) {
                json.writeStartObject();
                json.writeStringField("name", m.name());
                json.writeStringField("file", m.file());
                json.writeNumberField("triangles", m.triangles());
                json.writeNumberField("load_seconds", m.loadSeconds());
                stat(json, "bvh_build_seconds", m.buildSeconds());
                stat(json, "bvh_build_triangles_per_second", m.buildRate());
                json.writeNumberField("bytes_per_triangle", m.bytesPerTriangle());
                json.writeArrayFieldStart("rays");
                for (Rays x : m.rays()) {
                    json.writeStartObject();
                    json.writeStringField("set", x.set());
                    json.writeStringField("query", x.set().equals("shadow") ? "any-hit" : "closest-hit");
                    json.writeNumberField("threads", x.threads());
                    json.writeNumberField("rays", x.rays());
                    json.writeNumberField("hits", x.hits());
                    stat(json, "rays_per_second", x.raysPerSecond());
                    if (x.raysPerCpuSecond() != null) {
                        stat(json, "rays_per_cpu_second", x.raysPerCpuSecond());
                    }
                    json.writeEndObject();
                }
                json.writeEndArray();
                json.writeStringField("check", m.check());
                json.writeEndObject();
            }
            json.writeEndArray();
            json.writeArrayFieldStart("skipped");
            for (String s : r.skipped) {
                json.writeString(s);
            }
            json.writeEndArray();
            json.writeStringField("anchors", r.anchors.source());
            json.writeArrayFieldStart("targets");
            for (Target t : r.targets) {
                json.writeStartObject();
                json.writeStringField("name", t.name());
                json.writeNumberField("measured", t.measured());
                json.writeNumberField("anchor", t.anchor());
                json.writeStringField("anchor_source", t.anchorSource());
                json.writeNumberField("ratio", t.ratio());
                if (!Double.isNaN(t.goal())) {
                    json.writeStringField("goal", (t.atMost() ? "<= " : ">= ") + t.goal());
                    json.writeBooleanField("reached", t.reached());
                }
                json.writeEndObject();
            }
            json.writeEndArray();
            json.writeNumberField("seconds", r.seconds);
            json.writeEndObject();
        });
    }

    private static void stat(JsonGenerator json, String name, Stat s) throws IOException {
        json.writeObjectFieldStart(name);
        json.writeNumberField("median", s.median());
        json.writeNumberField("min", s.min());
        json.writeNumberField("max", s.max());
        json.writeNumberField("runs", s.runs());
        json.writeEndObject();
    }

    private static void array(JsonGenerator json, String name, double[] v) throws IOException {
        if (v != null) {
            json.writeArrayFieldStart(name);
            for (double x : v) {
                json.writeNumber(x);
            }
            json.writeEndArray();
        }
    }
}
