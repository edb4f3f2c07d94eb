package dev.strahl.medium;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.List;
import java.util.SplittableRandom;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;

/**
 * Inputs for fuzzing the {@code .vol} reader ({@code io.ParserFuzzTest}): headers from the format's
 * grammar with hostile sizes, versions, encodings and channel counts over data of random length,
 * and valid files with integers overwritten and bytes scrambled or cut off.
 */
public final class VolFuzzInputs {
    private VolFuzzInputs() {
    }

    private static final int[] HOSTILE = {0, 1, -1, 2, 3, 6, 255, 256, 0x7fff, 0x10000, 1 << 24, 0x7fffffff, 0x80000000, 1290, 46341};

    private static int hostile(SplittableRandom r) {
        return r.nextInt(3) == 0 ? r.nextInt() : HOSTILE[r.nextInt(HOSTILE.length)];
    }

    /** A header with each field right or hostile, then 0 to 600 bytes of random floats (sometimes negative or NaN). */
    public static Arbitrary<byte[]> fromTheGrammar() {
        return Arbitraries.longs().map(seed -> {
            SplittableRandom r = new SplittableRandom(seed);
            int nx = r.nextBoolean() ? 1 + r.nextInt(5) : hostile(r), ny = r.nextBoolean() ? 1 + r.nextInt(5) : hostile(r);
            int nz = r.nextBoolean() ? 1 + r.nextInt(5) : hostile(r);
            int dataBytes = r.nextInt(4) == 0 ? r.nextInt(600) : 4 * Math.max(0, Math.min(150, nx * ny * nz));
            ByteBuffer b = ByteBuffer.allocate(48 + dataBytes).order(ByteOrder.LITTLE_ENDIAN);
            b.put((byte) 'V').put((byte) 'O').put((byte) (r.nextInt(20) == 0 ? 'X' : 'L')).put((byte) (r.nextInt(10) == 0 ? hostile(r) : 3));
            b.putInt(r.nextInt(10) == 0 ? hostile(r) : 1).putInt(nx).putInt(ny).putInt(nz).putInt(r.nextInt(8) == 0 ? hostile(r) : 1);
            for (int i = 0; i < 6; i++) {
                b.putFloat(r.nextInt(10) == 0 ? Float.NaN : (float) r.nextGaussian());
            }
            while (b.remaining() >= 4) {
                b.putFloat(r.nextInt(50) == 0 ? -1 : r.nextInt(100) == 0 ? Float.NaN : r.nextFloat() * 10);
            }
            return b.array();
        });
    }

    /** Valid files of a few sizes with 1 to 5 binary edits. */
    public static Arbitrary<byte[]> mutated() {
        List<byte[]> seeds = List.of(VolFiles.bytes(1, 1, 1, new float[] {0, 0, 0, 1, 1, 1}, new float[] {0.5f}),
                VolFiles.bytes(4, 3, 2, new float[] {-1, 0, -1, 1, 2, 1}, new float[24]),
                VolFiles.bytes(8, 8, 8, new float[] {0, 0, 0, 1, 1, 1}, new float[512]));
        return Arbitraries.of(seeds).flatMap(seed -> Arbitraries.longs().map(choice -> {
            SplittableRandom r = new SplittableRandom(choice);
            byte[] b = seed.clone();
            int edits = 1 + r.nextInt(5);
            for (int e = 0; e < edits; e++) {
                int at = r.nextInt(Math.max(1, b.length - 3));
                switch (r.nextInt(4)) {
                    case 0 -> ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putInt(Math.min(at, 44), hostile(r));
                    case 1 -> b[at] = (byte) r.nextInt(256);
                    case 2 -> b = java.util.Arrays.copyOf(b, r.nextInt(b.length + 1));
                    default -> ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putInt(Math.min(at, b.length - 4) & ~3, Float.floatToIntBits(-r.nextFloat()));
                }
                if (b.length < 4) {
                    break;
                }
            }
            return b;
        }));
    }
}
