package dev.strahl.integrator;

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
    // the closest hit of each live path
    private final int[] hitPrim;
    private final double[] hitT, hitB1, hitB2;
    // the shadow queries of a stage: ray (7 per query) and contribution (3); slot of each
    private final double[] shadowRay, shadowContribution;
    private final boolean[] shadowTraced;
    private final int[] shadowSlot;
    // live paths in slot order, and the same grouped by kind for shading
    private final int[] live, shadeOrder, kindStart;
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
        hitPrim = new int[n];
        hitT = new double[n];
        hitB1 = new double[n];
        hitB2 = new double[n];
        shadowRay = new double[7 * n];
        shadowContribution = new double[3 * n];
        shadowTraced = new boolean[n];
        shadowSlot = new int[n];
        live = new int[n];
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

    /** Stage 1: the closest hit of every live path (prim -1 for a miss). */
    private void closestHits(int alive) {
        Tracer tracer = w.tracer;
        for (int i = 0; i < alive; i++) {
            int slot = live[i];
            load(ray, 7 * slot, r);
            if (tracer.closestHit(r, hit)) {
                hitPrim[slot] = hit.prim;
                hitT[slot] = hit.t;
                hitB1[slot] = hit.b1;
                hitB2[slot] = hit.b2;
            } else {
                hitPrim[slot] = -1;
            }
        }
    }

    /**
     * The live paths in the order stage 2 shades them: misses first, then by the kind of BSDF they
     * hit, each group in slot order (a stable counting sort), so that each BSDF's code runs on many
     * paths in a row. Returns the order: {@code live} itself where the scene has one kind.
     */
    private int[] groupByKind(int alive) {
        if (kinds == 1) {
            return live;
        }
        java.util.Arrays.fill(kindStart, 0);
        Geometry geometry = pt.world().geometry();
        for (int i = 0; i < alive; i++) {
            int prim = hitPrim[live[i]];
            kindStart[(prim < 0 ? 0 : kindOf[geometry.material(prim)] + 1) + 1]++;
        }
        for (int k = 1; k < kindStart.length; k++) {
            kindStart[k] += kindStart[k - 1];
        }
        for (int i = 0; i < alive; i++) {
            int slot = live[i];
            int prim = hitPrim[slot];
            shadeOrder[kindStart[prim < 0 ? 0 : kindOf[geometry.material(prim)] + 1]++] = slot;
        }
        return shadeOrder;
    }

    /**
     * Stage 2: every live path at its hit, through the vertex kernel (or the environment for a
     * miss); a path that ends gets depth 0. Returns the number of shadow queries made.
     */
    private int shade(int alive, int[] order) {
        Tracer tracer = w.tracer;
        Shading s = w.s;
        PathState p = w.path;
        ShadowQuery q = w.q;
        int queries = 0;
        for (int i = 0; i < alive; i++) {
            int slot = order[i];
            int o = 7 * slot;
            load(ray, o, r);
            loadState(slot, p);
            loadRadiance(slot);
            double t = -1;
            if (hitPrim[slot] >= 0) {
                hit.prim = hitPrim[slot];
                hit.t = hitT[slot];
                hit.b1 = hitB1[slot];
                hit.b2 = hitB2[slot];
                r.tMax = hit.t;                    // as the query left it
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
            storeRadiance(slot);
            if (q.pending) {
                store(shadowRay, 7 * queries, q.ray);
                shadowContribution[3 * queries] = q.contribution.r;
                shadowContribution[3 * queries + 1] = q.contribution.g;
                shadowContribution[3 * queries + 2] = q.contribution.b;
                shadowTraced[queries] = q.traced;
                shadowSlot[queries++] = slot;
            }
            if (goesOn) {
                store(ray, o, r);
                storeState(slot, p);
            } else {
                depth[slot] = 0;
            }
        }
        return queries;
    }

    /** Stage 3: the shadow rays of the stage's light samples; each unblocked one adds its contribution to its path. */
    private void traceShadows(int queries) {
        DirectLight direct = w.tracer.direct;
        ShadowQuery q = w.q;
        for (int i = 0; i < queries; i++) {
            int slot = shadowSlot[i];
            load(shadowRay, 7 * i, q.ray);
            q.contribution.set(shadowContribution[3 * i], shadowContribution[3 * i + 1], shadowContribution[3 * i + 2]);
            q.traced = shadowTraced[i];
            loadRadiance(slot);
            direct.resolve(q, out);
            storeRadiance(slot);
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
