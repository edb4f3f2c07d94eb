package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.io.SceneLoader;
import dev.strahl.render.RenderCluster;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.scene.Scene;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * Render clusters with real members on loopback: workers are child JVMs ({@code strahl worker},
 * so that one can be killed), on free ports the test picks, in a cluster of a name of their own;
 * the coordinator is this JVM (the command line in-process, or the library API) or a child. Every
 * cluster image is compared byte for byte with the local render of the same scene and settings.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class ClusterTest {
    private static final String SCENE = Path.of("scenes", "cornell-sphere.json").toAbsolutePath().toString();
    private static final String[] SIZE = {"--width", "96", "--height", "64", "--threads", "1", "--seed", "3"};
    private final String name = "test-" + UUID.randomUUID().toString().substring(0, 8);
    private final List<Worker> started = new ArrayList<>();
    private Worker first;

    private Path dir;

    /** A worker JVM and its stderr. */
    record Worker(Process process, int port, Path log) {
        String text() throws IOException {
            return Files.readString(log, StandardCharsets.UTF_8);
        }

        void await(String pattern, int seconds) throws Exception {
            Pattern p = Pattern.compile(pattern);
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
            while (!p.matcher(text()).find()) {
                assertThat(process.isAlive()).as("worker alive; its log: " + text()).isTrue();
                assertThat(System.nanoTime()).as("waiting for /" + pattern + "/ in: " + text()).isLessThan(deadline);
                Thread.sleep(50);
            }
        }

        /** Units the worker says it rendered for its jobs so far (from its "finished: N units" lines). */
        int unitsRendered() throws IOException {
            Matcher m = Pattern.compile("finished: (\\d+) units rendered here").matcher(text());
            int n = 0;
            while (m.find()) {
                n += Integer.parseInt(m.group(1));
            }
            return n;
        }
    }

    @BeforeAll
    void firstWorker(@TempDir Path tmp) throws Exception {
        dir = tmp;
        first = worker("w1");
        first.await("joined cluster", 60);
    }

    @AfterAll
    void stopWorkers() throws InterruptedException {
        for (Worker w : started) {
            w.process.destroy();
        }
        for (Worker w : started) {
            if (!w.process.waitFor(15, TimeUnit.SECONDS)) {
                w.process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
        }
    }

    @Test
    @Order(1)
    void bitIdenticalToALocalRenderWithOneTwoAndThreeWorkers() throws Exception {
        byte[] local = local(SCENE, "local.pfm", "--spp", "12");
        assertThat(onCluster(SCENE, "c1.pfm", "--spp", "12").code()).isZero();
        assertThat(Files.readAllBytes(dir.resolve("c1.pfm"))).as("1 worker").isEqualTo(local);

        Worker w2 = worker("w2", "--join", "127.0.0.1:" + first.port);
        Worker w3 = worker("w3", "--join", "127.0.0.1:" + first.port);
        w2.await("joined cluster .*\\((2|3) members", 60);
        w3.await("joined cluster .*\\((2|3) members", 60);
        first.await("member .* joined.*\\n(.*\\n)*.*member .* joined", 30);
        Run r3 = onCluster(SCENE, "c3.pfm", "--spp", "12", "--stats", dir.resolve("c3.json").toString());
        assertThat(r3.code()).as(r3.err()).isZero();
        assertThat(Files.readAllBytes(dir.resolve("c3.pfm"))).as("3 workers").isEqualTo(local);
        List<Map<String, Object>> members = StatsFileTest.members(dir.resolve("c3.json"));
        assertThat(members).as("this JVM and three workers").hasSize(4);
        assertThat(members.get(0).get("coordinator")).as("the coordinator first").isEqualTo(true);
        assertThat(members).filteredOn(m -> m.get("coordinator").equals(true)).hasSize(1);
        assertThat(sum(members, "units")).as("3 x 2 tiles, passes of 1, 4 and 7 spp").isEqualTo(UNITS_12_SPP);
        assertThat(sum(members, "samples")).isEqualTo(96 * 64 * 12);
        assertThat(sum(members, "lost_units")).isZero();
        for (Map<String, Object> m : members) {
            assertThat(((Number) m.get("bytes_sent")).longValue()).as("%s", m).isPositive();
            assertThat(((Number) m.get("bytes_received")).longValue()).as("%s", m).isPositive();
            assertThat(((Number) m.get("mean_unit_seconds")).doubleValue()).as("%s", m).isPositive();
        }
        // a worker may hear the render's member leave before the job's end: then it says "dropped" (as the late joiner below)
        for (Worker w : List.of(first, w2, w3)) {
            w.await("(finished|its coordinator left): \\d+ units", 30);
            assertThat(w.text()).as("every worker took part").containsPattern("(finished|its coordinator left): [1-9]\\d* units rendered here");
        }
        w3.process.destroy();                                      // leaves cleanly (SIGTERM)
        assertThat(w3.process.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(w3.text()).contains("SIGTERM: leaving the cluster");

        // two workers, through the library: the same listener and snapshot as a local job
        Scene scene = SceneLoader.load(Path.of(SCENE));
        RenderSettings settings = RenderSettings.defaults().withSize(96, 64).withSamplesPerPixel(12).withSeed(3).withThreads(1);
        AtomicInteger passes = new AtomicInteger();
        AtomicReference<RenderStats> lastPass = new AtomicReference<>();
        try (RenderCluster cluster = RenderCluster.builder().join("127.0.0.1:" + first.port).clusterName(name).threads(1)
                .port(freePort()).start();
             RenderJob job = cluster.render(scene, Path.of(SCENE), settings, new RenderListener() {
                 @Override
                 public void passFinished(RenderStats soFar, Image image) {
                     passes.incrementAndGet();
                     lastPass.set(soFar);
                 }
             })) {
            assertThat(cluster.memberCount()).isEqualTo(3);
            Image image = job.awaitCompletion();
            assertThat(passes.get()).isGreaterThan(1);
            assertThat(job.snapshot().rgb()).isEqualTo(image.rgb());
            Image reference;
            try (RenderJob localJob = RenderJob.start(scene, settings)) {
                reference = localJob.awaitCompletion();
            }
            assertThat(image.rgb()).as("2 workers, library").isEqualTo(reference.rgb());
            List<RenderStats.Member> figures = job.awaitStats().members();
            assertThat(figures).hasSize(3);
            assertThat(figures.stream().mapToLong(RenderStats.Member::units).sum()).isEqualTo(UNITS_12_SPP);
            assertThat(figures.stream().mapToLong(RenderStats.Member::samples).sum()).isEqualTo(96 * 64 * 12);
            assertThat(lastPass.get().members()).as("the listener heard them too").isEqualTo(figures);
        }
    }

    @Test
    @Order(2)
    void aWorkerKilledMidRenderAndALateJoiner() throws Exception {
        Worker w2 = started.get(1);
        Scene scene = SceneLoader.load(Path.of(SCENE));
        RenderSettings settings = RenderSettings.defaults().withSize(96, 64).withSamplesPerPixel(128).withSeed(3).withThreads(1);
        int before = w2.unitsRendered();
        Image image;
        Worker late;
        try (RenderCluster cluster = RenderCluster.builder().join("127.0.0.1:" + first.port).clusterName(name).threads(1)
                .port(freePort()).start();
             RenderJob job = cluster.render(scene, Path.of(SCENE), settings, new RenderListener() {})) {
            w2.await("job \\S+ from", 60);
            w2.process.destroyForcibly();                          // kill -9, with units out to it
            job.pause();                                           // so that the late joiner is up before the end
            late = worker("w4", "--join", "127.0.0.1:" + first.port);
            late.await("joined cluster", 60);
            assertThat(job.isDone()).as("the render was still going when the late joiner came").isFalse();
            job.resume();
            image = job.awaitCompletion();
            assertThat(job.completedSamplesPerPixel()).isEqualTo(128);
            // a unit lost with the killed worker counts where it was rendered in the end
            List<RenderStats.Member> figures = job.awaitStats().members();
            assertThat(figures.stream().mapToLong(RenderStats.Member::units).sum()).as("%s", figures).isEqualTo(6 * 5);  // 1, 4, 16, 64, 43 spp
            assertThat(figures.stream().mapToLong(RenderStats.Member::samples).sum()).as("%s", figures).isEqualTo(96 * 64 * 128);
        }
        Image reference;
        try (RenderJob localJob = RenderJob.start(scene, settings)) {
            reference = localJob.awaitCompletion();
        }
        assertThat(image.rgb()).as("after a kill -9 and a late joiner").isEqualTo(reference.rgb());
        assertThat(w2.unitsRendered()).isEqualTo(before);         // it never said it finished
        // the late joiner took part; it may hear this JVM leave before the job's end (then it says "dropped")
        late.await("(finished|its coordinator left): [1-9]\\d* units rendered here", 30);
    }

    @Test
    @Order(3)
    void aSceneWithItsMeshInAnotherFolderIsShippedAndCached() throws Exception {
        Path scenes = dir.resolve("project/scenes");
        Path meshes = dir.resolve("project/meshes");
        Files.createDirectories(scenes);
        Files.createDirectories(meshes);
        Path src = Path.of("scenes");
        Files.copy(src.resolve("cornell-box.obj"), meshes.resolve("box.obj"));
        Path textures = dir.resolve("project/textures");
        Files.createDirectories(textures);
        BufferedImage checker = new BufferedImage(8, 8, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 8; x++) {
                checker.setRGB(x, y, (x + y) % 2 == 0 ? 0x3060c0 : 0xe0c040);
            }
        }
        ImageIO.write(checker, "png", textures.resolve("checker.png").toFile());
        // the floor takes a texture from a third folder: it must be shipped too
        Files.writeString(meshes.resolve("cornell-box.mtl"), Files.readString(src.resolve("cornell-box.mtl"))
                .replace("newmtl floor\n", "newmtl floor\nmap_Kd ../textures/checker.png\n"));
        String json = Files.readString(src.resolve("cornell-box.json")).replace("\"cornell-box.obj\"", "\"../meshes/box.obj\"");
        Files.writeString(scenes.resolve("box.json"), json);
        String scene = scenes.resolve("box.json").toString();
        byte[] local = local(scene, "box-local.pfm", "--spp", "4");
        Run r = onCluster(scene, "box.pfm", "--spp", "4");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(Files.readAllBytes(dir.resolve("box.pfm"))).isEqualTo(local);
        first.await("scenes/box.json \\(4 files, 4 fetched", 30);
        Run again = onCluster(scene, "box2.pfm", "--spp", "4");
        assertThat(again.code()).as(again.err()).isZero();
        first.await("scenes/box.json \\(4 files, 0 fetched", 30);
        assertThat(Files.readAllBytes(dir.resolve("box2.pfm"))).isEqualTo(local);
    }

    @Test
    @Order(4)
    void aLocalCheckpointResumesOnTheClusterBitIdentically() throws Exception {
        byte[] local = local(SCENE, "full.pfm", "--spp", "10");
        Path ck = dir.resolve("part.ck");
        local(SCENE, "part.pfm", "--spp", "3", "--checkpoint", ck.toString());
        Run r = onCluster(SCENE, "resumed.pfm", "--spp", "10", "--resume", ck.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.err()).contains("resuming");
        assertThat(Files.readAllBytes(dir.resolve("resumed.pfm"))).isEqualTo(local);
    }

    @Test
    @Order(4)
    void featureBuffersAndTheDenoisedImageAreBitIdenticalToo() throws Exception {
        // the denoiser reads the variance and the feature sums: equal outputs need the film's whole per-pixel state
        String[] opts = {"--spp", "6", "--aov", "albedo,normal,depth", "--denoise"};
        byte[] local = local(SCENE, "dn-local.pfm", opts);
        Run r = onCluster(SCENE, "dn-cluster.pfm", opts);
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(Files.readAllBytes(dir.resolve("dn-cluster.pfm"))).as("denoised image").isEqualTo(local);
        for (String aov : List.of("albedo", "normal", "depth")) {
            assertThat(Files.readAllBytes(dir.resolve("dn-cluster." + aov + ".pfm"))).as(aov)
                    .isEqualTo(Files.readAllBytes(dir.resolve("dn-local." + aov + ".pfm")));
        }
    }

    /**
     * A noise threshold on the cluster: the image and the sample counts are the local render's
     * bits, and a tile whose pixels have all converged is not handed out again. With a field of
     * view of 80° the box fills the middle column of tiles and the four tiles beside it are black,
     * done at the first decision: fewer units than every tile in every pass.
     */
    @Test
    @Order(4)
    void adaptiveSamplingIsBitIdenticalAndConvergedTilesAreNotHandedOutAgain() throws Exception {
        String[] opts = {"--spp", "512", "--noise-threshold", "0.2", "--aov", "spp", "--fov", "80"};
        byte[] local = local(SCENE, "ad-local.pfm", opts);
        Path stats = dir.resolve("ad.json");
        Run r = onCluster(SCENE, "ad-cluster.pfm", "--spp", "512", "--noise-threshold", "0.2", "--aov", "spp", "--fov", "80",
                "--stats", stats.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(Files.readAllBytes(dir.resolve("ad-cluster.pfm"))).as("image").isEqualTo(local);
        assertThat(Files.readAllBytes(dir.resolve("ad-cluster.spp.pfm"))).as("samples per pixel")
                .isEqualTo(Files.readAllBytes(dir.resolve("ad-local.spp.pfm")));
        String json = Files.readString(stats);
        Matcher passes = Pattern.compile("\"passes\" : (\\d+)").matcher(json);
        assertThat(passes.find()).isTrue();
        long units = sum(StatsFileTest.members(stats), "units");
        assertThat(units).as("units of %s passes over 3 x 2 tiles", passes.group(1)).isLessThanOrEqualTo(2L * Integer.parseInt(passes.group(1)) + 4 * 6);
    }

    @Test
    @Order(4)
    void aTimeLimitAndCtrlCEndAClusterRenderWithTheImageSoFar() throws Exception {
        Run limited = onCluster(SCENE, "limited.png", "--spp", "1000000", "--time-limit", "2s");
        assertThat(limited.code()).as(limited.err()).isZero();
        assertThat(limited.err()).containsPattern("the time limit of 2 ?s ended the render at \\d+ of 1000000 spp");
        assertThat(dir.resolve("limited.png")).isNotEmptyFile();

        int ended = count(first.text(), "job \\S+ [^:]*(finished|dropped)[^:]*:");
        Path log = dir.resolve("interrupted.txt");
        Path png = dir.resolve("interrupted.png");
        Path ck = dir.resolve("interrupted.ck");
        Process coordinator = child(log, List.of(), "render", SCENE, "-o", png.toString(), "--width", "96", "--height", "64",
                "--spp", "1000000", "--threads", "1", "--checkpoint", ck.toString(), "--checkpoint-interval", "10ms",
                "--cluster", "127.0.0.1:" + first.port, "--cluster-name", name, "--port", Integer.toString(freePort()));
        try {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (!Files.exists(ck)) {                                // a pass has completed: there is something to keep
                assertThat(coordinator.isAlive()).as(Files.readString(log)).isTrue();
                assertThat(System.nanoTime()).as("a checkpoint is written").isLessThan(deadline);
                Thread.sleep(50);
            }
            Process kill = new ProcessBuilder("kill", "-INT", Long.toString(coordinator.pid())).start();
            assertThat(kill.waitFor(10, TimeUnit.SECONDS)).isTrue();
            assertThat(coordinator.waitFor(60, TimeUnit.SECONDS)).as("exited").isTrue();
            String err = Files.readString(log);
            assertThat(coordinator.exitValue()).as(err).isEqualTo(Interrupts.SIGINT_EXIT);
            assertThat(err).containsPattern("interrupted at \\d+ of 1000000 spp").contains("--resume " + ck).doesNotContain("Exception");
            assertThat(png).isNotEmptyFile();
            long deadline2 = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (count(first.text(), "job \\S+ [^:]*(finished|dropped)[^:]*:") == ended) {   // the worker is done with it and stays up
                assertThat(first.process.isAlive()).isTrue();
                assertThat(System.nanoTime()).as("the worker ends the job: " + first.text()).isLessThan(deadline2);
                Thread.sleep(50);
            }
        } finally {
            coordinator.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    @Test
    @Order(5)
    void aWorkerOfAnotherVersionIsRefusedAndTheCoordinatorDyingLeavesTheWorkersUp() throws Exception {
        Worker old = worker("old", List.of("-Dstrahl.cluster.version=0.0-old"), "--join", "127.0.0.1:" + first.port);
        assertThat(old.process.waitFor(60, TimeUnit.SECONDS)).as(old.text()).isTrue();
        assertThat(old.process.exitValue()).as(old.text()).isEqualTo(2);
        assertThat(old.text()).contains("strahl: refused: the members at 127.0.0.1:" + first.port + " run strahl ")
                .contains("this is strahl 0.0-old").doesNotContain("Exception");
        first.await("refused member 127.0.0.1:" + old.port + ": it runs strahl 0.0-old", 30);

        int jobs = count(first.text(), "job \\S+ from");
        Process coordinator = child(dir.resolve("coordinator.txt"), List.of(), "render", SCENE, "-o", dir.resolve("never.pfm").toString(),
                "--width", "256", "--height", "256", "--spp", "100000", "--threads", "1",
                "--cluster", "127.0.0.1:" + first.port, "--cluster-name", name, "--port", Integer.toString(freePort()));
        try {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (count(first.text(), "job \\S+ from") == jobs) {
                assertThat(coordinator.isAlive()).as(Files.readString(dir.resolve("coordinator.txt"))).isTrue();
                assertThat(System.nanoTime()).as("the worker takes the job").isLessThan(deadline);
                Thread.sleep(50);
            }
            jobs++;
            coordinator.destroyForcibly();
            first.await("dropped: its coordinator left", 30);
            assertThat(first.process.isAlive()).isTrue();
            Run next = onCluster(SCENE, "next.pfm", "--spp", "2");
            assertThat(next.code()).as(next.err()).isZero();
            assertThat(count(first.text(), "job \\S+ from")).isGreaterThan(jobs);
        } finally {
            coordinator.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    @Test
    @Order(6)
    void nothingReachableIsAClearErrorWithinThirtySeconds() throws Exception {
        long start = System.nanoTime();
        Run r = strahl("render", SCENE, "-o", dir.resolve("u.png").toString(), "--spp", "1", "--width", "8", "--height", "8",
                "--cluster", "127.0.0.1:" + freePort(), "--cluster-name", name, "--port", Integer.toString(freePort()));
        double seconds = (System.nanoTime() - start) * 1e-9;
        assertThat(r.code()).as(r.err()).isEqualTo(2);
        assertThat(r.err()).contains("no strahl member answered at 127.0.0.1:").doesNotContain("Exception");
        assertThat(seconds).isLessThan(30);
        assertThat(dir.resolve("u.png")).doesNotExist();
    }

    @Test
    @Order(7)
    void usageErrors() {
        assertThat(strahl("render", SCENE, "-o", dir.resolve("a.png").toString(), "--port", "5701").err()).contains("--port needs --cluster");
        assertThat(strahl("render", SCENE, "-o", dir.resolve("a.png").toString(), "--cluster-name", "x").code()).isEqualTo(2);
        Run photon = strahl("render", SCENE, "-o", dir.resolve("a.png").toString(), "--integrator", "photon", "--cluster", "127.0.0.1:1");
        assertThat(photon.code()).isEqualTo(2);
        assertThat(photon.err()).contains("photon mapper cannot render on a cluster");
        assertThat(strahl("worker", "--threads", "-1").code()).isEqualTo(2);
        assertThat(strahl("worker", "--port", "0").err()).contains("--port must be in 1..65535");
        assertThat(strahl("worker", "--bogus").code()).isEqualTo(2);
        assertThat(dir.resolve("a.png")).doesNotExist();
    }

    @Test
    @Order(8)
    void aPlainRenderLoadsNoHazelcastClass() throws Exception {
        Path out = dir.resolve("classes.txt");
        Process p = child(out, List.of("-Xlog:class+load=info"), "render", SCENE, "-o", dir.resolve("plain.png").toString(),
                "--width", "8", "--height", "8", "--spp", "1");
        assertThat(p.waitFor(120, TimeUnit.SECONDS)).isTrue();
        String log = Files.readString(out);
        assertThat(p.exitValue()).as(log).isZero();
        assertThat(log).contains("dev.strahl.render.RenderJob").doesNotContain("com.hazelcast").doesNotContain("dev.strahl.cluster");
    }

    // ---- helpers -------------------------------------------------------------------------------

    /** Units of a 96 × 64 render at 12 spp: 3 × 2 tiles, passes of 1, 4 and 7 spp. */
    private static final long UNITS_12_SPP = 6 * 3;

    private static long sum(List<Map<String, Object>> members, String field) {
        return members.stream().mapToLong(m -> ((Number) m.get(field)).longValue()).sum();
    }

    record Run(int code, String err) {
    }

    private static Run strahl(String... args) {
        CommandLine cl = Main.commandLine();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(new StringWriter(), true));
        cl.setErr(new PrintWriter(err, true));
        int code = cl.execute(args);
        return new Run(code, err.toString());
    }

    private byte[] local(String scene, String file, String... options) throws IOException {
        List<String> args = new ArrayList<>(List.of("render", scene, "-o", dir.resolve(file).toString(), "-q"));
        args.addAll(Arrays.asList(SIZE));
        args.addAll(Arrays.asList(options));
        Run r = strahl(args.toArray(String[]::new));
        assertThat(r.code()).as(r.err()).isZero();
        return Files.readAllBytes(dir.resolve(file));
    }

    private Run onCluster(String scene, String file, String... options) {
        List<String> args = new ArrayList<>(List.of("render", scene, "-o", dir.resolve(file).toString()));
        args.addAll(Arrays.asList(SIZE));
        args.addAll(Arrays.asList(options));
        args.addAll(List.of("--cluster", "127.0.0.1:" + first.port, "--cluster-name", name, "--port", Integer.toString(freePort())));
        return strahl(args.toArray(String[]::new));
    }

    private Worker worker(String label, String... args) throws IOException {
        return worker(label, List.of(), args);
    }

    private Worker worker(String label, List<String> jvm, String... args) throws IOException {
        int port = freePort();
        Path log = dir.resolve(label + ".txt");
        List<String> cmd = new ArrayList<>(List.of("worker", "--port", Integer.toString(port), "--threads", "1", "--cluster-name", name));
        cmd.addAll(Arrays.asList(args));
        Worker w = new Worker(child(log, jvm, cmd.toArray(String[]::new)), port, log);
        started.add(w);
        return w;
    }

    private Process child(Path output, List<String> jvm, String... args) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        String modules = System.getProperty("jdk.module.path", "");
        String classPath = (modules.isBlank() ? "" : modules + File.pathSeparator) + System.getProperty("java.class.path");
        cmd.addAll(List.of("-Xmx256m", "-XX:TieredStopAtLevel=1", "-Djava.io.tmpdir=" + dir.resolve("tmp-" + output.getFileName())));
        cmd.addAll(jvm);
        cmd.addAll(List.of("-cp", classPath, Main.class.getName()));
        cmd.addAll(List.of(args));
        Files.createDirectories(dir.resolve("tmp-" + output.getFileName()));
        return new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true).redirectOutput(output.toFile()).start();
    }

    private static int freePort() {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return s.getLocalPort();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    private static int count(String text, String pattern) {
        Matcher m = Pattern.compile(pattern).matcher(text);
        int n = 0;
        while (m.find()) {
            n++;
        }
        return n;
    }
}
