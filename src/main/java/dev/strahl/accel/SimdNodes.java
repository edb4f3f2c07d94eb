package dev.strahl.accel;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.IntVector;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * The slab test of {@link Bvh}'s four child boxes in one go with the incubating Vector API
 * (four float lanes): the same arithmetic as the scalar {@code Bvh.entry}, lane by lane, so both
 * paths give the same bits. Only loaded when the JVM runs with
 * {@code --add-modules jdk.incubator.vector} (see {@link #AVAILABLE}); otherwise {@link Bvh}
 * uses its scalar loop.
 */
final class SimdNodes {
    private SimdNodes() {}

    /** Whether the module is there and not switched off with {@code -Dstrahl.simd=false}. */
    static final boolean AVAILABLE = ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent()
            && !"false".equals(System.getProperty("strahl.simd"));

    /**
     * Writes the entry distances (float bits) of the four children of the node whose boxes start
     * at {@code o}, or -1 for the children the ray misses, into {@code out[0..3]}.
     */
    static void entries(float[] box, int o, int nx, int ny, int nz, float onx, float ony, float onz,
                        float ofx, float ofy, float ofz, float ix, float iy, float iz, int tMaxBits, int margin, int[] out) {
        Lanes.entries(box, o, nx, ny, nz, onx, ony, onz, ofx, ofy, ofz, ix, iy, iz, tMaxBits, margin, out);
    }

    /** Holds the species, so that merely checking {@link #AVAILABLE} never touches the module. */
    private static final class Lanes {
        private static final VectorSpecies<Float> F = FloatVector.SPECIES_128;

        static void entries(float[] box, int o, int nx, int ny, int nz, float onx, float ony, float onz,
                            float ofx, float ofy, float ofz, float ix, float iy, float iz, int tMaxBits, int margin, int[] out) {
            IntVector tnx = FloatVector.fromArray(F, box, o + nx).sub(onx).mul(ix).reinterpretAsInts();
            IntVector tny = FloatVector.fromArray(F, box, o + ny).sub(ony).mul(iy).reinterpretAsInts();
            IntVector tnz = FloatVector.fromArray(F, box, o + nz).sub(onz).mul(iz).reinterpretAsInts();
            IntVector tn = tnx.max(tny).max(tnz.max(0));
            IntVector tfx = FloatVector.fromArray(F, box, o + (nx ^ 12)).sub(ofx).mul(ix).reinterpretAsInts();
            IntVector tfy = FloatVector.fromArray(F, box, o + (ny ^ 20)).sub(ofy).mul(iy).reinterpretAsInts();
            IntVector tfz = FloatVector.fromArray(F, box, o + (nz ^ 28)).sub(ofz).mul(iz).reinterpretAsInts();
            IntVector tf = tfx.min(tfy).min(tfz.min(tMaxBits)).add(margin);
            tn.blend(-1, tn.compare(VectorOperators.GT, tf)).intoArray(out, 0);
        }
    }
}
