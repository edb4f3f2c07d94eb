package dev.strahl.medium;

import dev.strahl.image.Rgb;
import dev.strahl.color.MutableRgb;
import org.joml.Vector3dc;

/**
 * A heterogeneous medium whose extinction is {@code scale} × a {@link DensityGrid} that fills an
 * axis-aligned box (a Mitsuba 3 {@code heterogeneous} medium whose {@code sigma_t} is a
 * {@code gridvolume} mapped onto the box by its {@code to_world}); outside the box the extinction
 * is 0. σt is the same in every channel, the albedo may be coloured.
 *
 * <p><b>Sampling: delta tracking</b> (Woodcock et al. 1965; pbrt-v4 §14.2) against a majorant
 * σ̄ ≥ σt: tentative collisions follow e^(−σ̄·t), and one at x is real with probability
 * σt(x)/σ̄, else the walk goes on. σ̄ is constant over each brick of 8³ voxels (scale × the
 * largest value lookups in the brick can return, {@link MajorantGrid}), so empty space costs no
 * collisions and a dense brick does not slow down its sparse neighbours. That samples the first real collision
 * exactly in proportion to T(t)·σt(t), so a scattering event weighs σs/σt = the albedo and a
 * crossing weighs 1. A medium that only absorbs crosses every segment instead, weighted by a ratio
 * tracking estimate of its transmittance.
 *
 * <p><b>Transmittance: ratio tracking</b> (Novák et al. 2014): the same tentative collisions,
 * each multiplying the estimate by 1 − σt(x)/σ̄; once it falls below
 * {@value #ROULETTE_BELOW} it goes on with probability estimate/{@value #ROULETTE_BELOW} (then
 * set to {@value #ROULETTE_BELOW}) or ends at 0, which keeps it unbiased and bounds the walk.
 */
public final class GridMedium implements Medium {
    static final double ROULETTE_BELOW = 0.1;

    private final DensityGrid density;
    private final double minX, minY, minZ, maxX, maxY, maxZ;
    private final double invX, invY, invZ;
    private final double[] lower, upper;
    private final double scale;
    private final double majorant;
    private final MajorantGrid bricks;
    private final double brickX, brickY, brickZ;      // bricks per scene unit along each axis
    private final Rgb albedo;
    private final double g;

    /**
     * @param density the grid, filling the box
     * @param min     the box's lower corner
     * @param max     the box's upper corner, above {@code min} on every axis
     * @param scale   extinction per unit of density and scene unit, finite and ≥ 0
     * @param albedo  single-scattering albedo σs/σt, in [0, 1] per channel
     * @param g       Henyey–Greenstein asymmetry in (−1, 1)
     */
    public GridMedium(DensityGrid density, Vector3dc min, Vector3dc max, double scale, Rgb albedo, double g) {
        if (!(min.x() < max.x() && min.y() < max.y() && min.z() < max.z()) || !min.isFinite() || !max.isFinite()) {
            throw new IllegalArgumentException("the grid's bounds must be finite with min < max on every axis, got " + min + " .. " + max);
        }
        if (!(scale >= 0) || !Double.isFinite(scale)) {
            throw new IllegalArgumentException("the grid's scale must be finite and >= 0, got " + scale);
        }
        this.density = density;
        this.minX = min.x();
        this.minY = min.y();
        this.minZ = min.z();
        this.maxX = max.x();
        this.maxY = max.y();
        this.maxZ = max.z();
        this.lower = new double[] {minX, minY, minZ};
        this.upper = new double[] {maxX, maxY, maxZ};
        this.invX = 1 / (maxX - minX);
        this.invY = 1 / (maxY - minY);
        this.invZ = 1 / (maxZ - minZ);
        this.scale = scale;
        this.majorant = scale * density.max();
        this.bricks = new MajorantGrid(density);
        this.brickX = invX * density.sizeX() / MajorantGrid.BRICK;
        this.brickY = invY * density.sizeY() / MajorantGrid.BRICK;
        this.brickZ = invZ * density.sizeZ() / MajorantGrid.BRICK;
        this.albedo = Medium.checkAlbedo(albedo);
        this.g = Medium.checkG(g);
    }

