package dev.strahl.geometry;

import java.util.Arrays;
import org.joml.Vector3d;

/**
 * All primitives of a scene in flat arrays: triangles of every mesh concatenated (indexed
 * vertices, struct-of-arrays) and analytic spheres. Primitive ids 0 .. triangleCount-1 are
 * triangles, the following ones spheres. Immutable after {@link Builder#build()} and safe to share
 * between threads.
 *
 * <p>Intersection methods take t in (0, ray.tMax); new rays avoid self-intersection by starting
 * from {@link SurfacePoint#spawnOrigin}.
 */
public final class Geometry {
    /** Triangle flag: part of a closed, outward-facing mesh, so its back faces may be culled. */
    public static final byte CLOSED = 1;

    private final float[] pos;
    private final int[] tri;
    private final float[] nrm;          // per vertex, NaN where a vertex has no normal; null if none
    private final int[] triMaterial;
    private final byte[] triFlags;
    private final double[] sph;         // cx, cy, cz, r per sphere
    private final int[] sphMaterial;
    private final int triangleCount;
    private final int sphereCount;

    private Geometry(Builder b) {
        this.pos = Arrays.copyOf(b.pos, b.vertexCount * 3);
        this.tri = Arrays.copyOf(b.tri, b.triangleCount * 3);
        this.nrm = b.hasNormals ? Arrays.copyOf(b.nrm, b.vertexCount * 3) : null;
        this.triMaterial = Arrays.copyOf(b.triMaterial, b.triangleCount);
        this.triFlags = Arrays.copyOf(b.triFlags, b.triangleCount);
        this.sph = Arrays.copyOf(b.sph, b.sphereCount * 4);
        this.sphMaterial = Arrays.copyOf(b.sphMaterial, b.sphereCount);
        this.triangleCount = b.triangleCount;
        this.sphereCount = b.sphereCount;
    }

    private Geometry(Geometry g, int[] order) {
        this.triangleCount = g.triangleCount;
        this.sphereCount = g.sphereCount;
        this.tri = new int[g.tri.length];
        this.triMaterial = new int[g.triMaterial.length];
        this.triFlags = new byte[g.triFlags.length];
        this.sph = new double[g.sph.length];
        this.sphMaterial = new int[g.sphMaterial.length];
        // Vertices are renumbered in the order the reordered triangles first use them, so that
        // neighbouring triangles (of one leaf) find their vertices close together in memory;
        // vertices no triangle uses are dropped.
        int vertexCount = g.pos.length / 3;
        int[] newVertex = new int[vertexCount];
        java.util.Arrays.fill(newVertex, -1);
        int used = 0;
        boolean[] seen = new boolean[order.length];
        for (int i = 0; i < order.length; i++) {
            int old = order[i];
            if (old < 0 || old >= order.length || seen[old] || (i < triangleCount) != (old < triangleCount)) {
                throw new IllegalArgumentException("not a permutation keeping triangles before spheres: position " + i + " holds " + old);
            }
            seen[old] = true;
            if (i < triangleCount) {
                for (int k = 0; k < 3; k++) {
                    int v = g.tri[3 * old + k];
                    if (newVertex[v] < 0) {
                        newVertex[v] = used++;
                    }
                    tri[3 * i + k] = newVertex[v];
                }
                triMaterial[i] = g.triMaterial[old];
                triFlags[i] = g.triFlags[old];
            } else {
                int s = i - triangleCount, so = old - triangleCount;
                System.arraycopy(g.sph, 4 * so, sph, 4 * s, 4);
                sphMaterial[s] = g.sphMaterial[so];
            }
        }
        this.pos = new float[3 * used];
        this.nrm = g.nrm == null ? null : new float[3 * used];
        for (int v = 0; v < vertexCount; v++) {
            int n = newVertex[v];
            if (n >= 0) {
                System.arraycopy(g.pos, 3 * v, pos, 3 * n, 3);
                if (nrm != null) {
                    System.arraycopy(g.nrm, 3 * v, nrm, 3 * n, 3);
                }
            }
        }
    }

