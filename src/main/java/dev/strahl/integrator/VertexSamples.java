package dev.strahl.integrator;

import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.Sampler;

/**
 * The random numbers of one path vertex, drawn in one place and one order whatever the surface
 * (pbrt-v4's per-depth samples): the light sample — a pair for the point on the light, then one
 * number for the choice of light —, the BSDF sample — one number for the lobe, a pair for the
 * direction — and, from {@link PathTracer#RR_DEPTH} on, one number for Russian roulette. With the
 * stratified sampler the first vertex's numbers are its stratified dimensions 2–7: the pairs
 * (light point), (light choice, lobe choice), (BSDF direction).
 */
final class VertexSamples {
    double lightU1, lightU2, lightChoice;
    double lobe, directionU1, directionU2;
    /** Russian roulette's number; 0 where the vertex plays none. */
    double roulette;
    private final Sample2D pair = new Sample2D();

    /** Draws the vertex's numbers, the roulette's too when {@code roulette}. */
    void draw(Sampler sampler, boolean roulette) {
        sampler.get2D(pair);
        lightU1 = pair.u1;
        lightU2 = pair.u2;
        lightChoice = sampler.get1D();
        lobe = sampler.get1D();
        sampler.get2D(pair);
        directionU1 = pair.u1;
        directionU2 = pair.u2;
        this.roulette = roulette ? sampler.get1D() : 0;
    }
}
