package dev.strahl.medium;

/**
 * A scalar field on a regular grid of X × Y × Z voxels over the unit cube, as Mitsuba 3's
 * {@code gridvolume} (with its defaults: trilinear filter, clamp wrap mode): voxel (i, j, k)
 * holds the value at ((i + ½)/X, (j + ½)/Y, (k + ½)/Z), values between voxel centres are
 * trilinear, and in the half voxel between the outermost centres and the cube's faces (and beyond)
 * the coordinates are clamped to the outermost centres. Values are stored x fastest, then y, then
 * z (the order of a {@code .vol} file). Immutable.
 */
public final class DensityGrid {
    private final int nx, ny, nz;
    private final float[] values;
    private final float max;

    /**
     * @param values X·Y·Z values, x fastest; finite and ≥ 0 (kept, not copied)
     * @throws IllegalArgumentException if a size is not positive, the array's length differs from
     *                                  X·Y·Z or a value is negative or not finite
     */
    public DensityGrid(int nx, int ny, int nz, float[] values) {
        if (nx <= 0 || ny <= 0 || nz <= 0 || (long) nx * ny * nz != values.length) {
            throw new IllegalArgumentException("a " + nx + "x" + ny + "x" + nz + " grid needs that many values, got " + values.length);
        }
        float m = 0;
        for (int i = 0; i < values.length; i++) {
            float v = values[i];
            if (!(v >= 0) || v == Float.POSITIVE_INFINITY) {
                throw new IllegalArgumentException("voxel (" + i % nx + ", " + i / nx % ny + ", " + i / nx / ny
                        + ") holds " + v + ": densities must be finite and >= 0");
            }
            m = Math.max(m, v);
        }
        this.nx = nx;
        this.ny = ny;
        this.nz = nz;
        this.values = values;
        this.max = m;
    }

    public int sizeX() {
        return nx;
    }

    public int sizeY() {
        return ny;
    }

    public int sizeZ() {
        return nz;
    }

    /** The largest value: no interpolated value exceeds it. */
    public double max() {
        return max;
    }

    /** The value stored for voxel (i, j, k). */
    public double voxel(int i, int j, int k) {
        return values[(k * ny + j) * nx + i];
    }

    /** Bytes held by the values. */
    public long byteSize() {
        return 4L * values.length;
    }

    /** The trilinear value at (u, v, w) of the unit cube, clamped at its border. */
    public double eval(double u, double v, double w) {
        double x = clamp(u * nx - 0.5, nx - 1), y = clamp(v * ny - 0.5, ny - 1), z = clamp(w * nz - 0.5, nz - 1);
        int i0 = (int) x, j0 = (int) y, k0 = (int) z;
        double fx = x - i0, fy = y - j0, fz = z - k0;
        int di = i0 < nx - 1 ? 1 : 0, dj = j0 < ny - 1 ? nx : 0, dk = k0 < nz - 1 ? nx * ny : 0;
        int base = (k0 * ny + j0) * nx + i0;
        double c00 = lerp(values[base], values[base + di], fx);
        double c10 = lerp(values[base + dj], values[base + dj + di], fx);
        double c01 = lerp(values[base + dk], values[base + dk + di], fx);
        double c11 = lerp(values[base + dk + dj], values[base + dk + dj + di], fx);
        return lerp(lerp(c00, c10, fy), lerp(c01, c11, fy), fz);
    }

    /** x clamped to [0, hi]; NaN becomes 0. */
    private static double clamp(double x, int hi) {
        return x >= 0 ? Math.min(x, hi) : 0;
    }

    private static double lerp(double a, double b, double f) {
        return a + f * (b - a);
    }
}
