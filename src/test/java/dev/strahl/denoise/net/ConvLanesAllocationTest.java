package dev.strahl.denoise.net;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorSpecies;
import org.junit.jupiter.api.Test;

/**
 * The Vector API path of the convolution allocates nothing once C2 has compiled it, also when
 * other vector code ran first in the JVM and filled the API's shared type profiles with other
 * vector classes (as the BVH's kernel does in a render before a denoise). Runs in a JVM of its
 * own ({@link #main}), so that what the other tests ran before does not decide how C2 compiles
 * it, with {@code -Xbatch}: C2 has compiled it after a given number of calls.
 */
class ConvLanesAllocationTest {

    @Test
    void theLanesAllocateNothingAfterOtherVectorCodeRan() throws Exception {
        assumeTrue(Conv3x3.LANES, "the Vector API module is not in this JVM");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String classPath = where(ConvLanesAllocationTest.class) + File.pathSeparator + where(Conv3x3.class);
        Process p = new ProcessBuilder(java, "-Xbatch", "-Xmx256m", "--add-modules", "jdk.incubator.vector",
                "-cp", classPath, ConvLanesAllocationTest.class.getName())
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(5, TimeUnit.MINUTES)).as(out).isTrue();
        assertThat(p.exitValue()).as(out).isZero();
        assertThat(out).as(out).contains("bytes per convolution: 0\n");
    }

    private static String where(Class<?> c) throws URISyntaxException {
        return Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
    }

    /** Fills the profiles with every other float shape, compiles the lanes path, prints what one convolution allocates. */
    public static void main(String[] args) {
        for (VectorSpecies<Float> s : List.of(FloatVector.SPECIES_64, FloatVector.SPECIES_128, FloatVector.SPECIES_256, FloatVector.SPECIES_512)) {
            if (s.length() != FloatVector.SPECIES_PREFERRED.length()) {
                otherVectorCode(s);
            }
        }
        Conv3x3 conv = LayersTest.randomConv(8, 8, 1);
        FeatureMap[] src = {LayersTest.random(8, 2, 32, 2)};
        FeatureMap dst = new FeatureMap(8, 2, 32);
        for (int i = 0; i < 5000; i++) {
            ConvLanes.rows(conv, src, dst, 0, 2);
        }
        var threads = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(id);
        for (int i = 0; i < 100; i++) {
            ConvLanes.rows(conv, src, dst, 0, 2);
        }
        System.out.print("bytes per convolution: " + (threads.getThreadAllocatedBytes(id) - before) / 100 + "\n");
    }

    /** The operations the lanes path calls, on vectors of another shape. */
    private static void otherVectorCode(VectorSpecies<Float> s) {
        float[] a = new float[64];
        FloatVector sum = FloatVector.zero(s);
        for (int i = 0; i < 20000; i++) {
            FloatVector v = FloatVector.fromArray(s, a, 0);
            FloatVector k = FloatVector.broadcast(s, 0.5f);
            sum = v.fma(k, sum);
            sum.max(0f).intoArray(a, 0);
            sum.max(v).intoArray(a, 16);
            v.max(sum).intoArray(a, 32);
        }
    }
}
