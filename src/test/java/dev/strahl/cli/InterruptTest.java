package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Ctrl-C and SIGTERM on a real {@code strahl render} process: the image rendered so far is
 * written, with a checkpoint that resumes; a second signal ends the process at once.
 */
class InterruptTest {
    private static final String SCENE = Path.of("scenes", "cornell-box.json").toAbsolutePath().toString();

    @TempDir
    Path dir;
    private final List<Process> started = new ArrayList<>();

    /** A failed assertion must not leave a million-spp render running. */
    @AfterEach
    void stopWhatIsLeft() throws InterruptedException {
        for (Process p : started) {
            p.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
    }

    @Test
    void sigintWritesTheImageSoFarAndACheckpointThatResumes() throws Exception {
        Path png = dir.resolve("out.png");
        Path ck = dir.resolve("out.ck");
        Process p = start("render", SCENE, "-o", png.toString(), "--width", "48", "--height", "32", "--spp", "1000000",
                "--checkpoint", ck.toString(), "--checkpoint-interval", "10ms");
        awaitFile(p, ck);                        // a pass has completed: there is something to keep
        signal(p, "INT");
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).as("exited").isTrue();
        String err = stderr(p);
        assertThat(p.exitValue()).as(err).isEqualTo(Interrupts.SIGINT_EXIT);
        assertThat(err).contains("strahl: SIGINT: stopping").containsPattern("interrupted at \\d+ of 1000000 spp")
                .contains("wrote " + png).contains("--resume " + ck).doesNotContain("Exception");
        BufferedImage img = ImageIO.read(png.toFile());
        assertThat(img.getWidth()).isEqualTo(48);
        assertThat(img.getHeight()).isEqualTo(32);
        assertThat(img.getRGB(24, 16) & 0xffffff).as("the box is lit").isNotZero();
        assertThat(listing()).containsExactlyInAnyOrder("out.png", "out.ck");        // no temporary file left

        Path resumed = dir.resolve("resumed.png");
        Process q = start("render", SCENE, "-o", resumed.toString(), "--width", "48", "--height", "32", "--spp", "64",
                "--resume", ck.toString());
        assertThat(q.waitFor(120, TimeUnit.SECONDS)).isTrue();
        String qerr = stderr(q);
        assertThat(q.exitValue()).as(qerr).isZero();
        assertThat(qerr).containsPattern("resuming .*out.ck at \\d+ spp");
        assertThat(ImageIO.read(resumed.toFile()).getWidth()).isEqualTo(48);
    }

    @Test
    void sigtermStopsCleanlyToo() throws Exception {
        Path pfm = dir.resolve("t.pfm");
        Process p = start("render", SCENE, "-o", pfm.toString(), "--width", "16", "--height", "16", "--spp", "1000000",
                "--checkpoint", dir.resolve("t.ck").toString(), "--checkpoint-interval", "10ms");
        awaitFile(p, dir.resolve("t.ck"));
        p.destroy();                                                           // SIGTERM
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(stderr(p)).isEqualTo(Interrupts.SIGTERM_EXIT);
        assertThat(dev.strahl.codec.PfmReader.read(pfm).width()).isEqualTo(16);
    }

    @Test
    void aSecondSigintExitsAtOnceLeavingNoTemporaryFile() throws Exception {
        Path png = dir.resolve("big.png");
        Path ck = dir.resolve("big.ck");
        Process p = start("render", SCENE, "-o", png.toString(), "--width", "1500", "--height", "1500", "--spp", "1000000",
                "--checkpoint", ck.toString(), "--checkpoint-interval", "1ms");
        awaitFile(p, ck);
        signal(p, "INT");
        // the second signal once the first has been taken (two pending signals would merge into one),
        // while the 1500x1500 image and its 63 MB checkpoint are still being written
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (!stderr(p).contains("SIGINT: stopping") && System.nanoTime() < deadline) {
            Thread.sleep(2);
        }
        signal(p, "INT");
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        String err = stderr(p);
        assertThat(p.exitValue()).as(err).isEqualTo(Interrupts.SIGINT_EXIT);
        assertThat(err).contains("SIGINT again: exiting at once");
        // whatever was being written when the second signal came is either complete or absent
        for (String name : listing()) {
            assertThat(name).doesNotEndWith(".tmp");
        }
    }

    // ---- helpers -------------------------------------------------------------------------------

    private Process start(String... args) throws IOException {
        List<String> cmd = new ArrayList<>();
        // A process started in the background by a non-interactive shell ignores SIGINT, and
        // children inherit that; coreutils' env can give the child the default disposition back.
        if (new File("/usr/bin/env").canExecute() && envResetsSignals()) {
            cmd.addAll(List.of("/usr/bin/env", "--default-signal=INT"));
        }
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        // the tests may run on the module path: the child gets all of it on its class path (as `java -jar` would)
        String modules = System.getProperty("jdk.module.path", "");
        String classPath = (modules.isBlank() ? "" : modules + File.pathSeparator) + System.getProperty("java.class.path");
        cmd.addAll(List.of("-Xmx512m", "-cp", classPath, Main.class.getName()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(ProcessBuilder.Redirect.DISCARD)
                .redirectError(dir.resolve("stderr.txt").toFile()).start();
        started.add(p);
        return p;
    }

    private static boolean envResetsSignals() {
        try {
            Process p = new ProcessBuilder("/usr/bin/env", "--default-signal=INT", "true").start();
            return p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    private String stderr(Process p) throws IOException {
        return Files.readString(dir.resolve("stderr.txt"), StandardCharsets.UTF_8);
    }

    private static void signal(Process p, String name) throws Exception {
        Process kill = new ProcessBuilder("kill", "-" + name, Long.toString(p.pid())).start();
        assertThat(kill.waitFor(10, TimeUnit.SECONDS)).isTrue();
        assertThat(kill.exitValue()).isZero();
    }

    private void awaitFile(Process p, Path file) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!Files.exists(file)) {
            if (!p.isAlive()) {
                throw new AssertionError("the render process ended early, exit code " + p.exitValue() + ": " + stderr(p));
            }
            assertThat(System.nanoTime()).as("waiting for " + file).isLessThan(deadline);
            Thread.sleep(20);
        }
        if (!ignoresSigint(p)) {
            return;
        }
        p.destroyForcibly();
        assumeTrue(false, "SIGINT is ignored in the child process (inherited), so Ctrl-C cannot be tested here");
    }

    /** Linux: bit 1 (SIGINT = 2) of the SigIgn mask in /proc/PID/status. */
    private static boolean ignoresSigint(Process p) throws IOException {
        Path status = Path.of("/proc", Long.toString(p.pid()), "status");
        if (!Files.exists(status)) {
            return false;
        }
        try (Stream<String> lines = Files.lines(status)) {
            return lines.filter(l -> l.startsWith("SigIgn:")).findFirst()
                    .map(l -> (Long.parseLong(l.substring(7).trim(), 16) & 2) != 0).orElse(false);
        }
    }

    private List<String> listing() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(f -> f.getFileName().toString()).filter(n -> !n.equals("stderr.txt")).toList();
        }
    }
}
