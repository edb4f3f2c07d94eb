package dev.strahl.geometry;

import java.nio.ByteBuffer;
import java.security.MessageDigest;

/**
 * The content of a {@link Geometry} as bytes for a message digest, which ties a render
 * checkpoint to its scene ({@link Geometry#digest}): the counts, then every primitive array in a
 * fixed order. Not on any hot path.
 */
final class GeometryDigest {
    private GeometryDigest() {}

    static void feed(Geometry g, MessageDigest md) {
        ByteBuffer buf = ByteBuffer.allocate(1 << 16);
        buf.putInt(g.triangleCount()).putInt(g.sphereCount()).putInt(g.nrm == null ? 0 : 1);
        for (float f : g.pos) {
            room(md, buf, 4).putFloat(f);
        }
        for (int i : g.tri) {
            room(md, buf, 4).putInt(i);
        }
        for (float f : g.nrm == null ? new float[0] : g.nrm) {
            room(md, buf, 4).putInt(Float.floatToIntBits(f));
        }
        for (float f : g.uv == null ? new float[0] : g.uv) {
            room(md, buf, 4).putInt(Float.floatToIntBits(f));
        }
        for (int i : g.triMaterial) {
            room(md, buf, 4).putInt(i);
        }
        for (byte b : g.triFlags) {
            room(md, buf, 1).put(b);
        }
        for (double d : g.sph) {
            room(md, buf, 8).putDouble(d);
        }
        for (int i : g.sphMaterial) {
            room(md, buf, 4).putInt(i);
        }
        md.update(buf.flip());
    }

    /** {@code buf}, emptied into {@code md} first if fewer than {@code need} bytes are left. */
    private static ByteBuffer room(MessageDigest md, ByteBuffer buf, int need) {
        if (buf.remaining() < need) {
            md.update(buf.flip());
            buf.clear();
        }
        return buf;
    }
}