    @Override
    public double g() {
        return g;
    }

    @Override
    public Rgb albedo() {
        return albedo;
    }

    /** The extinction at the point (x, y, z): scale × the grid's value, 0 outside the box. */
    public double sigmaT(double x, double y, double z) {
        if (!(x >= minX && x <= maxX && y >= minY && y <= maxY && z >= minZ && z <= maxZ)) {
            return 0;
        }
        return scale * density.eval((x - minX) * invX, (y - minY) * invY, (z - minZ) * invZ);
    }

    /** The extinction at o + t·d inside the box (coordinates clamped by the grid). */
    private double sigmaTAt(Vector3dc o, Vector3dc d, double t) {
        return scale * density.eval((o.x() + t * d.x() - minX) * invX, (o.y() + t * d.y() - minY) * invY, (o.z() + t * d.z() - minZ) * invZ);
    }

    @Override
    public double sampleScattering(Vector3dc o, Vector3dc d, double tMax, int channel, double u1, double u2, TrackingRandom random,
                                   MutableRgb weight, MutableRgb ratio) {
        ratio.set(1, 1, 1);                  // σt is grey: every channel samples alike
        random.seed(u1, u2);
        weight.set(1, 1, 1);
        if (albedo.isBlack()) {
            transmittance(o, d, tMax, random, weight);
            return Double.POSITIVE_INFINITY;
        }
        double t = track(o, d, tMax, random, false);
        if (t < Double.POSITIVE_INFINITY) {
            weight.set(albedo);
        }
        return t;
    }

    @Override
    public void transmittance(Vector3dc o, Vector3dc d, double tMax, TrackingRandom random, MutableRgb tr) {
        tr.mul(track(o, d, tMax, random, true));
    }

    /**
     * Delta tracking ({@code ratio} false: returns the distance of the first real collision, or
     * +∞) or ratio tracking ({@code ratio} true: returns the transmittance estimate) along the
     * segment inside the box, brick by brick: a 3D DDA (Amanatides and Woo 1987) walks the bricks of
     * the {@link MajorantGrid} the segment crosses, and within each the tentative collisions follow
     * that brick's majorant; as the exponential forgets where it began, sampling restarts at every
     * brick face, which is exact (pbrt-v4 §14.2.2, its majorant grid).
     */
    private double track(Vector3dc o, Vector3dc d, double tMax, TrackingRandom random, boolean ratio) {
        double crossed = ratio ? 1 : Double.POSITIVE_INFINITY;
        double t = entry(o, d), t1 = Math.min(exit(o, d), tMax);
        if (!(t < t1) || majorant == 0) {
            return crossed;
        }
        // brick coordinates (a brick is one unit) at the entry, and their rates along the ray
        double sx = (o.x() + t * d.x() - minX) * brickX, sy = (o.y() + t * d.y() - minY) * brickY, sz = (o.z() + t * d.z() - minZ) * brickZ;
        double dx = d.x() * brickX, dy = d.y() * brickY, dz = d.z() * brickZ;
        int cx = cell(sx, bricks.nx), cy = cell(sy, bricks.ny), cz = cell(sz, bricks.nz);
        int stepX = dx > 0 ? 1 : -1, stepY = dy > 0 ? 1 : -1, stepZ = dz > 0 ? 1 : -1;
        double nextX = dx == 0 ? Double.POSITIVE_INFINITY : t + (cx + (dx > 0 ? 1 : 0) - sx) / dx;
        double nextY = dy == 0 ? Double.POSITIVE_INFINITY : t + (cy + (dy > 0 ? 1 : 0) - sy) / dy;
        double nextZ = dz == 0 ? Double.POSITIVE_INFINITY : t + (cz + (dz > 0 ? 1 : 0) - sz) / dz;
        double deltaX = Math.abs(1 / dx), deltaY = Math.abs(1 / dy), deltaZ = Math.abs(1 / dz);
        double estimate = 1;
        while (true) {
            double end = Math.min(t1, Math.min(nextX, Math.min(nextY, nextZ)));
            double m = scale * bricks.max(cx, cy, cz);
            if (m > 0) {
                for (double tc = t - Math.log1p(-random.next()) / m; tc < end; tc -= Math.log1p(-random.next()) / m) {
                    double sigma = sigmaTAt(o, d, tc);
                    if (!ratio) {
                        if (random.next() * m < sigma) {
                            return tc;
                        }
                        continue;
                    }
                    estimate *= 1 - sigma / m;
                    if (estimate < ROULETTE_BELOW) {
                        if (!(random.next() * ROULETTE_BELOW < estimate)) {
                            return 0;
                        }
                        estimate = ROULETTE_BELOW;
                    }
                }
            }
            if (!(end < t1)) {
                return ratio ? estimate : crossed;
            }
            t = end;
            if (nextX <= nextY && nextX <= nextZ) {
                cx += stepX;
                nextX += deltaX;
            } else if (nextY <= nextZ) {
                cy += stepY;
                nextY += deltaY;
            } else {
                cz += stepZ;
                nextZ += deltaZ;
            }
            if (cx < 0 || cy < 0 || cz < 0 || cx >= bricks.nx || cy >= bricks.ny || cz >= bricks.nz) {
                return ratio ? estimate : crossed;        // out of the grid a hair before t1 (round-off)
            }
        }
    }

