package dev.strahl.geometry;

import java.util.Arrays;
import org.joml.Vector3d;

/**
 * The placements of instances: instance i shows group {@link #group(int)} (a geometry of its own,
 * shared by all its instances) moved by an affine transform. Both directions are kept in flat
 * arrays, twelve doubles an instance (a 3×4 matrix, row by row): object to world for hit points
 * and tangents, world to object for rays and (transposed) for normals, so that nothing is
 * inverted per ray. Immutable and shared by all threads.
 */
public final class InstanceTransforms {
    /** An empty set: a scene without instances. */
    public static final InstanceTransforms NONE = new InstanceTransforms(new int[0], new double[0]);

    private final int[] group;
    private final double[] toWorld;
    private final double[] toObject;

    /**
     * @param group   the group of each instance
     * @param toWorld twelve values per instance: the rows of its object-to-world matrix (3×4)
     * @throws IllegalArgumentException if a matrix is not finite or not invertible
     */
    public InstanceTransforms(int[] group, double[] toWorld) {
        if (toWorld.length != 12 * group.length) {
            throw new IllegalArgumentException(toWorld.length + " matrix values for " + group.length + " instances");
        }
        this.group = group.clone();
        this.toWorld = toWorld.clone();
        this.toObject = new double[toWorld.length];
        for (int i = 0; i < group.length; i++) {
            invert(this.toWorld, this.toObject, 12 * i);
        }
    }

    private static void invert(double[] m, double[] dest, int o) {
        double a = m[o], b = m[o + 1], c = m[o + 2], d = m[o + 4], e = m[o + 5], f = m[o + 6], g = m[o + 8], h = m[o + 9], k = m[o + 10];
        double c00 = e * k - f * h, c01 = c * h - b * k, c02 = b * f - c * e;
        double det = a * c00 + d * c01 + g * c02;
        if (!Double.isFinite(det) || det == 0 || !Double.isFinite(m[o + 3] + m[o + 7] + m[o + 11])) {
            throw new IllegalArgumentException("instance transform is not invertible: " + Arrays.toString(Arrays.copyOfRange(m, o, o + 12)));
        }
        double inv = 1 / det;
        double[] r = {c00 * inv, c01 * inv, c02 * inv, (f * g - d * k) * inv, (a * k - c * g) * inv, (c * d - a * f) * inv,
                (d * h - e * g) * inv, (b * g - a * h) * inv, (a * e - b * d) * inv};
        for (int row = 0; row < 3; row++) {
            dest[o + 4 * row] = r[3 * row];
            dest[o + 4 * row + 1] = r[3 * row + 1];
            dest[o + 4 * row + 2] = r[3 * row + 2];
            dest[o + 4 * row + 3] = -(r[3 * row] * m[o + 3] + r[3 * row + 1] * m[o + 7] + r[3 * row + 2] * m[o + 11]);
        }
    }

    public int count() {
        return group.length;
    }

    public int group(int instance) {
        return group[instance];
    }

    /**
     * Ray {@code world} in the coordinates of {@code instance}, into {@code dest}: the origin and
     * direction through the inverse matrix, the direction made unit length again (the primitives'
     * tests assume it) and tMax scaled to match. Returns the scale: a distance t along
     * {@code dest} is t / scale along the world ray.
     */
    public double rayToObject(int instance, Ray world, Ray dest) {
        double[] m = toObject;
        int o = 12 * instance;
        double ox = world.o.x, oy = world.o.y, oz = world.o.z, dx = world.d.x, dy = world.d.y, dz = world.d.z;
        dest.o.set(m[o] * ox + m[o + 1] * oy + m[o + 2] * oz + m[o + 3],
                m[o + 4] * ox + m[o + 5] * oy + m[o + 6] * oz + m[o + 7],
                m[o + 8] * ox + m[o + 9] * oy + m[o + 10] * oz + m[o + 11]);
        double x = m[o] * dx + m[o + 1] * dy + m[o + 2] * dz, y = m[o + 4] * dx + m[o + 5] * dy + m[o + 6] * dz,
                z = m[o + 8] * dx + m[o + 9] * dy + m[o + 10] * dz;
        double scale = Math.sqrt(x * x + y * y + z * z);
        dest.d.set(x / scale, y / scale, z / scale);
        dest.tMax = world.tMax * scale;
        return scale;
    }

