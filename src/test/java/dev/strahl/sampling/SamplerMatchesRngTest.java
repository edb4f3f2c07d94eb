package dev.strahl.sampling;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/**
 * While the integrators still draw from {@link Rng}: the samplers give the same numbers for the
 * same sequence of draws (Rng's sample mode and its seeded stream), so that moving a caller
 * from one to the other keeps its image bit-identical where it draws the same sequence.
 */
class SamplerMatchesRngTest {

    @Test
    void stratifiedSamplerEqualsTheSampleModeOfRng() {
        StratifiedSampler sampler = new StratifiedSampler(11);
        Rng rng = new Rng();
        Sample2D u = new Sample2D();
        for (int s = 0; s < 300; s++) {
            int px = s % 17 - 3, py = s / 17;
            rng.startSample(11, px, py, s);
            sampler.startPixelSample(px, py, s);
            sampler.getPixel2D(u);
            assertThat(u.u1).isEqualTo(rng.nextDouble());
            assertThat(u.u2).isEqualTo(rng.nextDouble());
            for (int vertex = 0; vertex < 6; vertex++) {                // the path tracer's draws per vertex
                sampler.get2D(u);
                assertThat(u.u1).isEqualTo(rng.nextDouble());
                assertThat(u.u2).isEqualTo(rng.nextDouble());
                assertThat(sampler.get1D()).isEqualTo(rng.nextDouble());
                assertThat(sampler.get1D()).isEqualTo(rng.nextDouble());
                sampler.get2D(u);
                assertThat(u.u1).isEqualTo(rng.nextDouble());
                assertThat(u.u2).isEqualTo(rng.nextDouble());
                if (vertex >= 3) {
                    assertThat(sampler.get1D()).isEqualTo(rng.nextDouble());
                }
            }
        }
    }

    @Test
    void independentSamplerEqualsRngsStream() {
        IndependentSampler sampler = new IndependentSampler(11);
        Rng rng = new Rng();
        Sample2D u = new Sample2D();
        for (int s = 0; s < 300; s++) {
            rng.seed(Rng.streamSeed(11, s, -s, s / 3));
            sampler.startPixelSample(s, -s, s / 3);
            sampler.getPixel2D(u);
            assertThat(u.u1).isEqualTo(rng.nextDouble());
            assertThat(u.u2).isEqualTo(rng.nextDouble());
            for (int d = 0; d < 40; d++) {
                assertThat(sampler.get1D()).isEqualTo(rng.nextDouble());
            }
            sampler.startStream(s * 31L);
            rng.seed(s * 31L);
            for (int d = 0; d < 40; d++) {
                assertThat(sampler.get1D()).isEqualTo(rng.nextDouble());
            }
        }
    }
}