    /**
     * The same primitives in another order: primitive i of the result is primitive
     * {@code order[i]} of this one. Triangles must stay before spheres. Vertices are renumbered in
     * the order of first use (unused ones dropped). Acceleration structures use it to store
     * primitives in the order of their leaves.
     */
    public Geometry permute(int[] order) {
        if (order.length != primitiveCount()) {
            throw new IllegalArgumentException("order has " + order.length + " entries for " + primitiveCount() + " primitives");
        }
        return new Geometry(this, order);
    }

    public int triangleCount() {
        return triangleCount;
    }

    public int sphereCount() {
        return sphereCount;
    }

    public int primitiveCount() {
        return triangleCount + sphereCount;
    }

    public boolean isTriangle(int prim) {
        return prim < triangleCount;
    }

    public int material(int prim) {
        return prim < triangleCount ? triMaterial[prim] : sphMaterial[prim - triangleCount];
    }

    public boolean isClosed(int prim) {
        return prim < triangleCount && (triFlags[prim] & CLOSED) != 0;
    }

    /** Bytes held by the primitive arrays (for memory reports). */
    public long byteSize() {
        return 4L * pos.length + 4L * tri.length + (nrm == null ? 0 : 4L * nrm.length)
                + 4L * triMaterial.length + triFlags.length + 8L * sph.length + 4L * sphMaterial.length;
    }

    /**
     * The arrays behind the triangles, not copies, for acceleration structures that test
     * triangles in their own inner loops (with {@link RayTriangle}, as {@link #intersect} does): vertex
     * positions (x, y, z per vertex), vertex indices (three per triangle) and per-triangle flags
     * ({@link #CLOSED}). Never modify them.
     */
    public float[] positionArray() {
        return pos;
    }

    /** See {@link #positionArray()}. */
    public int[] indexArray() {
        return tri;
    }

    /** See {@link #positionArray()}. */
    public byte[] flagArray() {
        return triFlags;
    }

    /**
     * Feeds every primitive array into {@code md}, so that a digest identifies the geometry's
     * content (used to tie a render checkpoint to its scene). Not on any hot path.
     */
    public void digest(java.security.MessageDigest md) {
        var buf = java.nio.ByteBuffer.allocate(1 << 16);
        buf.putInt(triangleCount).putInt(sphereCount).putInt(nrm == null ? 0 : 1);
        for (float f : pos) {
            digestFlush(md, buf, 4).putFloat(f);
        }
        for (int i : tri) {
            digestFlush(md, buf, 4).putInt(i);
        }
        for (float f : nrm == null ? new float[0] : nrm) {
            digestFlush(md, buf, 4).putInt(Float.floatToIntBits(f));
        }
        for (int i : triMaterial) {
            digestFlush(md, buf, 4).putInt(i);
        }
        for (byte b : triFlags) {
            digestFlush(md, buf, 1).put(b);
        }
        for (double d : sph) {
            digestFlush(md, buf, 8).putDouble(d);
        }
        for (int i : sphMaterial) {
            digestFlush(md, buf, 4).putInt(i);
        }
        md.update(buf.flip());
    }

    private static java.nio.ByteBuffer digestFlush(java.security.MessageDigest md, java.nio.ByteBuffer buf, int need) {
        if (buf.remaining() < need) {
            md.update(buf.flip());
            buf.clear();
        }
        return buf;
    }

    /** Grows {@code box} by the bounds of a primitive. */
    public void includeBounds(int prim, Aabb box) {
        if (prim < triangleCount) {
            for (int k = 0; k < 3; k++) {
                int v = 3 * tri[3 * prim + k];
                box.include(pos[v], pos[v + 1], pos[v + 2]);
            }
        } else {
            int s = 4 * (prim - triangleCount);
            double r = sph[s + 3];
            box.include(sph[s] - r, sph[s + 1] - r, sph[s + 2] - r);
            box.include(sph[s] + r, sph[s + 1] + r, sph[s + 2] + r);
        }
    }

    /** The bounds of every primitive. */
    public Aabb bounds() {
        Aabb box = new Aabb();
        for (int i = 0; i < primitiveCount(); i++) {
            includeBounds(i, box);
        }
        return box;
    }

