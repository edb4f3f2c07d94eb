package dev.strahl.integrator;

import dev.strahl.camera.CameraRays;
import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Ray;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.StratifiedSampler;
import java.lang.management.ManagementFactory;

/**
 * The bytes a worker allocates per batch of camera samples, measured with the thread's
 * allocated-bytes counter: rounds of {@code samples} samples over a {@code side}² film, each with a
 * sampler of its own seed, until one round allocates nothing (the interpreter and C1 may box Vector
 * API values until the hot code is compiled); the best round counts.
 */
final class SampleAllocation {
    /** The fewest bytes a round allocated, and the sum of the green radiance (so the work is not dead). */
    record Result(long bestRoundBytes, double greenSum) {}

    private SampleAllocation() {}

    static Result bestRound(Integrator.Worker worker, CameraRays camera, int side, int samples, int rounds) {
        Ray ray = new Ray();
        Sample2D film = new Sample2D();
        MutableRgb out = new MutableRgb();
        var threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long allocated = Long.MAX_VALUE;
        double sum = 0;
        for (int round = 0; round < rounds && allocated > 0; round++) {
            StratifiedSampler sampler = new StratifiedSampler(round);
            long before = threads.getCurrentThreadAllocatedBytes();
            for (int i = 0; i < samples; i++) {
                int x = i % side, y = (i / side) % side;
                sampler.startPixelSample(x, y, i / (side * side));
                sampler.getPixel2D(film);
                camera.generate(x + film.u1, y + film.u2, ray);
                worker.radiance(ray, sampler, out);
                sum += out.g;
            }
            allocated = Math.min(allocated, threads.getCurrentThreadAllocatedBytes() - before);
        }
        return new Result(allocated, sum);
    }
}
