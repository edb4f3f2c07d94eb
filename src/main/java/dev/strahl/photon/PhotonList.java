package dev.strahl.photon;

import java.util.Arrays;

/**
 * Photons in one flat float array, {@value #STRIDE} floats each: the position, the unit direction
 * back towards where the photon came from (wi of the surface it landed on, in world space), its
 * flux (RGB), and the number of path segments from the light to it. Growable and reused between
 * iterations, so that tracing allocates only while the buffers grow. Not thread-safe.
 */
final class PhotonList {
    static final int STRIDE = 10;
    static final int X = 0, WX = 3, R = 6, SEGMENTS = 9;
    /** The longest array a JVM allocates. */
    private static final long MAX_LENGTH = Integer.MAX_VALUE - 8;

    private float[] data;
    private int size;

    PhotonList() {
        this(1024);
    }

    PhotonList(int capacity) {
        data = new float[Math.max(1, capacity) * STRIDE];
    }

    int size() {
        return size;
    }

    void clear() {
        size = 0;
    }

    /** The backing array: photon i occupies {@code [i·STRIDE, (i+1)·STRIDE)}. */
    float[] data() {
        return data;
    }

    void add(double x, double y, double z, double wx, double wy, double wz, double r, double g, double b, int segments) {
        ensureCapacity(size + 1);
        int o = size * STRIDE;
        data[o] = (float) x;
        data[o + 1] = (float) y;
        data[o + 2] = (float) z;
        data[o + 3] = (float) wx;
        data[o + 4] = (float) wy;
        data[o + 5] = (float) wz;
        data[o + 6] = (float) r;
        data[o + 7] = (float) g;
        data[o + 8] = (float) b;
        data[o + 9] = segments;
        size++;
    }

    /** Appends every photon of {@code other}, in its order. */
    void addAll(PhotonList other) {
        ensureCapacity(size + other.size);
        System.arraycopy(other.data, 0, data, size * STRIDE, other.size * STRIDE);
        size += other.size;
    }

    private void ensureCapacity(int photons) {
        long needed = (long) photons * STRIDE;
        if (needed > data.length) {
            if (needed > MAX_LENGTH) {
                throw new IllegalStateException("too many photons: " + photons);
            }
            data = Arrays.copyOf(data, (int) Math.min(MAX_LENGTH, Math.max(needed, 2L * data.length)));
        }
    }
}
