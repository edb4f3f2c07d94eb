package dev.strahl.math;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Known values of the numeric helpers. */
class MathUtilTest {

    @Test
    void powerHeuristicKnownValues() {
        assertThat(MathUtil.powerHeuristic(1, 1)).isEqualTo(0.5);
        assertThat(MathUtil.powerHeuristic(2, 1)).isCloseTo(0.8, within(1e-15));      // 4 / (4 + 1)
        assertThat(MathUtil.powerHeuristic(1, 3)).isCloseTo(0.1, within(1e-15));      // 1 / (1 + 9)
        assertThat(MathUtil.powerHeuristic(0.5, 0.25)).isCloseTo(0.8, within(1e-15)); // scale-free
        assertThat(MathUtil.powerHeuristic(1, 0)).as("the other strategy cannot sample it").isEqualTo(1);
        assertThat(MathUtil.powerHeuristic(0, 1)).as("this strategy cannot sample it").isEqualTo(0);
        assertThat(MathUtil.powerHeuristic(0, 0)).as("neither can: no weight, no NaN").isEqualTo(0);
    }

    @Test
    void powerHeuristicWeightsOfTwoStrategiesSumToOne() {
        SplittableRandom random = new SplittableRandom(3);
        for (int i = 0; i < 10_000; i++) {
            // pdfs over many orders of magnitude, as light and BSDF densities are (grazing lights: 1e12).
            double a = Math.pow(10, random.nextDouble(-12, 12)), b = Math.pow(10, random.nextDouble(-12, 12));
            double wa = MathUtil.powerHeuristic(a, b), wb = MathUtil.powerHeuristic(b, a);
            assertThat(wa).as("w(%s, %s)", a, b).isBetween(0.0, 1.0);
            assertThat(wa + wb).as("w(%s, %s) + w(%s, %s)", a, b, b, a).isCloseTo(1, within(1e-12));
            assertThat(wa).isCloseTo(a * a / (a * a + b * b), within(1e-12));
        }
    }

    @Test
    void powerHeuristicOfAnInfiniteOtherDensityIsZero() {
        // A light seen at a grazing angle can have an overflowing solid-angle pdf; the BSDF sample
        // that hits it then gets no weight (and no NaN).
        assertThat(MathUtil.powerHeuristic(2, Double.POSITIVE_INFINITY)).isEqualTo(0);
    }

    @Test
    void safeSqrtTreatsRoundOffBelowZeroAsZero() {
        assertThat(MathUtil.safeSqrt(4)).isEqualTo(2);
        assertThat(MathUtil.safeSqrt(0)).isEqualTo(0);
        assertThat(MathUtil.safeSqrt(-0.0)).isEqualTo(0);
        assertThat(MathUtil.safeSqrt(-1e-17)).isEqualTo(0);
        assertThat(MathUtil.safeSqrt(-1)).isEqualTo(0);
        assertThat(MathUtil.safeSqrt(2)).isEqualTo(Math.sqrt(2));
        assertThat(MathUtil.safeSqrt(Double.POSITIVE_INFINITY)).isEqualTo(Double.POSITIVE_INFINITY);
    }

    @Test
    void safeSqrtDoesNotHideNaN() {
        assertThat(MathUtil.safeSqrt(Double.NaN)).isNaN();
    }

    @Test
    void clampKnownValues() {
        assertThat(MathUtil.clamp(-1, 0, 1)).isEqualTo(0);
        assertThat(MathUtil.clamp(2, 0, 1)).isEqualTo(1);
        assertThat(MathUtil.clamp(0.25, 0, 1)).isEqualTo(0.25);
        assertThat(MathUtil.INV_PI * Math.PI).isCloseTo(1, within(1e-16));
    }
}
