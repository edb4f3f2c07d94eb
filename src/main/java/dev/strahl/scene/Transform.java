package dev.strahl.scene;

import dev.strahl.geometry.Sphere;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.joml.Matrix3d;
import org.joml.Matrix4d;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * An affine transform made of translations, rotations and scalings, applied in the order they
 * were added: {@code Transform.scale(2).rotate(90, 0, 1, 0).translate(1, 0, 0)} first scales,
 * then rotates, then translates. Immutable; it remembers its steps, so that a scene file can
 * write it back as it was given.
 *
 * <p>Applied to a mesh, positions go through the matrix M, normals through the inverse transpose
 * of its linear part (and are renormalised); a mirroring transform (det M &lt; 0) also reverses
 * the winding of every triangle, so that outward-facing surfaces stay outward-facing. A sphere
 * stays a sphere only under a similarity (rotation, uniform scale, translation); any other
 * transform of a sphere is refused.
 */
public final class Transform {
    /** The kind of one step. */
    enum Kind {
        /** Adds (x, y, z) to every point. */
        TRANSLATE,
        /** Rotates by {@code degrees} about the axis (x, y, z) through the origin, counter-clockwise looking down the axis. */
        ROTATE,
        /** Multiplies coordinate i by the i-th factor. */
        SCALE
    }