    /** A point of {@code instance}'s group into world coordinates, in place. */
    public Vector3d pointToWorld(int instance, Vector3d p) {
        return affine(toWorld, 12 * instance, p, 1);
    }

    /** A world point into {@code instance}'s coordinates, in place. */
    public Vector3d pointToObject(int instance, Vector3d p) {
        return affine(toObject, 12 * instance, p, 1);
    }

    /** A tangent (a difference of points) of the group into world coordinates, in place. */
    public Vector3d vectorToWorld(int instance, Vector3d v) {
        return affine(toWorld, 12 * instance, v, 0);
    }

    /**
     * A normal of the group into world coordinates, in place: through the inverse transpose of
     * the linear part (so it stays perpendicular to the moved surface under any scaling), then
     * made unit length. A mirror keeps it on the same side of the surface, as a mirrored mesh
     * (whose winding {@code Transform} reverses) has it.
     */
    public Vector3d normalToWorld(int instance, Vector3d n) {
        double[] m = toObject;
        int o = 12 * instance;
        double x = n.x, y = n.y, z = n.z;
        return n.set(m[o] * x + m[o + 4] * y + m[o + 8] * z, m[o + 1] * x + m[o + 5] * y + m[o + 9] * z,
                m[o + 2] * x + m[o + 6] * y + m[o + 10] * z).normalize();
    }

    /** Whether the instance's transform mirrors (a negative determinant): texture mappings change handedness. */
    public boolean mirrors(int instance) {
        double[] m = toWorld;
        int o = 12 * instance;
        return m[o] * (m[o + 5] * m[o + 10] - m[o + 6] * m[o + 9]) - m[o + 1] * (m[o + 4] * m[o + 10] - m[o + 6] * m[o + 8])
                + m[o + 2] * (m[o + 4] * m[o + 9] - m[o + 5] * m[o + 8]) < 0;
    }

    /** The world bounds of the group's box {@code object} moved by the instance (its eight corners), into {@code dest}. */
    public Aabb bounds(int instance, Aabb object, Aabb dest) {
        dest.reset();
        if (object.isEmpty()) {
            return dest;
        }
        Vector3d c = new Vector3d();
        for (int corner = 0; corner < 8; corner++) {
            c.set((corner & 1) == 0 ? object.minX : object.maxX, (corner & 2) == 0 ? object.minY : object.maxY,
                    (corner & 4) == 0 ? object.minZ : object.maxZ);
            pointToWorld(instance, c);
            dest.include(c.x, c.y, c.z);
        }
        return dest;
    }

    /** Bytes held by the groups' numbers and both matrices of every instance. */
    public long byteSize() {
        return 4L * group.length + 8L * (toWorld.length + toObject.length);
    }

    /** Feeds the groups and matrices into {@code md} (a render checkpoint's tie to its scene). */
    public void digest(java.security.MessageDigest md) {
        java.nio.ByteBuffer b = java.nio.ByteBuffer.allocate(4 + 4 * group.length + 8 * toWorld.length);
        b.putInt(group.length);
        for (int g : group) {
            b.putInt(g);
        }
        for (double v : toWorld) {
            b.putDouble(v);
        }
        md.update(b.array());
    }

    private static Vector3d affine(double[] m, int o, Vector3d p, double w) {
        double x = p.x, y = p.y, z = p.z;
        return p.set(m[o] * x + m[o + 1] * y + m[o + 2] * z + w * m[o + 3], m[o + 4] * x + m[o + 5] * y + m[o + 6] * z + w * m[o + 7],
                m[o + 8] * x + m[o + 9] * y + m[o + 10] * z + w * m[o + 11]);
    }
}
