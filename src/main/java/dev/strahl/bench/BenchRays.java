package dev.strahl.bench;

import dev.strahl.accel.Aggregate;
import dev.strahl.accel.RayBatch;
import dev.strahl.accel.TraversalStack;
import dev.strahl.scene.Camera;
import dev.strahl.camera.CameraRays;
import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.io.json.JsonFile;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import org.joml.Vector3d;

/**
 * The ray sets and kernels of {@code strahl bench}: rays made in advance (so that making them is
 * not timed), traced on a pool of threads, and a brute-force check of a subset so that a broken
 * fast path cannot win.
 */
public final class BenchRays {
    private BenchRays() {}

    /** Rays in flat arrays: origin, direction, tMax (7 doubles per ray); shadow rays ask only for any hit. */
    public record RaySet(String name, double[] data, int count, boolean anyHit) {}

    /** What tracing a set gave: wall time, the tracing threads' CPU time, hits, and an order-independent checksum of the hit primitives. */
    public record Result(double seconds, double cpuSeconds, long hits, long checksum) {}

    /** Camera rays through jittered points of a width × height film, {@code spp} per pixel. */
    public static RaySet primary(Camera camera, int width, int height, int spp, long seed) {
        CameraRays rays = CameraRays.pinholeOf(camera, width, height);
        SplittableRandom random = new SplittableRandom(seed);
        int n = width * height * spp;
        double[] data = new double[7 * n];
        Ray ray = new Ray();
        int k = 0;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                for (int s = 0; s < spp; s++) {
                    rays.generate(x + random.nextDouble(), y + random.nextDouble(), ray);
                    k = put(data, k, ray.o, ray.d, Double.POSITIVE_INFINITY);
                }
            }
        }
        return new RaySet("primary", data, n, false);
    }

    /** Origins uniform in the box, directions uniform on the sphere. */
    public static RaySet incoherent(Aabb box, int n, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double[] data = new double[7 * n];
        Vector3d o = new Vector3d(), d = new Vector3d();
        int k = 0;
        for (int i = 0; i < n; i++) {
            o.set(box.minX + random.nextDouble() * (box.maxX - box.minX), box.minY + random.nextDouble() * (box.maxY - box.minY),
                    box.minZ + random.nextDouble() * (box.maxZ - box.minZ));
            double z = 1 - 2 * random.nextDouble(), r = Math.sqrt(Math.max(0, 1 - z * z)), phi = 2 * Math.PI * random.nextDouble();
            d.set(r * Math.cos(phi), r * Math.sin(phi), z);
            k = put(data, k, o, d, Double.POSITIVE_INFINITY);
        }
        return new RaySet("incoherent", data, n, false);
    }

    /**
     * Shadow rays between pairs of random surface points (primitives chosen uniformly, points
     * uniform on them), both ends moved off their surfaces as the renderer does.
     */
    public static RaySet shadow(Geometry g, int n, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double[] data = new double[7 * n];
        SurfacePoint a = new SurfacePoint(), b = new SurfacePoint();
        Vector3d o = new Vector3d(), target = new Vector3d(), d = new Vector3d(), back = new Vector3d();
        int k = 0;
        for (int i = 0; i < n; i++) {
            double dist;
            do {
                g.samplePoint(random.nextInt(g.primitiveCount()), random.nextDouble(), random.nextDouble(), a);
                g.samplePoint(random.nextInt(g.primitiveCount()), random.nextDouble(), random.nextDouble(), b);
                d.set(b.p).sub(a.p).normalize();
                a.spawnOrigin(d, o);
                back.set(d).negate();
                b.spawnOrigin(back, target);
                dist = target.distance(o);
            } while (!(dist > 0));
            d.set(target).sub(o).div(dist);
            k = put(data, k, o, d, dist);
        }
        return new RaySet("shadow", data, n, true);
    }

    /**
     * Writes a mesh's triangles and ray sets for the anchors script ({@code docs/bench/anchors.py},
     * which traces the same rays with Embree): {@code NAME.triangles.f32} (9 little-endian floats
     * per triangle, the three vertices), {@code NAME.SET.f32} per set (7 floats per ray: origin,
     * direction, tMax, infinite for closest-hit sets) and {@code NAME.json} describing them.
     * Spheres are not written (the benchmark meshes have none; the JSON gives their count).
     */
    public static void export(Path dir, String name, String file, Geometry g, List<RaySet> sets) throws IOException {
        float[] pos = g.positionArray();
        int[] tri = g.indexArray();
        int n = g.triangleCount();
        ByteBuffer b = ByteBuffer.allocate(36 * n).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < 3 * n; i++) {
            int v = 3 * tri[i];
            b.putFloat(pos[v]).putFloat(pos[v + 1]).putFloat(pos[v + 2]);
        }
        Files.write(dir.resolve(name + ".triangles.f32"), b.array());
        for (RaySet set : sets) {
            ByteBuffer r = ByteBuffer.allocate(28 * set.count()).order(ByteOrder.LITTLE_ENDIAN);
            for (double x : set.data()) {
                r.putFloat((float) x);
            }
            Files.write(dir.resolve(name + "." + set.name() + ".f32"), r.array());
        }
        JsonFile.write(dir.resolve(name + ".json"), json -> {
            json.writeStartObject();
            json.writeStringField("mesh", name);
            json.writeStringField("file", file);
            json.writeNumberField("triangles", n);
            json.writeNumberField("spheres", g.sphereCount());
            json.writeArrayFieldStart("sets");
            for (RaySet set : sets) {
                json.writeStartObject();
                json.writeStringField("name", set.name());
                json.writeNumberField("rays", set.count());
                json.writeBooleanField("any_hit", set.anyHit());
                json.writeEndObject();
            }
            json.writeEndArray();
            json.writeEndObject();
        });
    }

    private static int put(double[] data, int k, Vector3d o, Vector3d d, double tMax) {
        data[k] = o.x;
        data[k + 1] = o.y;
        data[k + 2] = o.z;
        data[k + 3] = d.x;
        data[k + 4] = d.y;
        data[k + 5] = d.z;
        data[k + 6] = tMax;
        return k + 7;
    }

    private static void load(double[] data, int i, Ray ray) {
        int k = 7 * i;
        ray.o.set(data[k], data[k + 1], data[k + 2]);
        ray.d.set(data[k + 3], data[k + 4], data[k + 5]);
        ray.tMax = data[k + 6];
    }

    /** Traces the set on {@code threads} threads of the pool, each a contiguous share. */
    public static Result trace(Aggregate bvh, RaySet set, int threads, ExecutorService pool) throws InterruptedException {
        List<Callable<long[]>> tasks = new ArrayList<>();
        for (int t = 0; t < threads; t++) {
            int from = (int) ((long) set.count() * t / threads), to = (int) ((long) set.count() * (t + 1) / threads);
            tasks.add(() -> traceRange(bvh, set, from, to));
        }
        long start = System.nanoTime();
        List<Future<long[]>> futures = pool.invokeAll(tasks);
        double seconds = (System.nanoTime() - start) * 1e-9;
        long hits = 0, checksum = 0, cpu = 0;
        for (Future<long[]> f : futures) {
            try {
                hits += f.get()[0];
                checksum += f.get()[1];
                cpu += f.get()[2];
            } catch (ExecutionException e) {
                throw new IllegalStateException("ray kernel failed: " + e.getCause(), e.getCause());
            }
        }
        return new Result(seconds, cpu * 1e-9, hits, checksum);
    }

    /** Rays per batch query: the thread's batch is filled from the set and traced with one call. */
    private static final int BATCH = 256;

    private static long[] traceRange(Aggregate bvh, RaySet set, int from, int to) {
        RayBatch batch = new RayBatch(BATCH);
        TraversalStack stack = new TraversalStack();
        double[] data = set.data();
        long hits = 0, checksum = 0;
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        long cpu0 = mx.getCurrentThreadCpuTime();
        for (int first = from; first < to; first += BATCH) {
            int n = Math.min(BATCH, to - first);
            for (int j = 0, k = 7 * first; j < n; j++, k += 7) {
                batch.set(j, data[k], data[k + 1], data[k + 2], data[k + 3], data[k + 4], data[k + 5], data[k + 6]);
            }
            if (set.anyHit()) {
                bvh.occluded(batch, 0, n, stack);
                for (int j = 0; j < n; j++) {
                    if (batch.occluded[j]) {
                        hits++;
                        checksum += first + j;
                    }
                }
            } else {
                bvh.intersect(batch, 0, n, stack, false);
                for (int j = 0; j < n; j++) {
                    if (batch.prim[j] >= 0) {
                        hits++;
                        checksum += batch.prim[j] + 1;
                    }
                }
            }
        }
        return new long[] {hits, checksum, mx.getCurrentThreadCpuTime() - cpu0};
    }

    /**
     * Compares the BVH with a loop over every primitive on {@code samples} rays spread over the
     * set: the same hit or miss, the same primitive (or one at the same distance, a tie), the same
     * occlusion answer. Returns a description of the first difference, or null.
     */
    public static String check(Aggregate bvh, RaySet set, int samples) {
        Geometry g = bvh.geometry();
        TraversalStack stack = new TraversalStack();
        Ray r = new Ray(), rb = new Ray();
        Hit hit = new Hit(), brute = new Hit();
        int step = Math.max(1, set.count() / Math.max(1, samples));
        for (int i = 0; i < set.count(); i += step) {
            load(set.data(), i, r);
            load(set.data(), i, rb);
            if (set.anyHit()) {
                boolean expected = g.occludes(0, g.triangleCount(), rb)
                        || (g.sphereCount() > 0 && g.occludes(g.triangleCount(), g.sphereCount(), rb));
                if (bvh.occluded(r, stack) != expected) {
                    return set.name() + " ray " + i + ": BVH says " + !expected + ", brute force " + expected;
                }
                continue;
            }
            hit.reset();
            brute.reset();
            boolean found = bvh.intersect(r, hit, stack, false);
            boolean expected = g.intersect(0, g.triangleCount(), rb, brute, false);
            if (g.sphereCount() > 0) {
                expected |= g.intersect(g.triangleCount(), g.sphereCount(), rb, brute, false);
            }
            if (found != expected) {
                return set.name() + " ray " + i + ": BVH " + (found ? "hits" : "misses") + ", brute force " + (expected ? "hits" : "misses");
            }
            if (found && hit.prim != brute.prim && Math.abs(hit.t - brute.t) > 1e-12 * brute.t) {
                return set.name() + " ray " + i + ": BVH hits primitive " + hit.prim + " at " + hit.t + ", brute force " + brute.prim + " at " + brute.t;
            }
        }
        return null;
    }
}
