package dev.strahl.film;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

/** A film's state (per pixel count and sums) read out and put back, for checkpoints. */
class FilmStateTest {
    @Test
    void stateRoundTripsExactlyAcrossTileBoundaries() {
        Film a = new Film(70, 37);                           // partial tiles on both edges
        for (int y = 0; y < 37; y++) {
            for (int x = 0; x < 70; x++) {
                for (int s = 0; s < (x + y) % 4; s++) {
                    a.add(a.pixelIndex(x, y), 0.1 * x + s, Math.PI * y, 1e-300 * s);
                }
            }
        }
        Film b = new Film(70, 37);
        double[] sums = new double[3];
        for (int y = 0; y < 37; y++) {
            for (int x = 0; x < 70; x++) {
                int n = a.pixelState(x, y, sums);
                b.restorePixel(x, y, n, sums[0], sums[1], sums[2]);
            }
        }
        double[] other = new double[3];
        for (int y = 0; y < 37; y++) {
            for (int x = 0; x < 70; x++) {
                assertThat(b.pixelState(x, y, other)).isEqualTo(a.pixelState(x, y, sums)).isEqualTo((x + y) % 4);
                assertThat(other).containsExactly(sums);
                assertThat(b.sampleCountAt(b.pixelIndex(x, y))).isEqualTo(b.sampleCount(x, y));
            }
        }
        assertThat(b.toImage().rgb()).containsExactly(a.toImage().rgb());
        assertThat(a.minSampleCount()).isZero();
    }

    @Test
    void minSampleCountIsTheLeastOverRealPixels() {
        Film f = new Film(33, 2);                            // the padding of the second tile column is not a pixel
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 33; x++) {
                f.restorePixel(x, y, x == 32 && y == 1 ? 5 : 9, 0, 0, 0);
            }
        }
        assertThat(f.minSampleCount()).isEqualTo(5);
        assertThatThrownBy(() -> f.restorePixel(0, 0, -1, 0, 0, 0)).isInstanceOf(IllegalArgumentException.class);
    }
}
