package dev.strahl.units;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The wire form of a work unit: every bit of the sums and counts comes back, and junk is refused. */
class WorkUnitTest {

    private static WorkUnit unit(boolean uniform) {
        Random r = new Random(7);
        int[] counts = new int[32 * 20];
        double[] sums = new double[11 * counts.length];          // colour, variance and feature sums
        for (int i = 0; i < counts.length; i++) {
            counts[i] = uniform ? 16 : 16 + r.nextInt(3);
        }
        for (int i = 0; i < sums.length; i++) {
            sums[i] = i % 7 == 0 ? -0.0 : i % 11 == 0 ? Double.MIN_VALUE : r.nextDouble() * 1e3;
        }
        return new WorkUnit(64, 96, 32, 20, 16, 80, counts, sums);
    }

    @Test
    void roundTripKeepsEveryBit() throws IOException {
        for (boolean uniform : new boolean[] {true, false}) {
            WorkUnit u = unit(uniform);
            u.recordFigures(3, 123456789012L);
            byte[] bytes = u.encode(1);
            assertThat(bytes).hasSize(1 + u.wireSize());
            WorkUnit back = WorkUnit.decode(bytes, 1);
            assertThat(back.x0()).isEqualTo(64);
            assertThat(back.y0()).isEqualTo(96);
            assertThat(back.width()).isEqualTo(32);
            assertThat(back.height()).isEqualTo(20);
            assertThat(back.firstSample()).isEqualTo(16);
            assertThat(back.endSample()).isEqualTo(80);
            assertThat(back.sumsPerPixel()).isEqualTo(11);
            assertThat(back.invalidSamples()).isEqualTo(3);
            assertThat(back.rays()).isEqualTo(123456789012L);
            assertThat(back.counts()).isEqualTo(u.counts());
            long[] a = Arrays.stream(u.sums()).mapToLong(Double::doubleToRawLongBits).toArray();
            long[] b = Arrays.stream(back.sums()).mapToLong(Double::doubleToRawLongBits).toArray();
            assertThat(b).isEqualTo(a);
        }
        assertThat(unit(true).wireSize()).as("uniform counts are sent once").isEqualTo(unit(false).wireSize() - 4 * 640 + 8);
    }

    /** A unit of adaptive sampling names the pixels that take samples: the mask survives the wire, and only they count. */
    @Test
    void theMaskOfPixelsThatTakeSamplesRoundTrips() throws IOException {
        boolean[] renders = {true, false, false, true};
        WorkUnit u = new WorkUnit(0, 0, 2, 2, 4, 10, new int[] {4, 4, 4, 4}, new double[16], renders);
        assertThat(u.samples()).isEqualTo(12);
        WorkUnit back = WorkUnit.decode(u.encode(0), 0);
        for (int i = 0; i < 4; i++) {
            assertThat(back.renders(i)).isEqualTo(renders[i]);
        }
        assertThat(back.samples()).isEqualTo(12);
        assertThat(u.wireSize()).isEqualTo(new WorkUnit(0, 0, 2, 2, 4, 10, new int[] {4, 4, 4, 4}, new double[16]).wireSize() + 4);
        assertThatThrownBy(() -> new WorkUnit(0, 0, 2, 2, 4, 10, new int[4], new double[16], new boolean[3]))
                .isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void samplesCountsOnlyWhatPixelsLack() {
        int[] counts = {0, 5, 10, 12};
        WorkUnit u = new WorkUnit(0, 0, 2, 2, 4, 10, counts, new double[16]);
        assertThat(u.samples()).isEqualTo(6 + 5 + 0 + 0);
    }

    @Test
    void junkIsRefused() {
        byte[] bytes = unit(true).encode(0);
        assertThatThrownBy(() -> WorkUnit.decode(Arrays.copyOf(bytes, 100), 0)).isInstanceOf(IOException.class);
        byte[] huge = bytes.clone();
        huge[11] = 127;                                        // width 127 + 2^24...: too large a tile
        huge[8] = 1;
        assertThatThrownBy(() -> WorkUnit.decode(huge, 0)).isInstanceOf(IOException.class);
        byte[] backwards = bytes.clone();
        backwards[20] = 0;                                     // endSample 80 -> 0 < firstSample
        backwards[23] = 0;
        assertThatThrownBy(() -> WorkUnit.decode(backwards, 0)).isInstanceOf(IOException.class);
        assertThatThrownBy(() -> new WorkUnit(0, 0, 2, 2, 0, 1, new int[3], new double[12])).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new WorkUnit(0, 0, 2, 2, 0, 1, new int[4], new double[13])).as("sums not a whole number per pixel")
                .isInstanceOf(IllegalArgumentException.class);
        byte[] tooMany = bytes.clone();
        tooMany[27] = 99;                                      // 99 sums per pixel
        assertThatThrownBy(() -> WorkUnit.decode(tooMany, 0)).isInstanceOf(IOException.class);
    }
}
