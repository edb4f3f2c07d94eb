package dev.strahl.integrator;

import dev.strahl.accel.RayBatch;
import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Geometry;
import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;
import dev.strahl.material.Bsdf;
import dev.strahl.sampling.Sampler;

/**
 * The path tracer as a wavefront: a batch of paths advanced together, stage by stage — closest
 * hits of every live path, then shading of every hit grouped by the kind of its BSDF (the vertex kernel
 * {@link PathTracer#scatter}: emission, the light sample's shadow query, the BSDF sample, the
 * roulette), then the batch's shadow rays, then compaction of the paths still alive — instead of
 * one path from camera to end at a time. One per worker thread; every array is allocated once.
 *
 * <p>Each path has its own sampler, and every path goes through the same kernels with the same
 * numbers in the same order as the scalar worker's: the radiance of each is the same bits.
 * What a path carries between stages lives in flat arrays (its ray, throughput, last BSDF
 * sample, hit, shadow query, radiance), in double, as the scalar path holds it.
 *
 * <p>Use: {@link #sampler} of each slot is started for its pixel sample by the caller, which gives
 * the slot its camera ray ({@link #start}); {@link #run} traces slots [0, count) to their ends;
 * then {@link #red}, {@link #green}, {@link #blue} are each slot's radiance.
 */
public final class PathWavefront {
    /**
     * The system property that turns the wavefront on for the {@code path} renders started while it
     * is "on" (the render package reads it when a job starts; {@code strahl --wavefront on} sets it).
     */
    public static final String PROPERTY = "strahl.wavefront";

    private final PathTracer pt;
    private final PathTracer.PathWorker w;
    private final Sampler[] samplers;
    private final int capacity;
    /** Each material's kind: the index of its BSDF's class among the scene's; what stage 2 groups by. */
    private final int[] kindOf;
    private final int kinds;
    // the path state of each slot
    private final double[] ray, beta, prevPdf, etaScale, radiance;  // ray: o, d, tMax (7 per slot); beta, radiance: 3 per slot
    private final boolean[] prevDelta;
    private final int[] depth;
    // the rays of the live paths in live order, with their closest hits: the closest-hit stage's batch query
    private final RayBatch queue;
    // the shadow rays of a stage (traced ones only), with what each adds and to which slot
    private final RayBatch shadows;
    private final double[] shadowContribution;
    private final int[] shadowSlot;
    // live paths' slots in slot order; identity and grouped: positions in live in the order stage 2 shades them
    private final int[] live, identity, shadeOrder, kindStart;
    private final Ray r = new Ray();
    private final Hit hit = new Hit();
    private final MutableRgb out = new MutableRgb();

    PathWavefront(PathTracer pt, Sampler[] samplers) {
        this.pt = pt;
        this.w = pt.new PathWorker();
        this.samplers = samplers.clone();
        this.capacity = samplers.length;
        var classes = new java.util.ArrayList<Class<?>>();
        Bsdf[] bsdfs = pt.bsdfs();
        this.kindOf = new int[bsdfs.length];
        for (int m = 0; m < bsdfs.length; m++) {
            if (!classes.contains(bsdfs[m].getClass())) {
                classes.add(bsdfs[m].getClass());
            }
            kindOf[m] = classes.indexOf(bsdfs[m].getClass());
        }
        this.kinds = classes.size();
        int n = capacity;
        ray = new double[7 * n];
        beta = new double[3 * n];
        radiance = new double[3 * n];
        prevPdf = new double[n];
        etaScale = new double[n];
        prevDelta = new boolean[n];
        depth = new int[n];
        queue = new RayBatch(n);
        shadows = new RayBatch(n);
        shadowContribution = new double[3 * n];
        shadowSlot = new int[n];
        live = new int[n];
        identity = new int[n];
        for (int i = 0; i < n; i++) {
            identity[i] = i;
        }
        shadeOrder = new int[n];
        kindStart = new int[kinds + 2];
    }

