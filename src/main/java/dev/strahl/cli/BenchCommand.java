package dev.strahl.cli;

import dev.strahl.bench.BenchAnchors;
import dev.strahl.bench.BenchMeshes;
import dev.strahl.io.mesh.MeshFiles;
import dev.strahl.bench.BenchRays;
import dev.strahl.bench.BenchProgress;
import dev.strahl.bench.BenchReport;
import dev.strahl.bench.BenchResults;
import dev.strahl.accel.Bvh;
import dev.strahl.scene.Camera;
import dev.strahl.world.World;
import dev.strahl.image.Image;
import dev.strahl.geometry.Geometry;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.io.SceneLoader;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code strahl bench}: the figures every performance claim of the project cites. After a
 * warm-up, the median (and min/max) of several runs of: the Cornell Box (512², unbounded depth,
 * path tracer) in samples/s and rays/s; per mesh the BVH build, its bytes per triangle and
 * closest-hit (camera and incoherent rays) and any-hit (shadow rays) rates; on 1 and all
 * threads. Each benchmark checks its own result (the Cornell image's mean against the
 * reference's, rays against a brute-force loop on a subset, equal checksums on every run), so
 * that a broken fast path cannot win. A table on stdout, JSON with {@code --json}.
 */
@Command(name = "bench",
        mixinStandardHelpOptions = true,
        abbreviateSynopsis = true,
        versionProvider = Main.Version.class,
        description = {"Measures render and ray tracing speed: the Cornell Box in samples/s, and per mesh the BVH build,",
            "bytes per triangle and ray rates, on 1 and all threads; checks every result; prints a table."},
        sortOptions = false)
final class BenchCommand implements Callable<Integer> {
    /** Whole-image mean (R, G, B) of the Mitsuba reference of the Cornell Box, 512², unbounded depth (src/test/resources/golden/README.md). */
    static final double[] CORNELL_REFERENCE_MEAN = {0.18660, 0.12082, 0.03439};
    /** How far the Cornell image's mean may stray from the reference's: far above the noise of a few spp over 512² pixels. */
    static final double CORNELL_MEAN_TOLERANCE = 0.02;
    /** The scanned meshes under {@code --data DIR/meshes}: research-only, never in the repository. */
    static final List<String> STANFORD_MESHES = List.of("bunny/bun_zipper.ply", "dragon/dragon_100k.ply", "bunny/bunny_midpoint-sub2_1.1M.ply");

    @Spec
    CommandSpec spec;

    @ArgGroup(validate = false, heading = "%nRuns:%n")
    Runs measure = new Runs();

    @ArgGroup(validate = false, heading = "%nScenes and meshes:%n")
    Inputs inputs = new Inputs();

    @ArgGroup(validate = false, heading = "%nResults:%n")
    Results results = new Results();

    /** How much is measured, and on how many threads. */
    static final class Runs {
        @Option(names = "--quick", description = "One run of each, with fewer rays: a quick check, not for citing.")
        boolean quick;

        @Option(names = "--runs", defaultValue = "5", description = "Timed runs of each benchmark after the warm-up (default: ${DEFAULT-VALUE}; --quick: 1).")
        int runs;

        @Option(names = "--threads", split = ",", paramLabel = "N[,N...]", description = "Thread counts to measure (default: 1 and all processors).")
        List<Integer> threads;

        @Option(names = "--rays", paramLabel = "N", description = "Rays per ray set (default: 2^20; --quick: 2^17).")
        Integer raysPerSet;
    }

    /** What is measured: the Cornell Box and the meshes. */
    static final class Inputs {
        @Option(names = "--cornell", defaultValue = "scenes/cornell-box.json", paramLabel = "FILE", description = "The Cornell Box scene (default: ${DEFAULT-VALUE}).")
        Path cornell;

        @Option(names = "--no-cornell", description = "Skip the Cornell Box render.")
        boolean noCornell;

        @Option(names = "--data", paramLabel = "DIR", description = {"Also benchmark the Stanford meshes in DIR/meshes (bunny/bun_zipper.ply,",
            "dragon/dragon_100k.ply, bunny/bunny_midpoint-sub2_1.1M.ply), where present: research-only data, not part of strahl."})
        Path data;

        @Option(names = "--mesh", paramLabel = "FILE", description = "Benchmark these mesh files instead of the generated meshes (repeatable).")
        List<Path> meshes;
    }

    /** Where the results go and what they are compared with. */
    static final class Results {
        @Option(names = "--json", paramLabel = "FILE", description = "Also write the results as JSON.")
        Path json;

        @Option(names = "--anchors", paramLabel = "FILE", description = {"Compare with the anchor figures of this JSON file (written by docs/bench/anchors.py,",
            "measured side by side) instead of the built-in constants of an earlier machine."})
        Path anchors;

        @Option(names = "--export-rays", paramLabel = "DIR", description = {"Write each mesh's triangles and ray sets to DIR for docs/bench/anchors.py",
            "(Embree on the same rays) and stop: nothing is timed."})
        Path exportRays;
    }

    @ArgGroup(validate = false, heading = "%nExecution:%n")
    SimdOption execution = new SimdOption();

    private BenchProgress progress;

    @Override
    public Integer call() {
        try (SimdOption.Scope kernel = execution.apply()) {
            return measure();
        }
    }

    private Integer measure() {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter out = spec.commandLine().getOut();
        long start = System.nanoTime();
        int timedRuns = measure.quick ? 1 : measure.runs;
        if (timedRuns < 1) {
            err.println("strahl: --runs must be at least 1, got " + measure.runs);
            return 2;
        }
        TreeSet<Integer> counts = new TreeSet<>(measure.threads != null ? measure.threads : List.of(1, Runtime.getRuntime().availableProcessors()));
        if (counts.first() < 1) {
            err.println("strahl: --threads must be positive, got " + counts.first());
            return 2;
        }
        List<Path> meshFiles = new ArrayList<>(inputs.meshes != null ? inputs.meshes : List.of());
        if (inputs.data != null) {
            for (String name : STANFORD_MESHES) {
                Path file = inputs.data.resolve("meshes").resolve(name);
                if (java.nio.file.Files.isRegularFile(file)) {
                    meshFiles.add(file);
                }
            }
        }
        BenchResults r = BenchReport.machine(measure.quick, timedRuns);
        r.raysPerSet = measure.raysPerSet != null ? measure.raysPerSet : measure.quick ? 1 << 17 : 1 << 20;
        if (r.raysPerSet < 1) {
            err.println("strahl: --rays must be positive, got " + r.raysPerSet);
            return 2;
        }
        if (results.anchors != null) {
            try {
                r.anchors = BenchAnchors.read(results.anchors);
            } catch (IOException e) {
                err.println("strahl: --anchors " + e.getMessage());
                return 2;
            }
        }
        if (results.exportRays != null && !java.nio.file.Files.isDirectory(results.exportRays)) {
            err.println("strahl: --export-rays " + results.exportRays + ": not a directory");
            return 2;
        }
        progress = new BenchProgress(System.err, Terminal.isStderrTerminal());
        if (results.exportRays == null) {
            // Timed runs are of the kernel the report names: the SIMD one once C2 has compiled it, not the scalar twin meanwhile.
            progress.step("compiling the SIMD kernel");
            try {
                r.simdWarmUpSeconds = BenchReport.awaitSimd();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return 1;
            }
        }
        ExecutorService pool = Executors.newFixedThreadPool(counts.last(), t -> {
            Thread thread = new Thread(t, "strahl-bench");
            thread.setDaemon(true);
            return thread;
        });
        List<String> failures = new ArrayList<>();
        try {
            Scene box = null;
            if (!inputs.noCornell || inputs.meshes == null) {
                box = SceneLoader.load(inputs.cornell);
            }
            if (!inputs.noCornell && results.exportRays == null) {
                cornell(box, counts, timedRuns, r, failures);
            }
            List<MeshSet> sets = new ArrayList<>();
            if (inputs.meshes == null && box != null) {
                sets.add(new MeshSet("cornell-box", inputs.cornell.toString(), box, 0));
            }
            if (inputs.meshes == null) {
                for (BenchMeshes.Generated generated : BenchMeshes.defaults()) {
                    progress.step("generating " + generated.name());
                    long t0 = System.nanoTime();
                    Scene s = Scene.builder().addMesh(generated.mesh().get(), MeshFiles.DEFAULT_MATERIAL).build();
                    sets.add(new MeshSet(generated.name(), generated.description(), s, seconds(t0) - World.of(s).bvhBuildSeconds()));
                }
            }
            for (Path file : meshFiles) {
                progress.step("loading " + file.getFileName());
                try {
                    long t0 = System.nanoTime();
                    Scene s = SceneLoader.load(file);
                    sets.add(new MeshSet(name(file), file.toString(), s, seconds(t0) - World.of(s).bvhBuildSeconds()));
                } catch (SceneException e) {
                    r.skipped.add(name(file) + ": " + e.getMessage());
                }
            }
            for (MeshSet set : sets) {
                mesh(set, counts, timedRuns, pool, r, failures);
            }
        } catch (SceneException e) {
            progress.done();
            err.println("strahl: " + e.getMessage());
            return 2;
        } catch (IOException e) {
            progress.done();
            err.println("strahl: cannot write to " + results.exportRays + ": " + e.getMessage());
            return 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            err.println("strahl: interrupted");
            return 1;
        } finally {
            pool.shutdownNow();
        }
        progress.done();
        if (results.exportRays != null) {
            out.printf("wrote the triangles and rays of %d mesh%s to %s%n", r.meshes.size(), r.meshes.size() == 1 ? "" : "es", results.exportRays);
            out.flush();
            return 0;
        }
        r.seconds = (System.nanoTime() - start) * 1e-9;
        BenchReport.targets(r, counts.first(), counts.last());
        BenchReport.printTable(out, r);
        out.flush();
        if (results.json != null) {
            try {
                BenchReport.writeJson(results.json, r);
            } catch (IOException e) {
                err.println("strahl: cannot write " + results.json + ": " + e.getMessage());
                return 1;
            }
        }
        for (String f : failures) {
            err.println("strahl: check failed: " + f);
        }
        return failures.isEmpty() ? 0 : 1;
    }

    /** A mesh to measure: its name in the results, where it came from (a file or how it was generated), the scene, its load time. */
    private record MeshSet(String name, String source, Scene scene, double loadSeconds) {}

    private static double seconds(long since) {
        return (System.nanoTime() - since) * 1e-9;
    }

    private static String name(Path file) {
        String n = file.getFileName().toString();
        int dot = n.lastIndexOf('.');
        return dot > 0 ? n.substring(0, dot) : n;
    }

    /** The Cornell Box at 512², unbounded depth: samples/s and rays/s per thread count; the image mean checked. */
    private void cornell(Scene box, TreeSet<Integer> counts, int timedRuns, BenchResults r, List<String> failures)
            throws InterruptedException {
        int spp = measure.quick ? 1 : 8;
        r.cornellScene = inputs.cornell.toString();
        r.cornellSpp = spp;
        RenderSettings base = RenderSettings.defaults().withSize(512, 512).withSamplesPerPixel(spp).withSamplesPerPass(spp);
        progress.step("Cornell Box: warm-up");
        render(box, base.withThreads(counts.last()).withSamplesPerPixel(measure.quick ? 1 : 4));
        for (int t : counts) {
            double[] sps = new double[timedRuns], rps = new double[timedRuns];
            long rays = 0, samples = 0;
            for (int run = 0; run < timedRuns; run++) {
                progress.step(String.format("Cornell Box: %d thread%s, run %d/%d", t, t == 1 ? "" : "s", run + 1, timedRuns));
                RenderJob job = RenderJob.start(box, base.withThreads(t).withSeed(run));
                RenderStats stats;
                try (job) {
                    stats = job.awaitStats();
                }
                sps[run] = stats.samplesPerSecond();
                rps[run] = stats.raysPerSecond();
                rays += stats.rays();
                samples += stats.samples();
                if (r.cornellMean == null) {
                    r.cornellMean = job.snapshot().mean();
                }
            }
            r.cornell.add(new BenchResults.Render(t, BenchResults.Stat.of(sps), BenchResults.Stat.of(rps), (double) rays / samples));
        }
        // The viewer's preview while the camera moves: 128×128 at 1 spp per frame, one render job each.
        RenderSettings preview = base.withSize(128, 128).withSamplesPerPixel(1).withSamplesPerPass(1).withThreads(counts.last());
        int frames = measure.quick ? 10 : 60;
        double[] fps = new double[timedRuns];
        for (int run = 0; run < timedRuns; run++) {
            progress.step(String.format("Cornell Box: viewer preview frames, run %d/%d", run + 1, timedRuns));
            long t0 = System.nanoTime();
            for (int f = 0; f < frames; f++) {
                render(box, preview.withSeed(f));
            }
            fps[run] = frames / ((System.nanoTime() - t0) * 1e-9);
        }
        r.previewFps = BenchResults.Stat.of(fps);
        r.cornellReferenceMean = CORNELL_REFERENCE_MEAN.clone();
        for (int c = 0; c < 3; c++) {
            double rel = Math.abs(r.cornellMean[c] / CORNELL_REFERENCE_MEAN[c] - 1);
            if (!(rel <= CORNELL_MEAN_TOLERANCE)) {
                r.cornellCheck = String.format(java.util.Locale.ROOT, "image mean %s is %.1f %% off the reference's %s in channel %d",
                        java.util.Arrays.toString(r.cornellMean), 100 * rel, java.util.Arrays.toString(CORNELL_REFERENCE_MEAN), c);
                failures.add("Cornell Box: " + r.cornellCheck);
                return;
            }
        }
        r.cornellCheck = "passed";
    }

    private static Image render(Scene scene, RenderSettings settings) throws InterruptedException {
        try (RenderJob job = RenderJob.start(scene, settings)) {
            job.awaitStats();
            return job.snapshot();
        }
    }

    /** The three ray sets of a mesh; {@code --export-rays} writes exactly these. */
    private static List<BenchRays.RaySet> raySets(Scene scene, Geometry g, int n) {
        Camera camera = scene.camera();         // the scene file's, or one framing a mesh from +Z
        int side = (int) Math.max(1, Math.min(512, Math.sqrt(n / 4.0)));
        return List.of(BenchRays.primary(camera, side, side, 4, 1), BenchRays.incoherent(g.bounds(), n, 2), BenchRays.shadow(g, n, 3));
    }

    /** One mesh: BVH builds, memory, then each ray set checked against brute force and timed per thread count. */
    private void mesh(MeshSet mesh, TreeSet<Integer> counts, int timedRuns, ExecutorService pool, BenchResults r, List<String> failures)
            throws InterruptedException, IOException {
        String name = mesh.name();
        Scene scene = mesh.scene();
        Geometry g = World.of(scene).geometry();
        if (results.exportRays != null) {
            progress.step(name + ": writing rays");
            BenchRays.export(results.exportRays, name, mesh.source(), g, raySets(scene, g, r.raysPerSet));
            r.meshes.add(new BenchResults.Mesh(name, mesh.source(), g.triangleCount(), mesh.loadSeconds(), BenchResults.Stat.of(new double[] {0}), 0,
                    List.of(), "exported"));
            return;
        }
        double[] build = new double[timedRuns];
        Bvh bvh = null;
        progress.step(name + ": BVH build, warm-up");
        Bvh.build(g);
        for (int run = 0; run < timedRuns; run++) {
            progress.step(String.format("%s: BVH build, run %d/%d", name, run + 1, timedRuns));
            long t0 = System.nanoTime();
            bvh = Bvh.build(g);
            build[run] = (System.nanoTime() - t0) * 1e-9;
        }
        double bytes = (double) (bvh.geometry().byteSize() + bvh.byteSize()) / g.primitiveCount();

        progress.step(name + ": making rays");
        List<BenchRays.RaySet> sets = raySets(scene, g, r.raysPerSet);
        String check = "passed";
        int samples = (int) Math.max(16, Math.min(512, (1L << 24) / g.primitiveCount()));
        List<BenchResults.Rays> rays = new ArrayList<>();
        for (BenchRays.RaySet set : sets) {
            progress.step(name + ": " + set.name() + " rays, brute-force check of " + samples);
            String problem = BenchRays.check(bvh, set, samples);
            if (problem != null) {
                check = problem;
                failures.add(name + ": " + problem);
            }
            BenchRays.trace(bvh, set, counts.last(), pool);                          // warm-up
            BenchRays.Result reference = null;
            for (int t : counts) {
                double[] rate = new double[timedRuns], cpuRate = new double[timedRuns];
                for (int run = 0; run < timedRuns; run++) {
                    progress.step(String.format("%s: %s rays, %d thread%s, run %d/%d", name, set.name(), t, t == 1 ? "" : "s", run + 1, timedRuns));
                    BenchRays.Result res = BenchRays.trace(bvh, set, t, pool);
                    rate[run] = set.count() / res.seconds();
                    cpuRate[run] = set.count() / res.cpuSeconds();          // per core: all threads' CPU time
                    if (reference == null) {
                        reference = res;
                    } else if (res.hits() != reference.hits() || res.checksum() != reference.checksum()) {
                        check = set.name() + " rays: checksum differs between runs or thread counts";
                        failures.add(name + ": " + check);
                    }
                }
                rays.add(new BenchResults.Rays(set.name(), t, BenchResults.Stat.of(rate), reference.hits(), set.count(), BenchResults.Stat.of(cpuRate)));
            }
        }
        r.meshes.add(new BenchResults.Mesh(name, mesh.source(), g.triangleCount(), mesh.loadSeconds(), BenchResults.Stat.of(build), bytes, rays, check));
    }
}
