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
 * What a path carries between stages — its ray, {@link PathState} and radiance — are objects of
 * its slot, made once, which the kernels work on in place (copying them in and out of flat arrays
 * at every stage cost 5–8 % of the time); the batch queries' rays and hits, and the shadow rays,
 * are flat arrays ({@link RayBatch}). All in double, as the scalar path holds them.
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
    // the state of each slot's path: its ray, what it carries to the next vertex, its radiance so far
    private final Ray[] rays;
    private final PathState[] paths;
    private final MutableRgb[] radiance;
    // the rays of the live paths in live order, with their closest hits: the closest-hit stage's batch query
    private final RayBatch queue;
    // the shadow rays of a stage (traced ones only), with what each adds and to which slot
    private final RayBatch shadows;
    private final double[] shadowContribution;
    private final int[] shadowSlot;
    // live paths' slots in slot order; identity and grouped: positions in live in the order stage 2 shades them
    private final int[] live, identity, shadeOrder, kindStart;
    private final Hit hit = new Hit();

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
        rays = new Ray[n];
        paths = new PathState[n];
        radiance = new MutableRgb[n];
        for (int i = 0; i < n; i++) {
            rays[i] = new Ray();
            paths[i] = new PathState();
            radiance[i] = new MutableRgb();
        }
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
        Ray r = rays[slot];
        r.o.set(cameraRay.o);
        r.d.set(cameraRay.d);
        r.tMax = cameraRay.tMax;
        paths[slot].start();
        radiance[slot].setZero();
    }

    public double red(int slot) {
        return radiance[slot].r;
    }

    public double green(int slot) {
        return radiance[slot].g;
    }

    public double blue(int slot) {
        return radiance[slot].b;
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
            Ray r = rays[live[i]];
            queue.set(i, r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z, r.tMax);
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
        ShadowQuery q = w.q;
        int queries = 0;
        for (int k = 0; k < alive; k++) {
            int i = order[k];
            int slot = live[i];
            Ray r = rays[slot];
            PathState p = paths[slot];
            MutableRgb out = radiance[slot];
            double t = -1;
            if (queue.prim[i] >= 0) {
                hit.prim = queue.prim[i];
                hit.t = queue.t[i];
                hit.b1 = queue.b1[i];
                hit.b2 = queue.b2[i];
                hit.instance = queue.instance[i];
                double tMax = r.tMax;
                r.tMax = queue.tMax[i];            // as the query left it
                t = tracer.settle(r, tMax, hit, s);
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
            if (!goesOn) {
                p.depth = 0;
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
                int c = 3 * i;
                MutableRgb out = radiance[shadowSlot[i]];
                out.r += shadowContribution[c];
                out.g += shadowContribution[c + 1];
                out.b += shadowContribution[c + 2];
            }
        }
    }

    /** Stage 4: the paths still alive, in slot order. */
    private int compact(int alive) {
        int n = 0;
        for (int i = 0; i < alive; i++) {
            int slot = live[i];
            if (paths[slot].depth > 0) {
                live[n++] = slot;
            }
        }
        return n;
    }
}
