package dev.strahl.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class ImageTest {

    private static Image random(int w, int h, long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        float[] rgb = new float[3 * w * h];
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = (float) (4 * rnd.nextDouble());
        }
        return new Image(w, h, rgb);
    }

    @Test
    void downsampleByFourIsTheBoxMeanOfEachBlock() {
        Image img = random(8, 12, 1);
        Image small = img.downsample(4);
        assertThat(small.width()).isEqualTo(2);
        assertThat(small.height()).isEqualTo(3);
        for (int y = 0; y < 3; y++) {
            for (int x = 0; x < 2; x++) {
                for (int c = 0; c < 3; c++) {
                    double sum = 0;
                    for (int j = 4 * y; j < 4 * y + 4; j++) {
                        for (int i = 4 * x; i < 4 * x + 4; i++) {
                            sum += img.get(i, j, c);
                        }
                    }
                    assertThat((double) small.get(x, y, c)).isCloseTo(sum / 16, within(1e-6));
                }
            }
        }
        double[] before = img.mean();
        double[] after = small.mean();
        for (int c = 0; c < 3; c++) {
            assertThat(after[c]).as("box filtering preserves the mean").isCloseTo(before[c], within(1e-6));
        }
    }

    @Test
    void downsampleRefusesAFactorThatDoesNotDivideTheSize() {
        assertThatThrownBy(() -> random(8, 12, 2).downsample(5)).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void relMseOfIdenticalImagesIsZero() {
        Image img = random(16, 9, 3);
        assertThat(img.relMse(random(16, 9, 3))).isEqualTo(0);
    }

    @Test
    void relMseOfAKnownPairIsTheHandComputedValue() {
        Image ref = new Image(1, 1, new float[] {1, 0, 0.5f});
        Image img = new Image(1, 1, new float[] {2, 0.25f, 0.5f});
        // mean over channels of (img − ref)² / (ref² + 0.01): (1/1.01 + 0.0625/0.01 + 0) / 3
        double expected = (1 / 1.01 + 6.25) / 3;
        assertThat(img.relMse(ref)).isCloseTo(expected, within(1e-12));
    }
}
