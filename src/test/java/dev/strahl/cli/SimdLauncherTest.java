package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.accel.Simd;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The command line gets the SIMD kernel without a flag: a JVM started without the Vector API
 * module (as {@code java -jar strahl.jar} is) runs the command in a second JVM with it, whose
 * kernel {@code --version} and {@code --stats} report, with nothing else changed: no incubator
 * warning on stderr, the same stdout, exit codes and messages, and {@code --simd off} stays in one
 * JVM with the scalar kernel and renders the same image. Signals through the launcher:
 * {@link InterruptTest} (its processes are started this way).
 */
class SimdLauncherTest {
    private static final String SCENE = Path.of("scenes", "cornell-box.json").toAbsolutePath().toString();

    @TempDir
    Path dir;

    record Run(int code, String out, String err, boolean relaunched) {}

    /** {@code java -cp … Main ARGS} without the module, as {@code java -jar} starts it; notes whether it started a second JVM. */
    private Run strahl(List<String> jvm, String... args) throws Exception {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Xmx512m");
        cmd.addAll(jvm);
        String modules = System.getProperty("jdk.module.path", "");
        cmd.addAll(List.of("-cp", (modules.isBlank() ? "" : modules + File.pathSeparator) + System.getProperty("java.class.path"), Main.class.getName()));
        cmd.addAll(List.of(args));
        Path out = dir.resolve("out.txt"), err = dir.resolve("err.txt");
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        boolean relaunched = false;
        while (!p.waitFor(20, TimeUnit.MILLISECONDS)) {
            relaunched |= p.children().anyMatch(c -> c.info().arguments().map(a -> List.of(a).contains("--add-modules=" + SimdLauncher.MODULE)).orElse(false));
        }
        return new Run(p.exitValue(), Files.readString(out), Files.readString(err), relaunched);
    }

    private static boolean simdHere() {
        return Simd.AVAILABLE;                          // the test JVM has the module, as the relaunched one will
    }

    @Test
    void versionReportsTheSimdKernelWithoutAWarning() throws Exception {
        Run run = strahl(List.of(), "--version");
        assertThat(run.code()).as(run.err()).isZero();
        assertThat(run.err()).as("no incubator warning, nothing else").isEmpty();
        assertThat(run.out()).startsWith("strahl ").contains("ray kernel: " + (simdHere() ? "simd (" : "scalar"));
    }

    @Test
    void aRenderRunsInASecondJvmWithTheSimdKernelAndOnlyItsOwnOutput() throws Exception {
        Path png = dir.resolve("cb.png"), stats = dir.resolve("cb.json");
        Run run = strahl(List.of(), "render", SCENE, "-o", png.toString(), "--width", "32", "--height", "32", "--spp", "64", "--stats", stats.toString());
        assertThat(run.code()).as(run.err()).isZero();
        assertThat(run.relaunched()).as("a second JVM with the module").isTrue();
        assertThat(run.err()).doesNotContain("WARNING").startsWith("strahl: path, 32x32, 64 spp in ").endsWith(" -> " + png + System.lineSeparator());
        assertThat(run.err().lines().count()).as("one line, as before").isEqualTo(1);
        assertThat(run.out()).isEmpty();
        assertThat(Files.readString(stats)).contains("\"kernel\" : \"bvh8, " + (simdHere() ? "simd (" : "scalar"));
    }

    @Test
    void badInputIsStillOneLineAndExitCodeTwo() throws Exception {
        Run run = strahl(List.of(), "render", dir.resolve("missing.json").toString(), "-o", dir.resolve("x.png").toString());
        assertThat(run.code()).isEqualTo(2);
        assertThat(run.err()).isEqualTo("strahl: " + dir.resolve("missing.json") + ": file not found" + System.lineSeparator());
        assertThat(dir.resolve("x.png")).doesNotExist();
        Run usage = strahl(List.of(), "render", "--no-such-option");
        assertThat(usage.code()).isEqualTo(2);
        assertThat(usage.err()).doesNotContain("WARNING").startsWith("strahl: ");
    }

    @Test
    void simdOffStaysInOneJvmWithTheScalarKernelAndRendersTheSameImage() throws Exception {
        Path on = dir.resolve("on.pfm"), off = dir.resolve("off.pfm"), stats = dir.resolve("off.json");
        // From the first ray on: a short render would otherwise end before the SIMD kernel is compiled (SimdWarmUp).
        Run simd = strahl(List.of("-D" + Simd.PROPERTY + "=" + Simd.ALWAYS), "render", SCENE, "-o", on.toString(), "--width", "24", "--height", "24", "--spp", "8");
        Run scalar = strahl(List.of(), "render", SCENE, "-o", off.toString(), "--width", "24", "--height", "24", "--spp", "8", "--simd", "off", "--stats", stats.toString());
        assertThat(simd.code()).as(simd.err()).isZero();
        assertThat(scalar.code()).as(scalar.err()).isZero();
        assertThat(scalar.relaunched()).isFalse();
        assertThat(Files.readString(stats)).contains("\"kernel\" : \"bvh8, scalar\"");
        assertThat(Files.readAllBytes(on)).as("the same bits").isEqualTo(Files.readAllBytes(off));
    }

