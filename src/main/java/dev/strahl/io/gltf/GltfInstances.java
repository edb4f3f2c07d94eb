package dev.strahl.io.gltf;

import dev.strahl.scene.Transform;
import org.joml.AxisAngle4d;
import org.joml.Matrix3d;
import org.joml.Matrix4d;
import org.joml.Vector3d;

/**
 * A glTF placement as the steps of an instance's {@link Transform}: a node's world matrix is
 * T · R · S when no parent shears it (the common case: glTF's local transforms are T · R · S, and
 * a product of them shears only under a parent's unequal scale with a child's rotation). A
 * mirror (negative determinant) becomes a negative scale along x.
 */
final class GltfInstances {
    private GltfInstances() {}

    /** How far from orthonormal the rotation part may be (relative): round-off of a chain of products, not a shear. */
    private static final double TOLERANCE = 1e-9;

    /** The steps scale, rotate, translate giving {@code world}, or null where it shears. */
    static Transform steps(Matrix4d world) {
        Vector3d c0 = world.getColumn(0, new Vector3d()), c1 = world.getColumn(1, new Vector3d()), c2 = world.getColumn(2, new Vector3d());
        double s0 = c0.length(), s1 = c1.length(), s2 = c2.length();
        if (!(s0 > 0 && s1 > 0 && s2 > 0) || !Double.isFinite(s0 + s1 + s2)) {
            return null;
        }
        if (world.determinant3x3() < 0) {
            s0 = -s0;
        }
        Matrix3d r = new Matrix3d(c0.div(s0), c1.div(s1), c2.div(s2));
        if (Math.abs(r.getColumn(0, new Vector3d()).dot(r.getColumn(1, new Vector3d()))) > TOLERANCE
                || Math.abs(r.getColumn(0, new Vector3d()).dot(r.getColumn(2, new Vector3d()))) > TOLERANCE
                || Math.abs(r.getColumn(1, new Vector3d()).dot(r.getColumn(2, new Vector3d()))) > TOLERANCE) {
            return null;
        }
        Transform t = Transform.IDENTITY.scale(s0, s1, s2);
        AxisAngle4d a = new AxisAngle4d().set(r);
        if (a.angle != 0 && Double.isFinite(a.angle) && (a.x != 0 || a.y != 0 || a.z != 0)) {
            t = t.rotate(Math.toDegrees(a.angle), a.x, a.y, a.z);
        }
        t = t.translate(world.m30(), world.m31(), world.m32());
        // The steps must give the matrix back (else, such as near a half turn where the axis is ill-conditioned, copy).
        Matrix4d back = t.matrix();
        double scale = Math.max(Math.abs(s0), Math.max(s1, s2));
        for (int col = 0; col < 4; col++) {
            for (int row = 0; row < 3; row++) {
                if (!(Math.abs(back.get(col, row) - world.get(col, row)) <= 1e-9 * (col == 3 ? 1 + Math.abs(world.get(col, row)) : scale))) {
                    return null;
                }
            }
        }
        return t;
    }
}
