package dev.strahl.accel;

import dev.strahl.geometry.Hit;
import dev.strahl.geometry.Ray;

/**
 * Rays and their answers in flat arrays, for the batch queries of {@link Aggregate}: ray i is
 * origin ({@code ox[i]}, {@code oy[i]}, {@code oz[i]}), unit direction ({@code dx[i]} …) and
 * {@code tMax[i]}; a closest-hit query writes {@code prim[i]} (-1 for a miss), {@code t[i]} and
 * a triangle's barycentrics {@code b1[i]}, {@code b2[i]}; an occlusion query
 * {@code occluded[i]}. Owned by one thread.
 */
public final class RayBatch {
    public final double[] ox, oy, oz, dx, dy, dz, tMax;
    public final double[] t, b1, b2;
    public final int[] prim;
    /** The instance of a hit ({@link Hit#instance}: -1 for the scene's own primitives). */
    public final int[] instance;
    public final boolean[] occluded;

    /** A batch of room for {@code capacity} rays. */
    public RayBatch(int capacity) {
        ox = new double[capacity];
        oy = new double[capacity];
        oz = new double[capacity];
        dx = new double[capacity];
        dy = new double[capacity];
        dz = new double[capacity];
        tMax = new double[capacity];
        t = new double[capacity];
        b1 = new double[capacity];
        b2 = new double[capacity];
        prim = new int[capacity];
        instance = new int[capacity];
        occluded = new boolean[capacity];
    }

    public int capacity() {
        return prim.length;
    }

    /** Sets ray i. */
    public void set(int i, double oxi, double oyi, double ozi, double dxi, double dyi, double dzi, double tMaxi) {
        ox[i] = oxi;
        oy[i] = oyi;
        oz[i] = ozi;
        dx[i] = dxi;
        dy[i] = dyi;
        dz[i] = dzi;
        tMax[i] = tMaxi;
    }

    /** Ray i into {@code ray}. */
    void load(int i, Ray ray) {
        ray.o.set(ox[i], oy[i], oz[i]);
        ray.d.set(dx[i], dy[i], dz[i]);
        ray.tMax = tMax[i];
    }

    /** The answer of ray i from a single-ray query. */
    void store(int i, Ray ray, Hit hit) {
        tMax[i] = ray.tMax;
        prim[i] = hit.prim;
        instance[i] = hit.instance;
        t[i] = hit.t;
        b1[i] = hit.b1;
        b2[i] = hit.b2;
    }
}
