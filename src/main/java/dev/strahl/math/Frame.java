package dev.strahl.math;

import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * An orthonormal basis (s, t, n) with n as the z axis: the local shading frame. Mutable so that
 * one instance per thread can be reset at every hit.
 */
public final class Frame {
    /** Creates a frame to be {@link #set} before use. */
    public Frame() {}

    private double sx, sy, sz, tx, ty, tz, nx, ny, nz;

    /**
     * Builds the basis around the unit vector {@code n} without branches on its direction
     * (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017).
     */
    public Frame set(double nx, double ny, double nz) {
        double sign = Math.copySign(1.0, nz);
        double a = -1.0 / (sign + nz);
        double b = nx * ny * a;
        this.sx = 1.0 + sign * nx * nx * a;
        this.sy = sign * b;
        this.sz = -sign * nx;
        this.tx = b;
        this.ty = sign + ny * ny * a;
        this.tz = -ny;
        this.nx = nx;
        this.ny = ny;
        this.nz = nz;
        return this;
    }

    public Frame set(Vector3dc n) {
        return set(n.x(), n.y(), n.z());
    }

    /** World direction into local coordinates; writes into and returns {@code dest}. */
    public Vector3d toLocal(Vector3dc w, Vector3d dest) {
        double x = w.x(), y = w.y(), z = w.z();
        return dest.set(sx * x + sy * y + sz * z, tx * x + ty * y + tz * z, nx * x + ny * y + nz * z);
    }

    /** Local direction into world coordinates; writes into and returns {@code dest}. */
    public Vector3d toWorld(Vector3dc w, Vector3d dest) {
        double x = w.x(), y = w.y(), z = w.z();
        return dest.set(sx * x + tx * y + nx * z, sy * x + ty * y + ny * z, sz * x + tz * y + nz * z);
    }
}