    /**
     * One step of a transform.
     *
     * @param kind    what the step does
     * @param x       first component of the offset, axis or scale factors
     * @param y       second component
     * @param z       third component
     * @param degrees the rotation angle (0 for the other kinds)
     */
    record Step(Kind kind, double x, double y, double z, double degrees) {
        /**
         * Checks that the step is finite and not degenerate.
         *
         * @param kind    what the step does
         * @param x       first component
         * @param y       second component
         * @param z       third component
         * @param degrees the rotation angle (0 for the other kinds)
         */
        Step {
            Objects.requireNonNull(kind, "kind");
            if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z) || !Double.isFinite(degrees)) {
                throw new IllegalArgumentException(kind.name().toLowerCase(java.util.Locale.ROOT) + " must be finite, got (" + x + ", " + y + ", " + z + ")"
                        + (kind == Kind.ROTATE ? " by " + degrees + " degrees" : ""));
            }
            if (kind == Kind.ROTATE && x == 0 && y == 0 && z == 0) {
                throw new IllegalArgumentException("the rotation axis must not be zero");
            }
            if (kind == Kind.SCALE && (x == 0 || y == 0 || z == 0)) {
                throw new IllegalArgumentException("scale factors must not be zero, got (" + x + ", " + y + ", " + z + ")");
            }
        }
    }

    /** The transform that changes nothing. */
    public static final Transform IDENTITY = new Transform(List.of());

    private final List<Step> steps;
    private final Matrix4d matrix;

    private Transform(List<Step> steps) {
        this.steps = List.copyOf(steps);
        Matrix4d m = new Matrix4d();
        for (Step s : this.steps) {
            Matrix4d step = switch (s.kind()) {
                case TRANSLATE -> new Matrix4d().translation(s.x(), s.y(), s.z());
                case ROTATE -> new Matrix4d().rotation(Math.toRadians(s.degrees()), unit(s.x(), s.y(), s.z()));
                case SCALE -> new Matrix4d().scaling(s.x(), s.y(), s.z());
            };
            m = step.mul(m);                   // later steps act on the result of earlier ones
        }
        if (!m.isFinite()) {
            throw new IllegalArgumentException("the steps multiply to a matrix beyond the range of numbers (too large a scale or translation)");
        }
        this.matrix = m;
    }

    /** The unit vector along (x, y, z), also for axes whose squared length under- or overflows. */
    private static Vector3d unit(double x, double y, double z) {
        double max = Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
        return new Vector3d(x / max, y / max, z / max).normalize();
    }

    /**
     * A transform from its steps, applied in list order.
     *
     * @param steps the steps, first applied first
     * @return the transform
     * @throws IllegalArgumentException if the steps multiply to a matrix that is not finite
     */
    static Transform of(List<Step> steps) {
        return steps.isEmpty() ? IDENTITY : new Transform(steps);
    }

    /**
     * A translation.
     *
     * @param x offset along x
     * @param y offset along y
     * @param z offset along z
     * @return the transform
     */
    public static Transform translation(double x, double y, double z) {
        return IDENTITY.translate(x, y, z);
    }

    /**
     * A uniform scaling about the origin.
     *
     * @param factor the scale factor, not zero
     * @return the transform
     */
    public static Transform scaling(double factor) {
        return IDENTITY.scale(factor, factor, factor);
    }

    /**
     * A rotation about an axis through the origin.
     *
     * @param degrees the angle, counter-clockwise looking down the axis towards the origin
     * @param x       axis x
     * @param y       axis y
     * @param z       axis z
     * @return the transform
     */
    public static Transform rotation(double degrees, double x, double y, double z) {
        return IDENTITY.rotate(degrees, x, y, z);
    }

    /**
     * This transform followed by a translation.
     *
     * @param x offset along x
     * @param y offset along y
     * @param z offset along z
     * @return the combined transform
     */
    public Transform translate(double x, double y, double z) {
        return then(new Step(Kind.TRANSLATE, x, y, z, 0));
    }

    /**
     * This transform followed by a rotation about an axis through the origin.
     *
     * @param degrees the angle, counter-clockwise looking down the axis towards the origin
     * @param x       axis x
     * @param y       axis y
     * @param z       axis z
     * @return the combined transform
     */
    public Transform rotate(double degrees, double x, double y, double z) {
        return then(new Step(Kind.ROTATE, x, y, z, degrees));
    }

    /**
     * This transform followed by a uniform scaling about the origin.
     *
     * @param factor the scale factor, not zero
     * @return the combined transform
     */
    public Transform scale(double factor) {
        return scale(factor, factor, factor);
    }

    /**
     * This transform followed by a scaling about the origin, one factor per axis.
     *
     * @param x factor along x, not zero
     * @param y factor along y, not zero
     * @param z factor along z, not zero
     * @return the combined transform
     */
    public Transform scale(double x, double y, double z) {
        return then(new Step(Kind.SCALE, x, y, z, 0));
    }

    private Transform then(Step step) {
        List<Step> more = new ArrayList<>(steps);
        more.add(step);
        return new Transform(more);
    }

    /**
     * The steps, first applied first.
     *
     * @return an unmodifiable list
     */
    List<Step> steps() {
        return steps;
    }

    /**
     * The transform as a matrix acting on column vectors (p' = M p).
     *
     * @return a copy of the matrix
     */
    public Matrix4d matrix() {
        return new Matrix4d(matrix);
    }

    /**
     * Whether this transform changes nothing.
     *
     * @return true for the identity (whatever its steps)
     */
    public boolean isIdentity() {
        return matrix.equals(new Matrix4d(), 0);
    }

    /**
     * Transforms a point.
     *
     * @param p    the point
     * @param dest receives M p
     * @return {@code dest}
     */
    public Vector3d applyToPoint(Vector3dc p, Vector3d dest) {
        return matrix.transformPosition(p, dest);
    }

    /**
     * The mesh with every vertex moved by this transform (see the class comment for normals and winding).
     *
     * @param mesh the mesh in its own coordinates
     * @return the transformed mesh (the same mesh for the identity)
     * @throws IllegalArgumentException if the transform moves a vertex beyond the range of {@code float}
     */
    public TriangleMesh apply(TriangleMesh mesh) {
        if (isIdentity()) {
            return mesh;
        }
        float[] p = mesh.positions();
        Vector3d v = new Vector3d();
        for (int i = 0; i < p.length; i += 3) {
            matrix.transformPosition(v.set(p[i], p[i + 1], p[i + 2]));
            if (!(Math.abs(v.x) <= Float.MAX_VALUE && Math.abs(v.y) <= Float.MAX_VALUE && Math.abs(v.z) <= Float.MAX_VALUE)) {
                throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                        "the transform moves vertex %d (%s, %s, %s) to (%.3g, %.3g, %.3g), beyond the range of float coordinates",
                        i / 3 + 1, p[i], p[i + 1], p[i + 2], v.x, v.y, v.z));
            }
            p[i] = (float) v.x;
            p[i + 1] = (float) v.y;
            p[i + 2] = (float) v.z;
        }
        float[] n = mesh.normals();
        if (n != null) {
            Matrix3d normalMatrix = new Matrix3d(matrix).invert().transpose();
            for (int i = 0; i < n.length; i += 3) {
                if (Float.isNaN(n[i])) {
                    continue;                        // a vertex without a normal keeps none
                }
                normalMatrix.transform(v.set(n[i], n[i + 1], n[i + 2])).normalize();
                n[i] = (float) v.x;
                n[i + 1] = (float) v.y;
                n[i + 2] = (float) v.z;
            }
        }
        int[] idx = mesh.indices();
        if (matrix.determinant() < 0) {
            for (int t = 0; t < idx.length; t += 3) {
                int swap = idx[t + 1];
                idx[t + 1] = idx[t + 2];
                idx[t + 2] = swap;
            }
        }
        return new TriangleMesh(p, idx, n, mesh.uvsUnsafe());
    }

    /**
     * Whether the transform keeps a sphere a sphere: it is made of translations, rotations and
     * uniform scalings only (a similarity). Spheres accept no other transform.
     *
     * @return true for a similarity
     */
    public boolean isSimilarity() {
        Matrix3d linear = new Matrix3d(matrix);
        Matrix3d gram = new Matrix3d(linear).transpose().mul(linear);      // s² I for a similarity
        double s2 = gram.m00();
        double tolerance = 1e-9 * s2;
        return Math.abs(gram.m11() - s2) <= tolerance && Math.abs(gram.m22() - s2) <= tolerance
                && Math.abs(gram.m01()) <= tolerance && Math.abs(gram.m02()) <= tolerance && Math.abs(gram.m12()) <= tolerance;
    }

    /**
     * The sphere moved by this transform.
     *
     * @throws IllegalArgumentException if the transform is not a similarity (it scales the axes unequally)
     */
    Sphere apply(Sphere sphere) {
        Matrix3d linear = new Matrix3d(matrix);
        double sx = linear.getColumn(0, new Vector3d()).length();
        if (!isSimilarity()) {
            double sy = linear.getColumn(1, new Vector3d()).length();
            double sz = linear.getColumn(2, new Vector3d()).length();
            throw new IllegalArgumentException("a sphere can only be translated, rotated and scaled uniformly; this transform scales"
                    + " its axes by " + (float) sx + ", " + (float) sy + " and " + (float) sz);
        }
        Vector3d c = matrix.transformPosition(new Vector3d(sphere.center()));
        return new Sphere(c, sphere.radius() * sx);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Transform t && t.steps.equals(steps);
    }

    @Override
    public int hashCode() {
        return steps.hashCode();
    }

    @Override
    public String toString() {
        return "Transform" + steps;
    }
}