    /**
     * A flight recording asked for on the command line is the child's, the one of the work: the
     * launcher's own, which would overwrite it on exit, is dropped. (HotSpot samples threads for it
     * with SIGUSR2, which the launcher therefore does not use for forwarding.)
     */
    @Test
    void aFlightRecordingIsTheWorkingJvms() throws Exception {
        Path jfr = dir.resolve("rec.jfr"), png = dir.resolve("rec.png");
        Run run = strahl(List.of("-XX:StartFlightRecording=filename=" + jfr + ",settings=profile"), "render", SCENE, "-o", png.toString(),
                "--width", "48", "--height", "48", "--spp", "32", "--threads", "1");
        assertThat(run.code()).as(run.err()).isZero();
        assertThat(png).isNotEmptyFile();
        long renderSamples;
        ModuleLayer.boot().findModule("jdk.jfr").ifPresent(SimdLauncherTest.class.getModule()::addReads);   // the test module reads the recording
        try (var recording = new jdk.jfr.consumer.RecordingFile(jfr)) {
            long n = 0;
            while (recording.hasMoreEvents()) {
                var e = recording.readEvent();
                if (e.getEventType().getName().equals("jdk.ExecutionSample") && e.getStackTrace() != null
                        && e.getStackTrace().getFrames().stream().anyMatch(f -> f.getMethod().getType().getName().startsWith("dev.strahl.integrator"))) {
                    n++;
                }
            }
            renderSamples = n;
        }
        assertThat(renderSamples).as("samples of the render in the recording").isPositive();
    }

    @Test
    void noSecondJvmWithoutC2() throws Exception {
        Run run = strahl(List.of("-XX:TieredStopAtLevel=1"), "--version");
        assertThat(run.code()).isZero();
        assertThat(run.relaunched()).isFalse();
        assertThat(run.out()).contains("ray kernel: scalar");
    }

    @Test
    void theWarningLineIsDroppedAndEverythingElseKeptByteForByte() {
        String warning = SimdLauncher.WARNING + System.lineSeparator();
        assertThat(copied(warning + "strahl: rendering\r[###---] 50%")).isEqualTo("strahl: rendering\r[###---] 50%");
        assertThat(copied("strahl: no warning here\n" + warning)).isEqualTo("strahl: no warning here\n" + warning);
        assertThat(copied("WARNING: Using something else\n")).isEqualTo("WARNING: Using something else\n");
        assertThat(copied("WARN")).isEqualTo("WARN");
        assertThat(copied("")).isEmpty();
        assertThat(copied(warning)).isEmpty();
    }

    private static String copied(String stderr) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        SimdLauncher.copyStderr(new ByteArrayInputStream(stderr.getBytes(StandardCharsets.UTF_8)), out);
        return out.toString(StandardCharsets.UTF_8);
    }

    @Test
    void theChildTakesTheLaunchersAnswerAboutTheTerminal() {
        String before = System.getProperty(SimdLauncher.STDERR_TERMINAL);
        try {
            System.setProperty(SimdLauncher.STDERR_TERMINAL, "true");
            assertThat(Terminal.isStderrTerminal()).isTrue();
            System.setProperty(SimdLauncher.STDERR_TERMINAL, "false");
            assertThat(Terminal.isStderrTerminal()).isFalse();
        } finally {
            Optional.ofNullable(before).ifPresentOrElse(b -> System.setProperty(SimdLauncher.STDERR_TERMINAL, b),
                    () -> System.clearProperty(SimdLauncher.STDERR_TERMINAL));
        }
    }

    @Test
    void simdOffIsRecognisedInBothSpellings() {
        assertThat(SimdLauncher.simdOff(new String[] {"render", "x.json", "--simd", "off"})).isTrue();
        assertThat(SimdLauncher.simdOff(new String[] {"render", "--simd=OFF"})).isTrue();
        assertThat(SimdLauncher.simdOff(new String[] {"render", "--simd", "on"})).isFalse();
        assertThat(SimdLauncher.simdOff(new String[] {"render", "--simd"})).isFalse();
    }
}
