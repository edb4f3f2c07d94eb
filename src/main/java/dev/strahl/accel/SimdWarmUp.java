package dev.strahl.accel;

import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.GeometryBuilder;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * When the SIMD kernel is fast. Until C2 has compiled it, Vector API code runs in the interpreter
 * and in C1 code, where every lane operation allocates: about a hundred times slower than the
 * scalar kernel (measured: docs/performance.md, round 7), which would make every short render
 * slower than before and cost a long one its first two seconds. So a BVH built for the SIMD kernel
 * ({@link Bvh}) answers with the scalar twin — the same bits — until this says {@link #ready}:
 * a daemon thread, started by the first such query, traces random rays through a small soup of
 * triangles with both kernels and declares the SIMD one ready once it is faster than the scalar
 * one on the same rays three times in a row. It sleeps as long as it worked, so it takes at most
 * half of one core from a render meanwhile; should the SIMD kernel not get faster within a
 * minute, the scalar kernel stays.
 */
final class SimdWarmUp {
    private SimdWarmUp() {}

    private static volatile boolean ready;
    private static final AtomicBoolean STARTED = new AtomicBoolean();
    private static final long GIVE_UP_NANOS = 60_000_000_000L;

    /** Whether the SIMD kernel is compiled and faster; starts the warm-up on the first call. */
    static boolean ready() {
        if (!ready && STARTED.compareAndSet(false, true)) {
            Thread t = new Thread(SimdWarmUp::run, "strahl-simd-warm-up");
            t.setDaemon(true);
            t.start();
        }
        return ready;
    }

    private static void run() {
        SplittableRandom random = new SplittableRandom(1);
        Bvh simd = Bvh.build(soup(random)), scalar = simd.withSimd(false);
        simd = simd.withSimd(true);
        int rays = 128, faster = 0;
        double[] ray = new double[6 * 2048];
        for (int i = 0; i < ray.length; i++) {
            ray[i] = i % 6 < 3 ? random.nextDouble(-0.2, 1.2) : random.nextGaussian();
        }
        TraversalStack stack = new TraversalStack();
        Ray r = new Ray();
        Hit hit = new Hit();
        long start = System.nanoTime();
        while (faster < 3 && System.nanoTime() - start < GIVE_UP_NANOS) {
            long t0 = System.nanoTime();
            trace(simd, ray, rays, r, hit, stack);
            long t1 = System.nanoTime();
            trace(scalar, ray, rays, r, hit, stack);
            long t2 = System.nanoTime();
            faster = t1 - t0 < t2 - t1 ? faster + 1 : 0;
            rays = Math.min(2 * rays, 2048);
            try {
                Thread.sleep((t2 - t0) / 1_000_000);
            } catch (InterruptedException e) {
                return;
            }
        }
        ready = faster >= 3;
    }

    private static void trace(Bvh bvh, double[] ray, int rays, Ray r, Hit hit, TraversalStack stack) {
        for (int i = 0; i < rays; i++) {
            int k = 6 * i;
            r.o.set(ray[k], ray[k + 1], ray[k + 2]);
            r.d.set(ray[k + 3], ray[k + 4], ray[k + 5]).normalize();
            r.tMax = Double.POSITIVE_INFINITY;
            bvh.intersect(r, hit.reset(), stack, (i & 1) == 0);
            r.tMax = 0.5;
            bvh.occluded(r, stack);
        }
    }

    /** Two thousand small random triangles in the unit cube, half of them in a closed mesh (so culling runs too). */
    private static Geometry soup(SplittableRandom random) {
        int n = 2000;
        float[] p = new float[9 * n];
        int[] idx = new int[3 * n];
        for (int t = 0; t < n; t++) {
            double cx = random.nextDouble(), cy = random.nextDouble(), cz = random.nextDouble();
            for (int k = 0; k < 9; k++) {
                p[9 * t + k] = (float) ((k % 3 == 0 ? cx : k % 3 == 1 ? cy : cz) + 0.05 * random.nextDouble(-1, 1));
            }
        }
        for (int i = 0; i < idx.length; i++) {
            idx[i] = i;
        }
        byte[] flags = new byte[n];
        java.util.Arrays.fill(flags, 0, n / 2, Geometry.CLOSED);
        return new GeometryBuilder().addMesh(p, idx, null, new int[n], flags).build();
    }
}