    /**
     * Tests one primitive; on a hit closer than {@code ray.tMax}, records it in {@code hit} and
     * shortens {@code ray.tMax}. With {@code cullBackFaces}, back faces of triangles flagged
     * {@link #CLOSED} are ignored.
     */
    public boolean intersect(int prim, Ray ray, Hit hit, boolean cullBackFaces) {
        return intersect(prim, 1, ray, hit, cullBackFaces);
    }

    /**
     * The closest hit among the primitives {@code first .. first + count - 1}, which are either
     * all triangles or all spheres (as in a BVH leaf); on a hit closer than {@code ray.tMax},
     * records it in {@code hit} and shortens {@code ray.tMax}. The same arithmetic as the
     * one-primitive test and the BVH's, so that they agree bit for bit with a loop over all
     * primitives.
     */
    public boolean intersect(int first, int count, Ray ray, Hit hit, boolean cullBackFaces) {
        if (first < triangleCount) {
            assert first + count <= triangleCount : "range mixes triangles and spheres";
            return Intersections.triangles(pos, tri, triFlags, first, first + count, ray, hit, cullBackFaces);
        }
        boolean found = false;
        for (int prim = first, end = first + count; prim < end; prim++) {
            double t = Intersections.sphere(sph, prim - triangleCount, ray);
            if (t > 0) {
                ray.tMax = t;
                hit.t = t;
                hit.prim = prim;
                hit.b1 = 0;
                hit.b2 = 0;
                found = true;
            }
        }
        return found;
    }

    /** Whether the primitive blocks the ray somewhere in (0, tMax). Never culls. */
    public boolean occludes(int prim, Ray ray) {
        return occludes(prim, 1, ray);
    }

    /**
     * Whether any of the primitives {@code first .. first + count - 1} (all triangles or all
     * spheres) blocks the ray in (0, tMax), with the arithmetic of the closest-hit test. Never culls.
     */
    public boolean occludes(int first, int count, Ray ray) {
        if (first < triangleCount) {
            return Intersections.trianglesOcclude(pos, tri, first, first + count, ray);
        }
        for (int prim = first, end = first + count; prim < end; prim++) {
            if (Intersections.sphere(sph, prim - triangleCount, ray) > 0) {
                return true;
            }
        }
        return false;
    }

    /** Fills {@code sp} with the surface data of the hit (position, normals, material). */
    public void surface(Ray ray, Hit hit, SurfacePoint sp) {
        int prim = hit.prim;
        sp.prim = prim;
        sp.material = material(prim);
        if (prim < triangleCount) {
            int a = tri[3 * prim], b = tri[3 * prim + 1], c = tri[3 * prim + 2];
            int i0 = 3 * a, i1 = 3 * b, i2 = 3 * c;
            double b1 = hit.b1, b2 = hit.b2, b0 = 1 - b1 - b2;
            // The barycentric point lies on the triangle's plane, unlike o + t·d with its round-off.
            interpolate(pos, i0, i1, i2, b0, b1, b2, sp.p);
            edgeCross(i0, i1, i2, sp.ng).normalize();
            if (nrm != null && !Float.isNaN(nrm[i0]) && !Float.isNaN(nrm[i1]) && !Float.isNaN(nrm[i2])) {
                interpolate(nrm, i0, i1, i2, b0, b1, b2, sp.n);
                double len = sp.n.length();
                if (len > 0 && Double.isFinite(len)) {
                    sp.n.div(len);
                } else {
                    sp.n.set(sp.ng);
                }
            } else {
                sp.n.set(sp.ng);
            }
        } else {
            int k = 4 * (prim - triangleCount);
            double cx = sph[k], cy = sph[k + 1], cz = sph[k + 2], r = sph[k + 3];
            ray.at(hit.t, sp.p);
            sp.ng.set(sp.p.x - cx, sp.p.y - cy, sp.p.z - cz).normalize();
            // Re-project onto the surface to remove the round-off of o + t·d.
            sp.p.set(cx + r * sp.ng.x, cy + r * sp.ng.y, cz + r * sp.ng.z);
            sp.n.set(sp.ng);
        }
    }

    /** Area of a primitive. */
    public double area(int prim) {
        if (prim < triangleCount) {
            int i0 = 3 * tri[3 * prim], i1 = 3 * tri[3 * prim + 1], i2 = 3 * tri[3 * prim + 2];
            return 0.5 * edgeCross(i0, i1, i2, new Vector3d()).length();
        }
        double r = sph[4 * (prim - triangleCount) + 3];
        return 4 * Math.PI * r * r;
    }

