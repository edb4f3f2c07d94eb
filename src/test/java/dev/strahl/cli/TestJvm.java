package dev.strahl.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * How surefire starts the test JVM (pom.xml, argLine): this small JVM starts the real one with
 * the arguments it was given ({@code --add-modules jdk.incubator.vector}, so that the tests cover
 * the SIMD kernel, and surefire's own), passes stdin and stdout through (surefire's channel) and
 * copies stderr without the line the JVM prints for an incubating module, as {@link SimdLauncher}
 * does for the command line: the test output shows no such warning either. Its exit code is the
 * test JVM's; if surefire ends this JVM, it ends the test JVM.
 */
public final class TestJvm {
    private TestJvm() {}

    public static void main(String[] args) throws Exception {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(Arrays.asList(args));
        Process jvm = new ProcessBuilder(cmd).redirectInput(ProcessBuilder.Redirect.INHERIT).redirectOutput(ProcessBuilder.Redirect.INHERIT)
                .redirectError(ProcessBuilder.Redirect.PIPE).start();
        Runtime.getRuntime().addShutdownHook(new Thread(jvm::destroy));
        Thread pump = new Thread(() -> SimdLauncher.copyStderr(jvm.getErrorStream(), System.err), "stderr");
        pump.start();
        int code = jvm.waitFor();
        pump.join(2000);
        System.err.flush();
        Runtime.getRuntime().halt(code);
    }
}