    /** The brick of coordinate s, clamped to 0 .. count − 1. */
    private static int cell(double s, int count) {
        return s >= 0 ? Math.min((int) s, count - 1) : 0;
    }

    /** Where the ray enters the box (0 if it starts inside; +∞ if it misses). */
    private double entry(Vector3dc o, Vector3dc d) {
        return clip(o, d, true);
    }

    /** Where the ray leaves the box (−∞ if it misses). */
    private double exit(Vector3dc o, Vector3dc d) {
        return clip(o, d, false);
    }

    /** The slab test (Kay and Kajiya 1986): the near or far end of the ray's parameter range inside the box, from 0. */
    private double clip(Vector3dc o, Vector3dc d, boolean near) {
        double lo = 0, hi = Double.POSITIVE_INFINITY;
        for (int axis = 0; axis < 3; axis++) {
            double origin = o.get(axis), inv = 1 / d.get(axis);
            double ta = (lower[axis] - origin) * inv, tb = (upper[axis] - origin) * inv;
            if (ta > tb) {
                double s = ta;
                ta = tb;
                tb = s;
            }
            lo = ta > lo ? ta : lo;          // NaN (a zero direction on a slab face) leaves the bound as it was
            hi = tb < hi ? tb : hi;
        }
        if (!(lo <= hi)) {
            return near ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
        }
        return near ? lo : hi;
    }

    /** Feeds the grid's values into a fingerprint (a checkpoint's: a changed .vol file must not be resumed). */
    public void digest(java.security.MessageDigest md) {
        java.nio.ByteBuffer buf = java.nio.ByteBuffer.allocate(8 * 1024);
        for (int k = 0; k < density.sizeZ(); k++) {
            for (int j = 0; j < density.sizeY(); j++) {
                for (int i = 0; i < density.sizeX(); i++) {
                    if (buf.remaining() < 4) {
                        md.update(buf.flip());
                        buf.clear();
                    }
                    buf.putFloat((float) density.voxel(i, j, k));
                }
            }
        }
        md.update(buf.flip());
    }

    @Override
    public String toString() {
        return "GridMedium[" + density.sizeX() + "x" + density.sizeY() + "x" + density.sizeZ() + " in (" + minX + ", " + minY + ", " + minZ
                + ") .. (" + maxX + ", " + maxY + ", " + maxZ + "), scale " + scale + ", albedo " + albedo + ", g " + g + "]";
    }
}