    /** Paths per batch. */
    public int capacity() {
        return capacity;
    }

    /** The sampler of slot {@code slot}: the caller starts it for the slot's pixel sample and takes the camera's numbers from it. */
    public Sampler sampler(int slot) {
        return samplers[slot];
    }

    /** The worker whose tracer traces every ray of this wavefront: its {@link Integrator.Worker#rayCount()} counts them. */
    public Integrator.Worker worker() {
        return w;
    }

    /** Gives slot {@code slot} a new camera path along {@code cameraRay}. */
    public void start(int slot, Ray cameraRay) {
        store(ray, 7 * slot, cameraRay);
        w.path.start();
        storeState(slot, w.path);
        radiance[3 * slot] = radiance[3 * slot + 1] = radiance[3 * slot + 2] = 0;
    }

    public double red(int slot) {
        return radiance[3 * slot];
    }

    public double green(int slot) {
        return radiance[3 * slot + 1];
    }

    public double blue(int slot) {
        return radiance[3 * slot + 2];
    }

    /** Traces the paths of slots [0, count) to their ends. */
    public void run(int count) {
        if (count > capacity) {
            throw new IllegalArgumentException(count + " paths for a wavefront of " + capacity);
        }
        int alive = count;
        for (int i = 0; i < count; i++) {
            live[i] = i;
        }
        while (alive > 0) {
            closestHits(alive);
            int queries = shade(alive, groupByKind(alive));
            traceShadows(queries);
            alive = compact(alive);
        }
    }

    /** Stage 1: the closest hit of every live path, one batch query (prim -1 for a miss). */
    private void closestHits(int alive) {
        for (int i = 0; i < alive; i++) {
            int o = 7 * live[i];
            queue.set(i, ray[o], ray[o + 1], ray[o + 2], ray[o + 3], ray[o + 4], ray[o + 5], ray[o + 6]);
        }
        w.tracer.closestHits(queue, alive);
    }

    /**
     * The order stage 2 shades the live paths in (positions in {@code live}): misses first, then by
     * the kind of BSDF they hit, each group in slot order (a stable counting sort), so that each
     * BSDF's code runs on many paths in a row; plain live order where the scene has one kind.
     */
    private int[] groupByKind(int alive) {
        if (kinds == 1) {
            return identity;
        }
        java.util.Arrays.fill(kindStart, 0);
        Geometry geometry = pt.world().geometry();
        int[] prim = queue.prim;
        for (int i = 0; i < alive; i++) {
            kindStart[(prim[i] < 0 ? 0 : kindOf[geometry.material(prim[i])] + 1) + 1]++;
        }
        for (int k = 1; k < kindStart.length; k++) {
            kindStart[k] += kindStart[k - 1];
        }
        for (int i = 0; i < alive; i++) {
            shadeOrder[kindStart[prim[i] < 0 ? 0 : kindOf[geometry.material(prim[i])] + 1]++] = i;
        }
        return shadeOrder;
    }

