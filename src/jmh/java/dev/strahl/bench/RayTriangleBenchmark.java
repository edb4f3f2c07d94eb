package dev.strahl.bench;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.scene.TriangleMesh;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.joml.Vector3d;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * The watertight ray–triangle test on a leaf of four triangles (closest hit and any hit), rays
 * aimed near the triangles so that about half hit.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class RayTriangleBenchmark {
    private static final int RAYS = 1024;

    private Geometry leaf;
    private final double[] rays = new double[6 * RAYS];
    private final Ray ray = new Ray();
    private final Hit hit = new Hit();
    private int next;

    @Setup
    public void setUp() {
        SplittableRandom random = new SplittableRandom(2);
        float[] xyz = new float[36];
        for (int i = 0; i < xyz.length; i++) {
            xyz[i] = (float) random.nextDouble(-1, 1);
        }
        int[] idx = new int[12];
        for (int i = 0; i < 12; i++) {
            idx[i] = i;
        }
        leaf = new Geometry.Builder().addMesh(new TriangleMesh(xyz, idx, null), new int[4], false).build();
        Vector3d o = new Vector3d(), d = new Vector3d();
        for (int i = 0; i < RAYS; i++) {
            o.set(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize(3);
            d.set(random.nextDouble(-0.5, 0.5), random.nextDouble(-0.5, 0.5), random.nextDouble(-0.5, 0.5)).sub(o).normalize();
            rays[6 * i] = o.x;
            rays[6 * i + 1] = o.y;
            rays[6 * i + 2] = o.z;
            rays[6 * i + 3] = d.x;
            rays[6 * i + 4] = d.y;
            rays[6 * i + 5] = d.z;
        }
    }

    private Ray nextRay() {
        int k = 6 * (next++ & (RAYS - 1));
        ray.o.set(rays[k], rays[k + 1], rays[k + 2]);
        ray.d.set(rays[k + 3], rays[k + 4], rays[k + 5]);
        ray.tMax = Double.POSITIVE_INFINITY;
        return ray;
    }

    @Benchmark
    public int closestHitFourTriangles() {
        hit.reset();
        return leaf.intersect(0, 4, nextRay(), hit, false) ? hit.prim : -1;
    }

    @Benchmark
    public boolean anyHitFourTriangles() {
        return leaf.occludes(0, 4, nextRay());
    }
}
