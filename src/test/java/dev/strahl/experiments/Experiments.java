package dev.strahl.experiments;

import dev.strahl.experiments.Charts.Series;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.RayTriangle;
import dev.strahl.image.Image;
import dev.strahl.image.Rgb;
import dev.strahl.io.ImageWriters;
import dev.strahl.io.SceneLoader;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Material;
import dev.strahl.scene.Scene;
import dev.strahl.scene.Transform;
import dev.strahl.testing.Meshes;
import dev.strahl.world.World;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SplittableRandom;
import jdk.jfr.Recording;
import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordedFrame;
import jdk.jfr.consumer.RecordingFile;
import org.joml.Vector3d;

/**
 * Re-runs the experiments of the talk strahl grew from (docs/experiments.md): renders every
 * picture of the page, measures every figure, draws the plots, and writes the figures to
 * {@code figures.txt}. Run by docs/experiments/run.sh; not a test (nothing here asserts), kept in
 * test scope so that JFreeChart stays out of the library's dependencies.
 *
 * <p>Arguments: the output directory (docs/experiments), the repository root, and optionally
 * {@code --quick} (smaller sample counts, for a try-out; the page's figures are from a full run)
 * and {@code --data DIR} (the shared meshes, for the bunny; without it the bunny is skipped).
 */
public final class Experiments {
    private final Path out;
    private final Path root;
    private final boolean quick;
    private final Path bunny;
    private final List<String> figures = new ArrayList<>();