    /**
     * A point on a primitive from two uniform numbers, uniform by area; writes the point into
     * {@code sp.p} and its geometric normal into {@code sp.ng} (and {@code sp.n}). The one
     * sampling of triangles: light sampling and photon emission use it.
     *
     * <p>On a triangle the barycentrics are 1 − √u1 on v0, b1 = u2·√u1 on v1 and b2 = √u1 − b1
     * on v2 (pbrt-v4 §6.5.4), and the point is v0 + b1·(v1 − v0) + b2·(v2 − v0) with the edges in
     * double (as the normal's): it is v0 exactly at u1 = 0, and b2 has no round-off from 1 − √u1.
     */
    public void samplePoint(int prim, double u1, double u2, SurfacePoint sp) {
        sp.prim = prim;
        sp.material = material(prim);
        if (prim < triangleCount) {
            int i0 = 3 * tri[3 * prim], i1 = 3 * tri[3 * prim + 1], i2 = 3 * tri[3 * prim + 2];
            double su = Math.sqrt(u1);
            double b1 = u2 * su, b2 = su - b1;
            sp.p.set(pos[i0] + b1 * ((double) pos[i1] - pos[i0]) + b2 * ((double) pos[i2] - pos[i0]),
                    pos[i0 + 1] + b1 * ((double) pos[i1 + 1] - pos[i0 + 1]) + b2 * ((double) pos[i2 + 1] - pos[i0 + 1]),
                    pos[i0 + 2] + b1 * ((double) pos[i1 + 2] - pos[i0 + 2]) + b2 * ((double) pos[i2 + 2] - pos[i0 + 2]));
            edgeCross(i0, i1, i2, sp.ng).normalize();
        } else {
            int k = 4 * (prim - triangleCount);
            double z = 1 - 2 * u1;
            double rr = Math.sqrt(Math.max(0, 1 - z * z));
            double phi = 2 * Math.PI * u2;
            sp.ng.set(rr * Math.cos(phi), rr * Math.sin(phi), z);
            double r = sph[k + 3];
            sp.p.set(sph[k] + r * sp.ng.x, sph[k + 1] + r * sp.ng.y, sph[k + 2] + r * sp.ng.z);
        }
        sp.n.set(sp.ng);
    }

    /**
     * cross(v1 − v0, v2 − v0) of the triangle with vertex offsets i0, i1, i2 into {@code dest}.
     * The edges are formed in double like the intersection test: float subtraction would round
     * them and tilt ng by up to ~1e-7 off the plane the ray met, enough to misplace spawned origins.
     */
    private Vector3d edgeCross(int i0, int i1, int i2, Vector3d dest) {
        double e1x = (double) pos[i1] - pos[i0], e1y = (double) pos[i1 + 1] - pos[i0 + 1], e1z = (double) pos[i1 + 2] - pos[i0 + 2];
        double e2x = (double) pos[i2] - pos[i0], e2y = (double) pos[i2 + 1] - pos[i0 + 1], e2z = (double) pos[i2 + 2] - pos[i0 + 2];
        return dest.set(e1y * e2z - e1z * e2y, e1z * e2x - e1x * e2z, e1x * e2y - e1y * e2x);
    }

    /** b0·a[i0..] + b1·a[i1..] + b2·a[i2..] for a per-vertex triple array, into {@code dest}. */
    private static Vector3d interpolate(float[] a, int i0, int i1, int i2, double b0, double b1, double b2, Vector3d dest) {
        return dest.set(b0 * a[i0] + b1 * a[i1] + b2 * a[i2],
                b0 * a[i0 + 1] + b1 * a[i1 + 1] + b2 * a[i2 + 1],
                b0 * a[i0 + 2] + b1 * a[i1 + 2] + b2 * a[i2 + 2]);
    }

    /** Collects meshes and spheres with their material indices. */
    public static final class Builder {
        /** Creates an empty builder. */
        public Builder() {}

