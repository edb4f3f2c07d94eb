package dev.strahl.geometry;

/** An axis-aligned box, mutable, used while building acceleration structures and framing cameras. */
public final class Aabb {
    /** Creates an empty box (min +∞, max −∞), which any point or box extends. */
    public Aabb() {}

    public double minX = Double.POSITIVE_INFINITY, minY = Double.POSITIVE_INFINITY, minZ = Double.POSITIVE_INFINITY;
    public double maxX = Double.NEGATIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY, maxZ = Double.NEGATIVE_INFINITY;

    public Aabb reset() {
        minX = minY = minZ = Double.POSITIVE_INFINITY;
        maxX = maxY = maxZ = Double.NEGATIVE_INFINITY;
        return this;
    }

    public boolean isEmpty() {
        return minX > maxX || minY > maxY || minZ > maxZ;
    }

    public Aabb include(double x, double y, double z) {
        minX = Math.min(minX, x);
        minY = Math.min(minY, y);
        minZ = Math.min(minZ, z);
        maxX = Math.max(maxX, x);
        maxY = Math.max(maxY, y);
        maxZ = Math.max(maxZ, z);
        return this;
    }

    public Aabb include(Aabb b) {
        minX = Math.min(minX, b.minX);
        minY = Math.min(minY, b.minY);
        minZ = Math.min(minZ, b.minZ);
        maxX = Math.max(maxX, b.maxX);
        maxY = Math.max(maxY, b.maxY);
        maxZ = Math.max(maxZ, b.maxZ);
        return this;
    }

    public double extent(int axis) {
        return axis == 0 ? maxX - minX : axis == 1 ? maxY - minY : maxZ - minZ;
    }

    public double min(int axis) {
        return axis == 0 ? minX : axis == 1 ? minY : minZ;
    }

    public double max(int axis) {
        return axis == 0 ? maxX : axis == 1 ? maxY : maxZ;
    }

    /** Surface area; zero for an empty box. */
    public double area() {
        if (isEmpty()) {
            return 0;
        }
        double dx = maxX - minX, dy = maxY - minY, dz = maxZ - minZ;
        return 2 * (dx * dy + dy * dz + dz * dx);
    }

    /** Length of the diagonal; zero for an empty box. */
    public double diagonal() {
        if (isEmpty()) {
            return 0;
        }
        double dx = maxX - minX, dy = maxY - minY, dz = maxZ - minZ;
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * Slab test (Kay &amp; Kajiya 1986) of the ray o + t·d against the box for t in (0, tMax).
     * Infinite inverse directions are handled by IEEE arithmetic. An empty box meets no ray.
     */
    public boolean intersects(Ray ray) {
        if (isEmpty()) {
            return false;       // its inverted slabs would swap into (-inf, inf) and pass every ray
        }
        double t0 = 0, t1 = ray.tMax;
        for (int axis = 0; axis < 3; axis++) {
            double o = axis == 0 ? ray.o.x : axis == 1 ? ray.o.y : ray.o.z;
            double d = axis == 0 ? ray.d.x : axis == 1 ? ray.d.y : ray.d.z;
            double inv = 1 / d;
            double tNear = (min(axis) - o) * inv;
            double tFar = (max(axis) - o) * inv;
            if (tNear > tFar) {
                double tmp = tNear;
                tNear = tFar;
                tFar = tmp;
            }
            t0 = tNear > t0 ? tNear : t0;
            t1 = tFar < t1 ? tFar : t1;
            if (t0 > t1) {
                return false;
            }
        }
        return true;
    }

    @Override
    public String toString() {
        return "Aabb[(" + minX + ", " + minY + ", " + minZ + ") - (" + maxX + ", " + maxY + ", " + maxZ + ")]";
    }
}