    private Experiments(Path out, Path root, boolean quick, Path bunny) {
        this.out = out;
        this.root = root;
        this.quick = quick;
        this.bunny = bunny;
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args[0]);
        Path root = Path.of(args[1]);
        boolean quick = Arrays.asList(args).contains("--quick");
        int data = Arrays.asList(args).indexOf("--data");
        Path bunny = data >= 0 ? Path.of(args[data + 1], "meshes", "bunny", "bun_zipper.ply") : null;
        Files.createDirectories(out);
        Experiments e = new Experiments(out, root, quick, bunny != null && Files.isRegularFile(bunny) ? bunny : null);
        List<String> only = Arrays.stream(args).filter(a -> a.matches("e[1-9]")).toList();
        if (Arrays.asList(args).contains("--page-only")) {           // after editing page.md.in: the page from figures.txt
            Map<String, String> all = Page.read(out.resolve("figures.txt"));
            addTotal(all);
            scheduleChart(out, all);
            profileChart(out, all);
            Page.write(out.resolve("page.md.in"), all, root.resolve("docs").resolve("experiments.md"));
            return;
        }
        long start = System.nanoTime();
        e.warmUp();
        String[] names = {"e1", "e2", "e3", "e4", "e5", "e6", "e8", "e9"};
        for (String name : names) {
            if (!only.isEmpty() && !only.contains(name)) {
                continue;
            }
            long t0 = System.nanoTime();
            switch (name) {
                case "e1" -> e.intersection();
                case "e2" -> e.recursion();
                case "e3" -> e.softShadows();
                case "e4" -> e.globalIllumination();
                case "e5" -> e.convergence();           // experiments 5 and 7
                case "e6" -> e.hemisphere();
                case "e8" -> e.acceleration();
                case "e9" -> e.schedule();
                default -> throw new IllegalStateException(name);
            }
            e.figure(name + ".seconds", (System.nanoTime() - t0) * 1e-9);
            System.err.printf(Locale.ROOT, "experiments: %s done after %.0f s%n", name, (System.nanoTime() - start) * 1e-9);
        }
        e.figure("machine.processors", Runtime.getRuntime().availableProcessors());
        e.figure("machine.java", System.getProperty("java.version"));
        // The figures of a partial run replace those of the same experiments in figures.txt.
        Path file = out.resolve("figures.txt");
        Map<String, String> all = only.isEmpty() ? new LinkedHashMap<>() : Page.read(file);
        double seconds = (System.nanoTime() - start) * 1e-9;
        for (String f : e.figures) {
            int eq = f.indexOf(" = ");
            all.put(f.substring(0, eq), f.substring(eq + 3));
        }
        addTotal(all);
        List<String> lines = new ArrayList<>();
        all.forEach((k, v) -> lines.add(k + " = " + v));
        Files.write(file, lines);
        Page.write(out.resolve("page.md.in"), all, root.resolve("docs").resolve("experiments.md"));
        System.err.printf(Locale.ROOT, "experiments: wrote %s and docs/experiments.md after %.0f s%n", file, seconds);
    }

    // ---- helpers ------------------------------------------------------------------------------

    /** The experiments' time, whichever run measured each (the build and the warm-up add about three minutes). */
    private static void addTotal(Map<String, String> all) {
        double total = 0;
        for (var f : all.entrySet()) {
            if (f.getKey().matches("e[1-9]\\.seconds")) {
                total += Double.parseDouble(f.getValue());
            }
        }
        all.put("total.seconds", String.format(Locale.ROOT, "%.6g", total));
        all.put("total.minutes", String.valueOf((long) Math.ceil(total / 60)));
    }

    private void figure(String key, Object value) {
        String v = value instanceof Double d ? String.format(Locale.ROOT, "%.6g", d) : String.valueOf(value);
        figures.add(key + " = " + v);
        System.err.println("  " + key + " = " + v);
    }

    private Scene scene(String name) throws Exception {
        return SceneLoader.load(root.resolve("scenes").resolve(name));
    }

    record Run(Image image, RenderStats stats) {}

    private static Run render(Scene scene, RenderSettings s) throws InterruptedException {
        try (RenderJob job = RenderJob.start(scene, s)) {
            Image image = job.awaitCompletion();
            return new Run(image, job.awaitStats());
        }
    }

    private static RenderSettings settings(int size, int spp) {
        return RenderSettings.defaults().withSize(size, size).withSamplesPerPixel(spp);
    }

    private void picture(Run run, String name) throws IOException {
        ImageWriters.write(run.image(), out.resolve(name + ".png"));
    }

    /** RMSE of one render, from two renders with different seeds: E[(a - b)²] = 2 Var, so no reference image is needed. */
    private static double rmseOfPair(Image a, Image b) {
        float[] x = a.rgb(), y = b.rgb();
        double sum = 0;
        for (int i = 0; i < x.length; i++) {
            double d = x[i] - y[i];
            sum += d * d;
        }
        return Math.sqrt(sum / (2.0 * x.length));
    }

    /** The image with every value clamped to [0, 1], as a PNG shows it (before the sRGB curve). */
    private static Image clamped(Image img) {
        float[] v = img.rgb().clone();
        for (int i = 0; i < v.length; i++) {
            v[i] = Math.min(1, Math.max(0, v[i]));
        }
        return new Image(img.width(), img.height(), v);
    }

    private static double rmse(Image a, Image ref) {
        float[] x = a.rgb(), y = ref.rgb();
        double sum = 0;
        for (int i = 0; i < x.length; i++) {
            double d = x[i] - y[i];
            sum += d * d;
        }
        return Math.sqrt(sum / x.length);
    }

    /** Least-squares slope of log y over log x. */
    private static double logLogSlope(double[] x, double[] y) {
        int n = x.length;
        double mx = 0, my = 0;
        for (int i = 0; i < n; i++) {
            mx += Math.log(x[i]) / n;
            my += Math.log(y[i]) / n;
        }
        double sxy = 0, sxx = 0;
        for (int i = 0; i < n; i++) {
            sxy += (Math.log(x[i]) - mx) * (Math.log(y[i]) - my);
            sxx += (Math.log(x[i]) - mx) * (Math.log(x[i]) - mx);
        }
        return sxy / sxx;
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s.length % 2 == 1 ? s[s.length / 2] : 0.5 * (s[s.length / 2 - 1] + s[s.length / 2]);
    }

    private static Vector3d centre(dev.strahl.geometry.Aabb box) {
        return new Vector3d(0.5 * (box.minX + box.maxX), 0.5 * (box.minY + box.maxY), 0.5 * (box.minZ + box.maxZ));
    }

    private static double luminance(Image img) {
        double[] m = img.mean();
        return 0.2126 * m[0] + 0.7152 * m[1] + 0.0722 * m[2];
    }

    private void warmUp() throws Exception {
        render(scene("cornell-box.json"), settings(64, 32));
        render(scene("cornell-sphere.json"), settings(64, 32));
    }

    // ---- 1. intersection ---------------------------------------------------------------------

    private static final java.lang.management.ThreadMXBean CPU = java.lang.management.ManagementFactory.getThreadMXBean();

    /** CPU nanoseconds per ray–sphere and ray–triangle test (rays aimed near the primitive, about half hit), and the two roots of the sphere. */
    private void intersection() throws Exception {
        Scene sphereScene = scene("cornell-sphere.json");
        Geometry g = World.of(sphereScene).geometry();
        int sphere = g.triangleCount();                // the first sphere, after the triangles
        int triangle = 0;
        int rays = quick ? 1 << 20 : 1 << 22;
        figure("e1.rounds", rays);
        for (int[] prim : new int[][] {{sphere}, {triangle}}) {
            var box = new dev.strahl.geometry.Aabb();
            g.includeBounds(prim[0], box);
            Vector3d centre = centre(box);
            double size = box.diagonal();
            Ray[] pool = new Ray[4096];
            SplittableRandom random = new SplittableRandom(1);
            for (int i = 0; i < pool.length; i++) {
                Vector3d o = new Vector3d(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize().mul(4 * size).add(centre);
                Vector3d target = new Vector3d(random.nextDouble(-0.6, 0.6), random.nextDouble(-0.6, 0.6), random.nextDouble(-0.6, 0.6))
                        .mul(size).add(centre);
                pool[i] = new Ray().set(o, target.sub(o, new Vector3d()).normalize(), Double.POSITIVE_INFINITY);
            }
            Hit hit = new Hit();
            Ray ray = new Ray();
            RayTriangle test = new RayTriangle();
            float[] pos = g.positionArray();
            int[] tri = g.indexArray();
            byte[] flags = g.flagArray();
            boolean isSphere = prim[0] == sphere;
            long hits = 0;
            double best = Double.POSITIVE_INFINITY;
            for (int round = 0; round < 7; round++) {
                hits = 0;
                // CPU time of this thread, not wall time: on a shared machine the thread is not always running
                long t0 = CPU.getCurrentThreadCpuTime();
                for (int i = 0; i < rays; i++) {
                    Ray r = pool[i & 4095];
                    ray.set(r.o, r.d, Double.POSITIVE_INFINITY);
                    hit.reset();
                    // the sphere through Geometry; the triangle as the BVH's leaves run it: set up per ray, then tested
                    if (isSphere ? g.intersect(prim[0], ray, hit, false)
                            : test.prepare(ray).hit(pos, tri, flags, prim[0], ray.tMax, false)) {
                        hits++;
                    }
                }
                best = Math.min(best, (CPU.getCurrentThreadCpuTime() - t0) / (double) rays);
            }
            String what = prim[0] == sphere ? "sphere" : "triangle";
            figure("e1." + what + ".ns_per_test", best);
            figure("e1." + what + ".hit_fraction", hits / (double) rays);
        }
        // The two roots: from outside the sphere the nearer one, from its centre the farther one.
        double[] s = new double[4];
        var box = new dev.strahl.geometry.Aabb();
        g.includeBounds(sphere, box);
        Vector3d c = centre(box);
        double radius = box.extent(0) / 2;
        Ray ray = new Ray().set(new Vector3d(c).add(0, 0, 3 * radius), new Vector3d(0, 0, -1), Double.POSITIVE_INFINITY);
        Hit hit = new Hit().reset();
        g.intersect(sphere, ray, hit, false);
        s[0] = hit.t;
        ray = new Ray().set(c, new Vector3d(0, 0, -1), Double.POSITIVE_INFINITY);
        hit = new Hit().reset();
        g.intersect(sphere, ray, hit, false);
        s[1] = hit.t;
        figure("e1.sphere.radius", radius);
        figure("e1.sphere.t_from_outside_at_3r", s[0]);
        figure("e1.sphere.t_from_centre", s[1]);
        Run direct = render(sphereScene, settings(256, 16).withIntegrator(IntegratorKind.DIRECT));
        picture(direct, "e1-cornell-sphere-direct");
    }

    // ---- 2. recursive ray tracing --------------------------------------------------------------

    private void recursion() throws Exception {
        Scene scene = scene("cornell-sphere.json");
        int[] depths = {2, 3, 4, 5, 8, 16};
        Run[] runs = new Run[depths.length];
        for (int i = 0; i < depths.length; i++) {
            runs[i] = render(scene, settings(256, 16).withIntegrator(IntegratorKind.WHITTED).withMaxDepth(depths[i]));
            figure("e2.depth" + depths[i] + ".seconds", runs[i].stats().seconds());
            figure("e2.depth" + depths[i] + ".rays_per_sample", runs[i].stats().rays() / (double) runs[i].stats().samples());
        }
        double[] x = new double[depths.length - 1], y = new double[depths.length - 1];
        for (int i = 0; i < depths.length - 1; i++) {
            x[i] = depths[i];
            y[i] = rmse(runs[i].image(), runs[depths.length - 1].image());
            figure("e2.depth" + depths[i] + ".rmse_to_depth16", y[i]);
        }
        for (int i : new int[] {0, 1, 2, depths.length - 1}) {
            picture(runs[i], "e2-whitted-depth" + depths[i]);
        }
        Charts.logLog(out.resolve("e2-depth.png"), "Whitted ray tracing: what each level of recursion still adds",
                "maximum depth (path segments)", "RMSE against depth 16", List.of(new Series("cornell-sphere, 16 spp", x, y, false)));
    }

    // ---- 3. soft shadows ----------------------------------------------------------------------

    private void softShadows() throws Exception {
        Scene box = scene("cornell-box.json");
        Scene small = SceneLoader.load(out.resolve("scenes").resolve("cornell-small-light.json"));
        // Whitted: light sampling alone at diffuse hits, n shadow rays each (the direct integrator
        // adds one BSDF sample by MIS, whose noise n does not reduce); no delta surfaces here.
        RenderSettings direct = settings(256, 1).withIntegrator(IntegratorKind.WHITTED);
        Run hard = render(small, direct);
        picture(hard, "e3-hard-small-light");
        // The talk's first picture: Lambert × light, no shadow rays (the teaching option --shadows off).
        Run unshadowed = render(small, direct.withShadows(false));
        picture(unshadowed, "e3-no-shadows");
        for (var e : Map.of("hard", hard, "no_shadows", unshadowed).entrySet()) {
            figure("e3." + e.getKey() + ".mean_luminance", luminance(e.getValue().image()));
            figure("e3." + e.getKey() + ".rays_per_sample", e.getValue().stats().rays() / (double) e.getValue().stats().samples());
        }
        figure("e3.shadowed_share", 1 - luminance(hard.image()) / luminance(unshadowed.image()));
        for (int n : new int[] {1, 2, 100}) {
            Run run = render(box, direct.withLightSamples(n));
            picture(run, "e3-soft-" + n + "-light-samples");
            figure("e3.light_samples" + n + ".seconds", run.stats().seconds());
        }
        // Noise against shadow rays, one camera ray per pixel as in the talk (128²). Two errors:
        // (a) of the whole render, from pairs of seeds: the pixel position is random too;
        // (b) of the shadow rays alone: renders with the same seed share each pixel's position and
        //     their first shadow rays (the dimensions are laid out by construction), so against a
        //     render with N = 400 shadow rays, Var(mean_n - mean_N) = sigma^2 (1/n - 1/N).
        int[] counts = {1, 2, 4, 8, 16, 32, 100};
        int reference = 400;
        RenderSettings base = settings(128, 1).withIntegrator(IntegratorKind.WHITTED).withSeed(1);
        Image ref = render(box, base.withLightSamples(reference)).image();
        double[] x = new double[counts.length], y = new double[counts.length], pair = new double[counts.length];
        for (int i = 0; i < counts.length; i++) {
            RenderSettings s = base.withLightSamples(counts[i]);
            Image first = render(box, s).image(), second = render(box, s.withSeed(2)).image();
            x[i] = counts[i];
            pair[i] = rmseOfPair(first, second);
            y[i] = rmse(first, ref) / Math.sqrt(1 - counts[i] / (double) reference);
            figure("e3.light_samples" + counts[i] + ".rmse", pair[i]);
            figure("e3.light_samples" + counts[i] + ".rmse_shadow_rays", y[i]);
        }
        figure("e3.slope", logLogSlope(x, y));
        figure("e3.slope_whole_render", logLogSlope(x, pair));
        double[] ideal = new double[counts.length];
        for (int i = 0; i < counts.length; i++) {
            ideal[i] = y[0] / Math.sqrt(x[i]);
        }
        Charts.logLog(out.resolve("e3-light-samples.png"), "Soft shadows: noise against shadow rays per pixel", "shadow rays per pixel",
                "RMSE (1 camera ray per pixel)", List.of(new Series("the shadow rays' error", x, y, false),
                        new Series("the whole render's error", x, pair, false), new Series("N^-1/2", x, ideal, true)));
    }

    // ---- 4. global illumination ---------------------------------------------------------------

    private void globalIllumination() throws Exception {
        Scene scene = scene("cornell-sphere.json");
        Run whitted = render(scene, settings(256, 16).withIntegrator(IntegratorKind.WHITTED));
        Run path = render(scene, settings(256, quick ? 64 : 256));
        Run photon = render(scene, settings(256, quick ? 16 : 64).withIntegrator(IntegratorKind.PHOTON));
        Run pathShort = render(scene, settings(256, 16));
        picture(whitted, "e4-whitted");
        picture(path, "e4-path");
        picture(photon, "e4-photon");
        picture(pathShort, "e4-path-16spp");
        for (var e : Map.of("whitted", whitted, "path", path, "photon", photon, "path16", pathShort).entrySet()) {
            figure("e4." + e.getKey() + ".seconds", e.getValue().stats().seconds());
            figure("e4." + e.getKey() + ".spp", e.getValue().stats().samplesPerPixel());
            figure("e4." + e.getKey() + ".mean_luminance", luminance(e.getValue().image()));
        }
        figure("e4.whitted_share_of_path_luminance", luminance(whitted.image()) / luminance(path.image()));
        figure("e4.path_over_whitted_seconds", path.stats().seconds() / whitted.stats().seconds());
    }

    // ---- 5 and 7. Monte Carlo convergence -------------------------------------------------------

    private void convergence() throws Exception {
        Scene box = scene("cornell-box.json");
        int size = quick ? 24 : 32;
        int[] spps = quick ? new int[] {8, 32, 128, 512} : new int[] {8, 32, 128, 512, 2048, 8192};
        List<Series> series = new ArrayList<>();
        for (String sampler : new String[] {"stratified", "independent"}) {
            System.setProperty("strahl.sampler", sampler);        // read by each new render job
            double[] x = new double[spps.length], y = new double[spps.length], yc = new double[spps.length];
            for (int i = 0; i < spps.length; i++) {
                RenderSettings s = settings(size, spps[i]);
                Run a = render(box, s.withSeed(1));
                Run b = render(box, s.withSeed(2));
                x[i] = spps[i];
                y[i] = rmseOfPair(a.image(), b.image());
                figure("e5." + sampler + ".spp" + spps[i] + ".rmse", y[i]);
                figure("e5." + sampler + ".spp" + spps[i] + ".rmse_clamped", rmseOfPair(clamped(a.image()), clamped(b.image())));
                yc[i] = rmseOfPair(clamped(a.image()), clamped(b.image()));
                figure("e5." + sampler + ".spp" + spps[i] + ".seconds", a.stats().seconds());
            }
            double slope = logLogSlope(x, y);
            figure("e5." + sampler + ".slope", slope);
            figure("e5." + sampler + ".rmse_ratio_per_4x", Math.pow(4, slope));
            double slopeClamped = logLogSlope(x, yc);
            figure("e5." + sampler + ".slope_clamped", slopeClamped);
            figure("e5." + sampler + ".rmse_ratio_per_4x_clamped", Math.pow(4, slopeClamped));
            series.add(new Series(sampler + " (slope " + String.format(Locale.ROOT, "%.3f", slope) + ")", x, y, false));
        }
        System.clearProperty("strahl.sampler");
        double[] x = series.get(0).x(), ideal = new double[x.length];
        for (int i = 0; i < x.length; i++) {
            ideal[i] = series.get(1).y()[0] * Math.sqrt(x[0] / x[i]);
        }
        series.add(new Series("N^-1/2", x, ideal, true));
        Charts.logLog(out.resolve("e5-convergence.png"), "Path tracing, Cornell Box: RMSE against samples per pixel", "samples per pixel",
                "RMSE (from pairs of seeds)", series);
        // The talk's three pictures.
        for (int spp : quick ? new int[] {10, 230} : new int[] {10, 230, 2000}) {
            Run run = render(box, settings(64, spp));
            picture(run, "e7-path-" + spp + "spp");
            figure("e7.spp" + spp + ".seconds", run.stats().seconds());
        }
    }

    // ---- 6. cosine against uniform --------------------------------------------------------------

    private void hemisphere() throws Exception {
        Scene box = scene("cornell-box.json");
        double[] rmses = new double[2];
        for (HemisphereSampling h : HemisphereSampling.values()) {
            String name = h.name().toLowerCase(Locale.ROOT);
            RenderSettings s = settings(64, 100).withHemisphere(h);
            Run a = render(box, s.withSeed(1));
            Run b = render(box, s.withSeed(2));
            picture(a, "e6-" + name + "-100spp");
            double rmse = rmseOfPair(a.image(), b.image());
            double seconds = 0.5 * (a.stats().seconds() + b.stats().seconds());
            figure("e6." + name + ".rmse", rmse);
            figure("e6." + name + ".seconds", seconds);
            figure("e6." + name + ".efficiency", 1 / (rmse * rmse * seconds));
            rmses[h.ordinal()] = rmse;
        }
        figure("e6.uniform_over_cosine", rmses[1] / rmses[0]);
        figure("e6.uniform_over_cosine_squared", (rmses[1] / rmses[0]) * (rmses[1] / rmses[0]));
    }

    // ---- 8. acceleration and profiles -----------------------------------------------------------

    private void acceleration() throws Exception {
        Scene box = scene("cornell-box.json");
        Map<String, Map<String, Double>> shares = new LinkedHashMap<>();
        Map<String, Map<String, Double>> speed = new LinkedHashMap<>();
        timeAccel("cornell", box, settings(128, 16), settings(128, 16), speed);
        profile("Cornell Box, BVH", box, settings(128, 64), shares);
        profile("Cornell Box, none", box, settings(128, 32).withBruteForce(true), shares);
        if (bunny != null) {
            Scene b = SceneLoader.load(bunny);
            figure("e8.bunny.triangles", World.of(b).geometry().triangleCount());
            timeAccel("bunny", b, settings(128, 16), settings(48, 1), speed);
            profile("bunny, BVH", b, settings(256, 256), shares);
            profile("bunny, none", b, settings(48, 2).withBruteForce(true), shares);
        }
        figure("e8.cornell.triangles", World.of(box).geometry().triangleCount());
        Charts.bars(out.resolve("e8-accel.png"), "Rays per second: BVH against every ray against every primitive", "rays per second (log)",
                speed, false, true);
        Charts.bars(out.resolve("e8-profile.png"), PROFILE_TITLE, "share of samples", shares, true, false);
        culling();
    }

    /**
     * Rays per second with the BVH (at {@code s}) and without (at {@code brute}, smaller where
     * brute force is slow: rays per second hardly depend on the image size), in three paired
     * runs; the first pair at the same settings also checks that the images are the same bits.
     */
    private void timeAccel(String name, Scene scene, RenderSettings s, RenderSettings brute, Map<String, Map<String, Double>> speed)
            throws Exception {
        figure("e8." + name + ".bits_identical", Arrays.equals(render(scene, brute).image().rgb(),
                render(scene, brute.withBruteForce(true)).image().rgb()));
        double[] bvh = new double[3], none = new double[3];
        double bvhRays = 0, noneRays = 0;
        for (int i = 0; i < 3; i++) {
            Run a = render(scene, s);
            Run b = render(scene, brute.withBruteForce(true));
            bvh[i] = a.stats().raysPerSecond();
            none[i] = b.stats().raysPerSecond();
            bvhRays = a.stats().seconds();
            noneRays = b.stats().seconds();
        }
        figure("e8." + name + ".bvh.rays_per_second", median(bvh));
        figure("e8." + name + ".none.rays_per_second", median(none));
        figure("e8." + name + ".bvh.seconds", bvhRays);
        figure("e8." + name + ".none.seconds", noneRays);
        figure("e8." + name + ".speedup", median(bvh) / median(none));
        speed.computeIfAbsent("BVH", k -> new LinkedHashMap<>()).put(name, median(bvh));
        speed.computeIfAbsent("none", k -> new LinkedHashMap<>()).put(name, median(none));
    }

    /**
     * Renders under JFR and attributes each execution sample of a render thread to the first
     * strahl method on its stack (so that a JDK method such as Math.sqrt counts for its caller):
     * intersection (the BVH, the triangle and sphere tests), shading (surface data, BSDFs),
     * sampling (the samplers and warps), lights (light sampling and next-event estimation apart
     * from its shadow-ray tests) and the rest (integrator loops, camera, film).
     */
    private void profile(String label, Scene scene, RenderSettings s, Map<String, Map<String, Double>> shares) throws Exception {
        Path jfr = Files.createTempFile("strahl-experiments", ".jfr");
        Map<String, Integer> counts = new LinkedHashMap<>();
        for (String k : new String[] {"intersection", "shading", "sampling", "lights", "integrator, camera, film"}) {
            counts.put(k, 0);
        }
        try (Recording recording = new Recording()) {
            recording.enable("jdk.ExecutionSample").withPeriod(Duration.ofMillis(10));
            recording.start();
            render(scene, s);
            recording.stop();
            recording.dump(jfr);
        }
        int total = 0;
        for (RecordedEvent e : RecordingFile.readAllEvents(jfr)) {
            if (!e.getEventType().getName().equals("jdk.ExecutionSample") || e.getThread("sampledThread") == null
                    || e.getThread("sampledThread").getJavaName() == null
                    || !e.getThread("sampledThread").getJavaName().startsWith("strahl-render-") || e.getStackTrace() == null) {
                continue;
            }
            String kind = "integrator, camera, film";
            for (RecordedFrame f : e.getStackTrace().getFrames()) {
                String type = f.getMethod().getType().getName();
                if (!type.startsWith("dev.strahl.")) {
                    continue;
                }
                kind = classify(type, f.getMethod().getName());
                break;
            }
            counts.merge(kind, 1, Integer::sum);
            total++;
        }
        Files.deleteIfExists(jfr);
        String key = label.replaceAll("[^A-Za-z]+", "_").toLowerCase(Locale.ROOT);
        figure("e8.profile." + key + ".samples", total);
        for (var c : counts.entrySet()) {
            double share = total > 0 ? c.getValue() / (double) total : 0;
            figure("e8.profile." + key + "." + c.getKey().replaceAll("[^a-z]+", "_"), share);
            shares.computeIfAbsent(c.getKey(), k -> new LinkedHashMap<>()).put(label, share);
        }
    }

    private static String classify(String type, String method) {
        if (type.startsWith("dev.strahl.accel.") || type.equals("dev.strahl.geometry.RayTriangle")
                || type.equals("dev.strahl.geometry.Intersections")
                || (type.equals("dev.strahl.geometry.Geometry") && (method.equals("intersect") || method.equals("occludes")))) {
            return "intersection";
        }
        if (type.startsWith("dev.strahl.material.") || type.equals("dev.strahl.integrator.Shading")
                || type.startsWith("dev.strahl.geometry.") || type.startsWith("dev.strahl.math.Frame")) {
            return "shading";
        }
        if (type.startsWith("dev.strahl.sampling.")) {
            return "sampling";
        }
        if (type.startsWith("dev.strahl.light.") || type.equals("dev.strahl.integrator.DirectLight")) {
            return "lights";
        }
        return "integrator, camera, film";
    }

    /** Back-face culling on closed meshes: a grid of closed icospheres lit by the environment. */
    private void culling() throws Exception {
        Scene.Builder b = Scene.builder();
        Material grey = Material.diffuse("grey", new Rgb(0.7, 0.7, 0.7));
        var sphere = Meshes.icosphere(4, 0.4, false);
        for (int i = 0; i < 4; i++) {
            for (int j = 0; j < 4; j++) {
                b.addMesh(sphere, grey, Transform.translation(i - 1.5, j - 1.5, (i + j) % 2 * 0.5));
            }
        }
        b.camera(new Camera(new Vector3d(0, 0, 6), new Vector3d(0, 0, 0), new Vector3d(0, 1, 0), 45));
        b.environment(new Rgb(1, 1, 1));
        Scene scene = b.build();
        RenderSettings s = settings(96, 16);
        double[] off = new double[3], on = new double[3];
        for (int i = 0; i < 3; i++) {
            off[i] = render(scene, s).stats().seconds();
            Run culled = render(scene, s.withCullBackFaces(true));
            on[i] = culled.stats().seconds();
            if (i == 0) {
                picture(culled, "e8-icospheres-culled");
            }
        }
        figure("e8.culling.triangles", World.of(scene).geometry().triangleCount());
        figure("e8.culling.triangles.per", sphere.triangleCount());
        figure("e8.culling.off.seconds", median(off));
        figure("e8.culling.on.seconds", median(on));
        figure("e8.culling.speedup", median(off) / median(on));
    }

    // ---- 9. threads: stripes against tiles ------------------------------------------------------

    private void schedule() throws Exception {
        Scene box = scene("cornell-box.json");
        for (int threads : new int[] {2, 4}) {
            for (boolean sc : new boolean[] {false, true}) {
                double[] seconds = new double[3], idle = new double[3];
                for (int i = 0; i < 3; i++) {
                    Run run = render(box, settings(256, 16).withThreads(threads).withStripes(sc));
                    seconds[i] = run.stats().seconds();
                    idle[i] = run.stats().threadIdleSeconds();
                }
                String key = "e9." + (sc ? "stripes" : "tiles") + ".threads" + threads;
                figure(key + ".seconds", median(seconds));
                figure(key + ".idle_seconds", median(idle));
                figure(key + ".idle_share", median(idle) / (threads * median(seconds)));
            }
        }
        Map<String, String> measured = new LinkedHashMap<>();
        for (String f : figures) {
            measured.put(f.substring(0, f.indexOf(" = ")), f.substring(f.indexOf(" = ") + 3));
        }
        scheduleChart(out, measured);
    }

    private static final String PROFILE_TITLE = "Where a frame's time goes (JFR execution samples of the render threads)";
    private static final String[] PROFILE_RUNS = {"Cornell Box, BVH", "Cornell Box, none", "bunny, BVH", "bunny, none"};
    private static final String[] PROFILE_PARTS = {"intersection", "shading", "sampling", "lights", "integrator, camera, film"};

    /** The time-share plot of experiment 8, from its figures (so that --page-only can redraw it). */
    static void profileChart(Path out, Map<String, String> figures) throws IOException {
        Map<String, Map<String, Double>> shares = new LinkedHashMap<>();
        for (String part : PROFILE_PARTS) {
            for (String run : PROFILE_RUNS) {
                String key = "e8.profile." + run.replaceAll("[^A-Za-z]+", "_").toLowerCase(Locale.ROOT) + "." + part.replaceAll("[^a-z]+", "_");
                if (figures.containsKey(key)) {
                    shares.computeIfAbsent(part, k -> new LinkedHashMap<>()).put(run, Double.parseDouble(figures.get(key)));
                }
            }
        }
        if (!shares.isEmpty()) {
            Charts.bars(out.resolve("e8-profile.png"), PROFILE_TITLE, "share of samples", shares, true, false);
        }
    }

    /** The plot of experiment 9, from its figures (so that --page-only can redraw it). */
    static void scheduleChart(Path out, Map<String, String> figures) throws IOException {
        Map<String, Map<String, Double>> bars = new LinkedHashMap<>();
        for (int threads : new int[] {2, 4}) {
            for (boolean sc : new boolean[] {false, true}) {
                String key = "e9." + (sc ? "stripes" : "tiles") + ".threads" + threads;
                if (!figures.containsKey(key + ".seconds")) {
                    return;
                }
                String column = (sc ? "stripes" : "tiles") + ", " + threads + " threads";
                bars.computeIfAbsent("render time (s)", k -> new LinkedHashMap<>()).put(column, Double.parseDouble(figures.get(key + ".seconds")));
                bars.computeIfAbsent("idle thread time, summed (s)", k -> new LinkedHashMap<>())
                        .put(column, Double.parseDouble(figures.get(key + ".idle_seconds")));
            }
        }
        Charts.bars(out.resolve("e9-schedule.png"), "Cornell Box 256², 16 spp: stripes against tiles", "seconds", bars, false, false);
    }
}
