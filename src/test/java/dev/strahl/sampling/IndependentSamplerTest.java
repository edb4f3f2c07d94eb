package dev.strahl.sampling;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

/**
 * The independent sampler: dimension d of a pixel sample is position d + 1 of its stream, pairs
 * are plain consecutive dimensions, and a stream started on its own counts from 0.
 */
class IndependentSamplerTest {

    @Test
    void dimensionDIsPositionDPlusOneOfTheSamplesStream() {
        IndependentSampler sampler = new IndependentSampler(7);
        sampler.startPixelSample(13, 21, 5);
        long stream = SplitMix64.streamSeed(7, 13, 21, 5);
        Sample2D pixel = sampler.getPixel2D(new Sample2D());
        assertThat(pixel.u1).isEqualTo(SplitMix64.toUnit(SplitMix64.at(stream, 1)));
        assertThat(pixel.u2).isEqualTo(SplitMix64.toUnit(SplitMix64.at(stream, 2)));
        assertThat(sampler.dimension()).isEqualTo(Sampler.FIRST_INTEGRATOR_DIMENSION);
        assertThat(sampler.get1D()).isEqualTo(SplitMix64.toUnit(SplitMix64.at(stream, 3)));
        Sample2D u = sampler.get2D(new Sample2D());
        assertThat(sampler.dimension()).as("no padding: every dimension is independent").isEqualTo(5);
        assertThat(u.u1).isEqualTo(SplitMix64.toUnit(SplitMix64.at(stream, 4)));
        assertThat(u.u2).isEqualTo(SplitMix64.toUnit(SplitMix64.at(stream, 5)));
    }

    @Test
    void aStreamStartedOnItsOwnCountsFromZero() {
        IndependentSampler sampler = new IndependentSampler(1);
        sampler.startPixelSample(1, 2, 3);
        sampler.get1D();
        sampler.startStream(12345);
        for (int k = 1; k <= 10; k++) {
            assertThat(sampler.get1D()).isEqualTo(SplitMix64.toUnit(SplitMix64.at(12345, k)));
        }
    }

    @Test
    void theNumbersAreAFunctionOfSeedPixelAndSampleAlone() {
        IndependentSampler a = new IndependentSampler(4), b = new IndependentSampler(4);
        a.startPixelSample(9, 9, 9);
        a.get2D(new Sample2D());
        a.startPixelSample(3, 5, 8);
        b.startPixelSample(3, 5, 8);
        for (int d = 0; d < 50; d++) {
            assertThat(a.get1D()).isEqualTo(b.get1D());
        }
        b.startPixelSample(3, 5, 9);
        a.startPixelSample(3, 5, 8);
        assertThat(b.get1D()).isNotEqualTo(a.get1D());
    }

    @Test
    void pixelsAndDimensionsAreUncorrelated() {
        int n = 128 * 128;
        double bound = 5 / Math.sqrt(n);
        double[] here = new double[n], right = new double[n], nextDimension = new double[n];
        IndependentSampler sampler = new IndependentSampler(2);
        for (int i = 0; i < n; i++) {
            sampler.startPixelSample(i % 128, i / 128, 0);
            here[i] = sampler.get1D();
            nextDimension[i] = sampler.get1D();
            sampler.startPixelSample(i % 128 + 1, i / 128, 0);
            right[i] = sampler.get1D();
        }
        assertThat(SplitMix64Test.correlation(here, right)).isCloseTo(0, within(bound));
        assertThat(SplitMix64Test.correlation(here, nextDimension)).isCloseTo(0, within(bound));
    }
}