        private float[] pos = new float[48];
        private int[] tri = new int[48];
        private float[] nrm = new float[48];
        private int[] triMaterial = new int[16];
        private byte[] triFlags = new byte[16];
        private double[] sph = new double[16];
        private int[] sphMaterial = new int[4];
        private int vertexCount, triangleCount, sphereCount;
        private boolean hasNormals;
        private int degenerateCount;

        /**
         * Adds every non-degenerate triangle of an indexed mesh with its material and flags
         * ({@link #CLOSED}) per triangle. Triangles of zero area are skipped and counted.
         *
         * @param p         vertex positions, x, y, z per vertex
         * @param idx       three vertex indices per triangle, each in range
         * @param n         vertex normals like {@code p}, or null
         * @param materials the material index of each triangle
         * @param flags     the flags of each triangle
         */
        public Builder addMesh(float[] p, int[] idx, float[] n, int[] materials, byte[] flags) {
            int triangles = idx.length / 3;
            if (materials.length != triangles || flags.length != triangles) {
                throw new IllegalArgumentException("need one material and flag per triangle: " + materials.length + " for " + triangles);
            }
            int base = vertexCount;
            ensureVertices(vertexCount + p.length / 3);
            System.arraycopy(p, 0, pos, 3 * base, p.length);
            if (n != null) {
                if (!hasNormals) {
                    Arrays.fill(nrm, 0, 3 * base, Float.NaN);
                    hasNormals = true;
                }
                System.arraycopy(n, 0, nrm, 3 * base, n.length);
            } else {
                Arrays.fill(nrm, 3 * base, 3 * (base + p.length / 3), Float.NaN);
            }
            vertexCount += p.length / 3;
            for (int t = 0; t < triangles; t++) {
                int a = idx[3 * t], b = idx[3 * t + 1], c = idx[3 * t + 2];
                if (isDegenerate(p, a, b, c)) {
                    degenerateCount++;
                    continue;
                }
                ensureTriangles(triangleCount + 1);
                tri[3 * triangleCount] = base + a;
                tri[3 * triangleCount + 1] = base + b;
                tri[3 * triangleCount + 2] = base + c;
                triMaterial[triangleCount] = materials[t];
                triFlags[triangleCount] = flags[t];
                triangleCount++;
            }
            return this;
        }

        public Builder addSphere(Sphere sphere, int material) {
            if (4 * (sphereCount + 1) > sph.length) {
                sph = Arrays.copyOf(sph, 2 * sph.length);
                sphMaterial = Arrays.copyOf(sphMaterial, 2 * sphMaterial.length);
            }
            int k = 4 * sphereCount;
            sph[k] = sphere.center().x();
            sph[k + 1] = sphere.center().y();
            sph[k + 2] = sphere.center().z();
            sph[k + 3] = sphere.radius();
            sphMaterial[sphereCount++] = material;
            return this;
        }

        /** Triangles skipped so far because their area is zero. */
        public int degenerateCount() {
            return degenerateCount;
        }

        public Geometry build() {
            return new Geometry(this);
        }

        private static boolean isDegenerate(float[] p, int a, int b, int c) {
            double e1x = (double) p[3 * b] - p[3 * a], e1y = (double) p[3 * b + 1] - p[3 * a + 1], e1z = (double) p[3 * b + 2] - p[3 * a + 2];
            double e2x = (double) p[3 * c] - p[3 * a], e2y = (double) p[3 * c + 1] - p[3 * a + 1], e2z = (double) p[3 * c + 2] - p[3 * a + 2];
            double cx = e1y * e2z - e1z * e2y, cy = e1z * e2x - e1x * e2z, cz = e1x * e2y - e1y * e2x;
            return cx * cx + cy * cy + cz * cz == 0;
        }

        private void ensureVertices(int count) {
            if (3 * count > pos.length) {
                int size = Math.max(3 * count, 2 * pos.length);
                pos = Arrays.copyOf(pos, size);
                nrm = Arrays.copyOf(nrm, size);
            }
        }

        private void ensureTriangles(int count) {
            if (count > triMaterial.length) {
                int size = Math.max(count, 2 * triMaterial.length);
                tri = Arrays.copyOf(tri, 3 * size);
                triMaterial = Arrays.copyOf(triMaterial, size);
                triFlags = Arrays.copyOf(triFlags, size);
            }
        }
    }
}
