package dev.strahl.accel;

/**
 * Whether {@link SimdKernel} can run in this JVM: the incubating Vector API module
 * ({@code jdk.incubator.vector}) is in the boot layer, and the processor has 256-bit vectors
 * (where it has not, the API would emulate the lanes in Java, far slower than the scalar kernel).
 * The strahl command line starts its JVM with the module ({@code dev.strahl.cli.SimdLauncher});
 * a program using the library adds {@code --add-modules jdk.incubator.vector} to its JVM's options.
 * Without it {@link ScalarKernel} runs, with the same results.
 */
public final class Simd {
    private Simd() {}

    /**
     * The system property that switches the SIMD kernel off for BVHs built from then on
     * ({@code -Dstrahl.simd=false}), or on from the first ray, before C2 has compiled it
     * ({@value #ALWAYS}: for tests that want its answers, not its speed; see {@link SimdWarmUp}).
     */
    public static final String PROPERTY = "strahl.simd";
    public static final String ALWAYS = "always";

    /**
     * Whether the module is there, the processor has 256-bit vectors and the JVM compiles with C2
     * (the Vector API's lanes are C2's intrinsics; interpreted or in C1 code they are slower than
     * the scalar kernel: {@code -Xint}, {@code -XX:TieredStopAtLevel=1}).
     */
    public static final boolean AVAILABLE = ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent() && Lanes.wide() && c2();

    /** Whether a BVH built now takes the SIMD kernel: {@link #AVAILABLE} and not switched off by {@link #PROPERTY}. */
    public static boolean enabled() {
        return AVAILABLE && !"false".equals(System.getProperty(PROPERTY));
    }

    /**
     * Waits until the SIMD kernel is compiled and answers the queries of BVHs built with the
     * default ({@link SimdWarmUp}), at most {@code millis}; for benchmarks, which time it warm.
     *
     * @return whether it is
     */
    public static boolean awaitWarmUp(long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000;
        while (enabled() && !SimdWarmUp.ready()) {
            if (System.nanoTime() > end) {
                return false;
            }
            Thread.sleep(10);
        }
        return enabled();
    }

    /** The kernel's name for reports: the SIMD kernel's lanes and the processor's vector width, or "scalar". */
    public static String describe(boolean simd) {
        return simd ? "simd (256-bit lanes: 8 floats a node test, 4 doubles a leaf block; " + Lanes.preferredBits() + "-bit CPU vectors)" : "scalar";
    }

    /** Whether this JVM compiles with C2 (the server compiler), which the lanes need to be fast. */
    public static boolean c2() {
        return c2(java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments());
    }

    /**
     * Whether a JVM with these options compiles with C2: not interpreted only ({@code -Xint},
     * {@code -XX:-UseCompiler}) and not stopped at C1 ({@code -XX:TieredStopAtLevel} below 4, as
     * with {@code -XX:TieredStopAtLevel=1}). The JVM's options, not its diagnostic bean: that costs
     * tens of milliseconds of start-up more.
     */
    public static boolean c2(java.util.List<String> jvmOptions) {
        if (System.getProperty("java.vm.info", "").startsWith("interpreted")) {
            return false;
        }
        boolean c2 = true;
        for (String o : jvmOptions) {
            if (o.equals("-Xint") || o.equals("-XX:-UseCompiler")) {
                c2 = false;
            } else if (o.startsWith("-XX:TieredStopAtLevel=")) {
                c2 = o.endsWith("=4") || o.endsWith("=-1");
            }
        }
        return c2;
    }

    /** Touches the Vector API only when the module is present (checked before the call). */
    private static final class Lanes {
        static boolean wide() {
            return jdk.incubator.vector.FloatVector.SPECIES_PREFERRED.vectorBitSize() >= 256;
        }

        static int preferredBits() {
            return jdk.incubator.vector.FloatVector.SPECIES_PREFERRED.vectorBitSize();
        }
    }
}
