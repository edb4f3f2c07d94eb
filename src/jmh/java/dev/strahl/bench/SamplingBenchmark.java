package dev.strahl.bench;

import dev.strahl.material.BsdfSample;
import dev.strahl.material.Glossy;
import dev.strahl.material.Lambert;
import dev.strahl.image.Rgb;
import dev.strahl.sampling.Rng;
import java.util.concurrent.TimeUnit;
import org.joml.Vector3d;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/** A BSDF sample (Lambert, Glossy) and the random numbers of one path vertex (stream and stratified). */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class SamplingBenchmark {
    private final Lambert lambert = new Lambert(Rgb.gray(0.7));
    private final Glossy glossy = Glossy.fromPhongExponent(Rgb.gray(0.3), Rgb.gray(0.5), 50);
    private final Vector3d wo = new Vector3d(0.3, 0.2, 0.9).normalize();
    private final BsdfSample out = new BsdfSample();
    private final Rng rng = new Rng(1);
    private int sample;

    @Benchmark
    public double lambertSample() {
        lambert.sample(wo, rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), out);
        return out.wi.z;
    }

    @Benchmark
    public double glossySample() {
        glossy.sample(wo, rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), out);
        return out.wi.z;
    }

    /** Eight draws of the plain stream. */
    @Benchmark
    public double streamEightDraws() {
        rng.seed(Rng.streamSeed(1, 2, 3, sample++));
        double s = 0;
        for (int i = 0; i < 8; i++) {
            s += rng.nextDouble();
        }
        return s;
    }

    /** Eight stratified dimensions of a sample (four Owen-scrambled Sobol pairs). */
    @Benchmark
    public double stratifiedEightDraws() {
        rng.startSample(1, 2, 3, sample++);
        double s = 0;
        for (int i = 0; i < 8; i++) {
            s += rng.nextDouble();
        }
        return s;
    }
}
