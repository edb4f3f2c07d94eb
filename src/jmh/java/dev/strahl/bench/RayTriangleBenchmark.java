package dev.strahl.bench;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.GeometryBuilder;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.RayTriangle;
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
 * The watertight ray–triangle test ({@link RayTriangle}) on a leaf of four triangles, as the BVH
 * runs it: the per-ray set-up, then the four tests (closest hit: all four; any hit: up to the
 * first). Rays are aimed near the triangles so that about half hit.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class RayTriangleBenchmark {
    private static final int RAYS = 1024;

    private float[] pos;
    private int[] tri;
    private byte[] flags;
    private final double[] rays = new double[6 * RAYS];
    private final Ray ray = new Ray();
    private final RayTriangle test = new RayTriangle();
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
        Geometry leaf = new GeometryBuilder().addMesh(xyz, idx, null, new int[4], new byte[4]).build();
        pos = leaf.positionArray();
        tri = leaf.indexArray();
        flags = leaf.flagArray();
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
        test.prepare(nextRay());
        double tMax = Double.POSITIVE_INFINITY;
        int found = -1;
        for (int prim = 0; prim < 4; prim++) {
            if (test.hit(pos, tri, flags, prim, tMax, false)) {
                tMax = test.t;
                found = prim;
            }
        }
        return found;
    }

    @Benchmark
    public boolean anyHitFourTriangles() {
        test.prepare(nextRay());
        for (int prim = 0; prim < 4; prim++) {
            if (test.hit(pos, tri, flags, prim, Double.POSITIVE_INFINITY, false)) {
                return true;
            }
        }
        return false;
    }
}
