package dev.strahl.render;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import dev.strahl.film.Film;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The stopping rule on films filled by hand: what the threshold measures, the window, the boundaries and the saved state. */
class NoiseTargetTest {

    /** Adds {@code n} grey samples to a pixel: value {@code v}, or {@code bright} for one of them in every {@code every} (0: never). */
    private static void fill(Film film, int x, int y, int n, double v, double bright, int every) {
        int p = film.pixelIndex(x, y);
        for (int i = 0; i < n; i++) {
            double s = every > 0 && i % every == every - 1 ? bright : v;
            film.add(p, s, s, s);
        }
    }

    @Test
    void theErrorIsTheStandardErrorOfTheMeanOverTheMeanOrTheFloor() {
        Film film = new Film(2, 1);
        fill(film, 0, 0, 40, 0.2, 1.2, 4);                       // 30 x 0.2, 10 x 1.2: mean 0.45
        int p = film.pixelIndex(0, 0);
        double mean = 0.45, var = (30 * Math.pow(0.2 - mean, 2) + 10 * Math.pow(1.2 - mean, 2)) / 39;
        assertThat(film.meanLuminance(p)).isCloseTo(mean, within(1e-12));
        assertThat(film.varianceOfMean(p)).isCloseTo(var / 40, within(1e-12));
        assertThat(NoiseTarget.relativeError(mean, var / 40)).isCloseTo(Math.sqrt(var / 40) / mean, within(1e-12));
        // darker than the floor: measured against the floor, so a black pixel is done at once
        assertThat(NoiseTarget.relativeError(0.01, 1e-6)).isCloseTo(1e-3 / NoiseTarget.FLOOR, within(1e-12));
        assertThat(NoiseTarget.relativeError(0, 0)).isZero();
    }

    @Test
    void boundariesComeEverySixteenSamplesThenEveryQuarter() {
        int[] expected = {32, 48, 64, 80, 96, 112, 128, 160, 192, 240, 288, 352, 432, 528, 656};
        int b = 0;
        for (int e : expected) {
            b = NoiseTarget.nextBoundary(b);
            assertThat(b).isEqualTo(e);
        }
        for (int i = 0; i < 40; i++) {
            int next = NoiseTarget.nextBoundary(b);
            assertThat(next % 16).isZero();
            assertThat(next - b).isBetween(b / 4 - 16, b / 4);
            b = next;
        }
    }

    /** A flat film with one noisy pixel: it and every pixel within two of it go on, the rest stop. */
    @Test
    void aNoisyPixelKeepsItsWindowSampling() {
        Film film = new Film(40, 40);
        for (int y = 0; y < 40; y++) {
            for (int x = 0; x < 40; x++) {
                fill(film, x, y, 32, 0.5, 0, 0);
            }
        }
        film.restorePixel(20, 10, 0, new double[4]);
        fill(film, 20, 10, 32, 0.1, 10, 16);                     // two bright samples in 32: about 40 % error
        NoiseTarget target = new NoiseTarget(film, 0.05);
        assertThat(target.goal(4096)).isEqualTo(32);
        assertThat(target.decidesAt(32)).isTrue();
        assertThat(target.decide(4096)).isTrue();
        for (int y = 0; y < 40; y++) {
            for (int x = 0; x < 40; x++) {
                boolean near = Math.abs(x - 20) <= 2 && Math.abs(y - 10) <= 2;
                assertThat(target.renders(film.pixelIndex(x, y))).as("%d,%d", x, y).isEqualTo(near);
            }
        }
        assertThat(target.convergedFraction()).isCloseTo(1 - 25 / 1600.0, within(1e-12));
        assertThat(target.rendersTile(0)).isTrue();                  // the tile of (20, 10)
        assertThat(target.rendersTile(1)).isFalse();
        assertThat(target.start()).isEqualTo(32);
        assertThat(target.goal(4096)).isEqualTo(48);
        assertThat(target.goal(40)).as("the sample count comes first").isEqualTo(40);
        assertThat(target.decidesAt(40)).isFalse();
        // what is left is estimated from the error's fall as 1/sqrt(n), no pixel beyond the sample count
        assertThat(target.estimatedTotalSamples()).isGreaterThan(1600 * 32).isLessThanOrEqualTo(1575 * 32 + 25 * 4096.0);
    }

    /** A threshold above every pixel's error ends the render at the first decision, one below it does not. */
    @Test
    void aCleanFilmConvergesAtTheFirstBoundaryAndNotBefore() {
        Film film = new Film(8, 8);
        SplittableRandom r = new SplittableRandom(1);
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 8; x++) {
                int p = film.pixelIndex(x, y);
                for (int i = 0; i < 32; i++) {
                    double v = 0.5 + 0.1 * (r.nextDouble() - 0.5);
                    film.add(p, v, v, v);
                }
            }
        }
        NoiseTarget target = new NoiseTarget(film, 0.02);             // about 1 % error everywhere
        assertThat(target.convergedFraction()).isZero();
        assertThat(target.decide(1000)).isFalse();
        assertThat(target.convergedFraction()).isEqualTo(1);
        assertThat(target.start()).isEqualTo(Integer.MAX_VALUE);
        assertThat(new NoiseTarget(film, 0.005).decide(1000)).as("1 percent is not half a percent").isTrue();
    }

    @Test
    void theStateRoundTripsThroughItsPackedForm() {
        Film film = new Film(13, 5);
        boolean[] mask = new boolean[65];
        for (int i = 0; i < mask.length; i++) {
            mask[i] = i % 3 == 0 || i == 64;
        }
        NoiseTarget target = new NoiseTarget(film, 0.1, 48, mask);
        NoiseTarget.State s = target.state();
        assertThat(s.boundary()).isEqualTo(48);
        assertThat(s.mask()).isEqualTo(mask);
        byte[] packed = s.packedMask();
        assertThat(packed).hasSize(9);
        assertThat(NoiseTarget.State.unpacked(48, packed, 65).mask()).isEqualTo(mask);
        assertThat(target.renders(film.pixelIndex(1, 0))).isFalse();
        assertThat(target.renders(film.pixelIndex(3, 0))).isTrue();
        assertThat(target.goal(1000)).isEqualTo(64);
        assertThatThrownBy(() -> new NoiseTarget(film, 0.1, 48, new boolean[64])).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new NoiseTarget(film, 0)).isInstanceOf(IllegalArgumentException.class);
    }
}
