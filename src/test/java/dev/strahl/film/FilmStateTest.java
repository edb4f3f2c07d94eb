package dev.strahl.film;

import dev.strahl.integrator.FeatureTracer;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

/** A film's state (per pixel count and sums) read out and put back, for checkpoints. */
class FilmStateTest {
    @Test
    void stateRoundTripsExactlyAcrossTileBoundaries() {
        Film a = new Film(70, 37, true);                     // partial tiles on both edges
        double[] f = new double[FeatureTracer.CHANNELS];
        for (int y = 0; y < 37; y++) {
            for (int x = 0; x < 70; x++) {
                for (int s = 0; s < (x + y) % 4; s++) {
                    a.add(a.pixelIndex(x, y), 0.1 * x + s, Math.PI * y, 1e-300 * s);
                    for (int i = 0; i < f.length; i++) {
                        f[i] = x + 0.01 * y + 1e-3 * s + i;
                    }
                    a.addFeatures(a.pixelIndex(x, y), f);
                }
            }
        }
        Film b = new Film(70, 37, true);
        double[] sums = new double[a.stateSums()];
        assertThat(sums).hasSize(4 + FeatureTracer.CHANNELS);
        for (int y = 0; y < 37; y++) {
            for (int x = 0; x < 70; x++) {
                int n = a.pixelState(x, y, sums);
                b.restorePixel(x, y, n, sums);
            }
        }
        double[] other = new double[sums.length];
        for (int y = 0; y < 37; y++) {
            for (int x = 0; x < 70; x++) {
                assertThat(b.pixelState(x, y, other)).isEqualTo(a.pixelState(x, y, sums)).isEqualTo((x + y) % 4);
                assertThat(other).containsExactly(sums);
                assertThat(b.sampleCountAt(b.pixelIndex(x, y))).isEqualTo(b.sampleCount(x, y));
            }
        }
        assertThat(b.toImage().rgb()).containsExactly(a.toImage().rgb());
        assertThat(b.varianceImage().rgb()).containsExactly(a.varianceImage().rgb());
        for (int offset : new int[] {0, 3, 6}) {
            assertThat(b.featureImage(offset).rgb()).containsExactly(a.featureImage(offset).rgb());
        }
        assertThat(a.minSampleCount()).isZero();
    }

    /** The variance of a pixel's mean luminance, from samples whose variance is known. */
    @Test
    void varianceIsTheSampleVarianceOfTheMeanLuminance() {
        Film f = new Film(3, 1);
        double[] ys = {1, 2, 3, 6};                          // mean 3, unbiased sample variance 14/3
        for (double y : ys) {
            f.add(f.pixelIndex(0, 0), y, y, y);              // grey: luminance = y
            f.add(f.pixelIndex(1, 0), 5, 5, 5);              // constant: no variance
        }
        f.add(f.pixelIndex(2, 0), 9, 0, 0);                  // one sample: variance unknown, 0
        var v = f.varianceImage();
        assertThat((double) v.get(0, 0, 0)).isCloseTo(14.0 / 3 / 4, org.assertj.core.api.Assertions.within(1e-6));
        assertThat(v.get(0, 0, 1)).isEqualTo(v.get(0, 0, 0));
        assertThat(v.get(1, 0, 0)).isEqualTo(0f);
        assertThat(v.get(2, 0, 0)).isEqualTo(0f);
    }

    @Test
    void featureBuffersAreMeansAndAbsentUnlessAsked() {
        Film f = new Film(2, 2, true);
        f.add(f.pixelIndex(1, 1), 1, 1, 1);
        f.addFeatures(f.pixelIndex(1, 1), new double[] {0.2, 0.4, 0.6, 0, 1, 0, 3});
        f.add(f.pixelIndex(1, 1), 1, 1, 1);
        f.addFeatures(f.pixelIndex(1, 1), new double[] {0.4, 0.4, 0.4, 0, 0, 1, 5});
        assertThat(f.featureImage(0).get(1, 1, 0)).isEqualTo(0.3f);
        assertThat(f.featureImage(3).get(1, 1, 2)).isEqualTo(0.5f);
        assertThat(f.featureImage(6).get(1, 1, 1)).isEqualTo(4f);
        assertThat(f.featureImage(0).get(0, 0, 0)).isEqualTo(0f);
        Film plain = new Film(2, 2);
        assertThat(plain.hasFeatures()).isFalse();
        assertThatThrownBy(() -> plain.addFeatures(0, new double[7])).isInstanceOf(IllegalStateException.class);
        assertThat(plain.varianceImage().width()).isEqualTo(2);
    }

    @Test
    void minSampleCountIsTheLeastOverRealPixels() {
        Film f = new Film(33, 2);                            // the padding of the second tile column is not a pixel
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 33; x++) {
                f.restorePixel(x, y, x == 32 && y == 1 ? 5 : 9, new double[4]);
            }
        }
        assertThat(f.minSampleCount()).isEqualTo(5);
        assertThatThrownBy(() -> f.restorePixel(0, 0, -1, new double[4])).isInstanceOf(IllegalArgumentException.class);
    }
}