    /**
     * Stage 2: every live path at its hit, through the vertex kernel (or the environment for a
     * miss); a path that ends gets depth 0. A light sample whose shadow ray must be traced joins
     * the stage's shadow batch; one that needs none (the teaching option without shadows) is added
     * at once. Returns the number of shadow rays.
     */
    private int shade(int alive, int[] order) {
        Tracer tracer = w.tracer;
        Shading s = w.s;
        PathState p = w.path;
        ShadowQuery q = w.q;
        int queries = 0;
        for (int k = 0; k < alive; k++) {
            int i = order[k];
            int slot = live[i];
            int o = 7 * slot;
            load(ray, o, r);
            loadState(slot, p);
            loadRadiance(slot);
            double t = -1;
            if (queue.prim[i] >= 0) {
                hit.prim = queue.prim[i];
                hit.t = queue.t[i];
                hit.b1 = queue.b1[i];
                hit.b2 = queue.b2[i];
                r.tMax = queue.tMax[i];            // as the query left it
                t = tracer.settle(r, ray[o + 6], hit, s);
            }
            boolean goesOn;
            if (t < 0) {
                w.addEnvironment(r, p.beta, pt.environmentWeight(p, r.d), out);
                goesOn = false;
                q.pending = false;
            } else {
                goesOn = pt.scatter(tracer, s, t, p, w.u, samplers[slot], q, r, out);
            }
            if (q.pending && !q.traced) {
                tracer.direct.resolve(q, out);     // nothing to trace: counts at once
            } else if (q.pending) {
                Ray sr = q.ray;
                shadows.set(queries, sr.o.x, sr.o.y, sr.o.z, sr.d.x, sr.d.y, sr.d.z, sr.tMax);
                shadowContribution[3 * queries] = q.contribution.r;
                shadowContribution[3 * queries + 1] = q.contribution.g;
                shadowContribution[3 * queries + 2] = q.contribution.b;
                shadowSlot[queries++] = slot;
            }
            storeRadiance(slot);
            if (goesOn) {
                store(ray, o, r);
                storeState(slot, p);
            } else {
                depth[slot] = 0;
            }
        }
        return queries;
    }

    /** Stage 3: the stage's shadow rays, one batch query; each unblocked one adds its contribution to its path. */
    private void traceShadows(int queries) {
        if (queries == 0) {
            return;
        }
        w.tracer.direct.occluded(shadows, queries);
        for (int i = 0; i < queries; i++) {
            if (!shadows.occluded[i]) {
                int c = 3 * i, slot = 3 * shadowSlot[i];
                radiance[slot] += shadowContribution[c];
                radiance[slot + 1] += shadowContribution[c + 1];
                radiance[slot + 2] += shadowContribution[c + 2];
            }
        }
    }

    /** Stage 4: the paths still alive, in slot order. */
    private int compact(int alive) {
        int n = 0;
        for (int i = 0; i < alive; i++) {
            int slot = live[i];
            if (depth[slot] > 0) {
                live[n++] = slot;
            }
        }
        return n;
    }

    private static void store(double[] a, int o, Ray ray) {
        a[o] = ray.o.x;
        a[o + 1] = ray.o.y;
        a[o + 2] = ray.o.z;
        a[o + 3] = ray.d.x;
        a[o + 4] = ray.d.y;
        a[o + 5] = ray.d.z;
        a[o + 6] = ray.tMax;
    }

    private static void load(double[] a, int o, Ray ray) {
        ray.o.set(a[o], a[o + 1], a[o + 2]);
        ray.d.set(a[o + 3], a[o + 4], a[o + 5]);
        ray.tMax = a[o + 6];
    }

    private void storeState(int slot, PathState p) {
        beta[3 * slot] = p.beta.r;
        beta[3 * slot + 1] = p.beta.g;
        beta[3 * slot + 2] = p.beta.b;
        prevPdf[slot] = p.prevPdf;
        prevDelta[slot] = p.prevDelta;
        etaScale[slot] = p.etaScale;
        depth[slot] = p.depth;
    }

    private void loadState(int slot, PathState p) {
        p.beta.set(beta[3 * slot], beta[3 * slot + 1], beta[3 * slot + 2]);
        p.prevPdf = prevPdf[slot];
        p.prevDelta = prevDelta[slot];
        p.etaScale = etaScale[slot];
        p.depth = depth[slot];
    }

    private void loadRadiance(int slot) {
        out.set(radiance[3 * slot], radiance[3 * slot + 1], radiance[3 * slot + 2]);
    }

    private void storeRadiance(int slot) {
        radiance[3 * slot] = out.r;
        radiance[3 * slot + 1] = out.g;
        radiance[3 * slot + 2] = out.b;
    }
}
