package dev.strahl.bench;

import dev.strahl.material.BsdfSample;
import dev.strahl.material.Glossy;
import dev.strahl.material.Lambert;
import dev.strahl.image.Rgb;
import dev.strahl.sampling.IndependentSampler;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.Sampler;
import dev.strahl.sampling.StratifiedSampler;
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

/** A BSDF sample (Lambert, Glossy) and the random numbers of a pixel sample's first vertex (independent and stratified). */
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
    private final IndependentSampler independent = new IndependentSampler(1);
    private final StratifiedSampler stratified = new StratifiedSampler(1);
    private final Sample2D u = new Sample2D();
    private int sample;

    @Benchmark
    public double lambertSample() {
        independent.get2D(u);
        lambert.sample(wo, independent.get1D(), u.u1, u.u2, out);
        return out.wi.z;
    }

    @Benchmark
    public double glossySample() {
        independent.get2D(u);
        glossy.sample(wo, independent.get1D(), u.u1, u.u2, out);
        return out.wi.z;
    }

    /** The eight numbers of a pixel sample's first vertex from independent streams. */
    @Benchmark
    public double independentFirstVertex() {
        return firstVertex(independent);
    }

    /** The same from the stratified sampler: its eight stratified dimensions (four Owen-scrambled Sobol pairs). */
    @Benchmark
    public double stratifiedFirstVertex() {
        return firstVertex(stratified);
    }

    /** Pixel position, light sample (pair, choice), BSDF sample (lobe, pair): the path tracer's first vertex. */
    private double firstVertex(Sampler sampler) {
        sampler.startPixelSample(2, 3, sample++);
        double s = sampler.getPixel2D(u).u1 + u.u2;
        s += sampler.get2D(u).u1 + u.u2;
        s += sampler.get1D() + sampler.get1D();
        return s + sampler.get2D(u).u1 + u.u2;
    }
}
