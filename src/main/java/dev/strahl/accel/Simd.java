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

    /** The system property that switches the SIMD kernel off for BVHs built from then on ({@code -Dstrahl.simd=false}). */
    public static final String PROPERTY = "strahl.simd";

    /** Whether the module is there and the processor has 256-bit vectors. */
    public static final boolean AVAILABLE = ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent() && Lanes.wide();

    /** Whether a BVH built now takes the SIMD kernel: {@link #AVAILABLE} and not switched off by {@link #PROPERTY}. */
    public static boolean enabled() {
        return AVAILABLE && !"false".equals(System.getProperty(PROPERTY));
    }

    /** The kernel's name for reports: "simd (AVX-512, 256-bit lanes)" style, or "scalar". */
    public static String describe(boolean simd) {
        return simd ? "simd (" + Lanes.preferredBits() + "-bit vectors, 8 float lanes per node, 4 double lanes per leaf block)" : "scalar";
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
