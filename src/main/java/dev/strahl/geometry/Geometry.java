package dev.strahl.geometry;

import org.joml.Vector3d;

/**
 * All primitives of a scene in flat arrays: triangles of every mesh concatenated (indexed
 * vertices, struct-of-arrays) and analytic spheres. Primitive ids 0 .. triangleCount-1 are
 * triangles, the following ones spheres. Immutable and safe to share
 * between threads. Built by {@link GeometryBuilder}.
 *
 * <p>Intersection methods take t in (0, ray.tMax); new rays avoid self-intersection by starting
 * from {@link SurfacePoint#spawnOrigin}.
 */
public final class Geometry {
    /** Triangle flag: part of a closed, outward-facing mesh, so its back faces may be culled. */
    public static final byte CLOSED = 1;

    // Package-private for the builder, the leaf reordering and the digest (GeometryBuilder, LeafOrder, GeometryDigest).
    final float[] pos;
    final int[] tri;
    final float[] nrm;          // per vertex, NaN where a vertex has no normal; null if none
    final float[] uv;           // u, v per vertex, NaN where a vertex has none; null if no mesh has texture coordinates
    final int[] triMaterial;
    final byte[] triFlags;
    final double[] sph;         // cx, cy, cz, r per sphere
    final int[] sphMaterial;
    private final int triangleCount;
    private final int sphereCount;

    /** Takes the arrays (not copies); the counts are those of the material arrays. */
    Geometry(float[] pos, int[] tri, float[] nrm, float[] uv, int[] triMaterial, byte[] triFlags, double[] sph, int[] sphMaterial) {
        this.pos = pos;
        this.nrm = nrm;
        this.uv = uv;
        this.tri = tri;
        this.triMaterial = triMaterial;
        this.triFlags = triFlags;
        this.triangleCount = triMaterial.length;
        this.sph = sph;
        this.sphMaterial = sphMaterial;
        this.sphereCount = sphMaterial.length;
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
        return LeafOrder.permute(this, order);
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
        return 4L * pos.length + 4L * tri.length + (nrm == null ? 0 : 4L * nrm.length) + (uv == null ? 0 : 4L * uv.length)
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
        GeometryDigest.feed(this, md);
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

    /**
     * Fills {@code sp} with the surface data of the hit: position, normals, material, texture
     * coordinates and dp/du. A triangle's (u, v) are its vertices' interpolated, or the barycentrics
     * (b1, b2) where a vertex has none (Mitsuba's default); dp/du follows from the triangle's
     * positions and (u, v) (pbrt-v4 §6.5.3; any vector in the plane if the (u, v) are degenerate).
     * A sphere's are u = φ/2π, v = 1 − θ/π about the y axis (θ from +y, φ = atan2(z, x) from +x
     * towards +z), so the image's top row is the north pole.
     */
    public void surface(Ray ray, Hit hit, SurfacePoint sp) {
        if (hit.prim >= triangleCount) {
            ray.at(hit.t, sp.p);
        }
        surfaceAt(hit, sp);
    }

    /**
     * {@link #surface} where the ray is no longer at hand (a hit in an instance, whose ray was in
     * the instance's coordinates): a triangle needs only the barycentrics; for a sphere,
     * {@code sp.p} must hold the point o + t·d of the hit in this geometry's coordinates.
     */
    public void surfaceAt(Hit hit, SurfacePoint sp) {
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
            texCoords(a, b, c, b0, b1, b2, sp);
        } else {
            int k = 4 * (prim - triangleCount);
            double cx = sph[k], cy = sph[k + 1], cz = sph[k + 2], r = sph[k + 3];
            sp.ng.set(sp.p.x - cx, sp.p.y - cy, sp.p.z - cz).normalize();
            // Re-project onto the surface to remove the round-off of o + t·d.
            sp.p.set(cx + r * sp.ng.x, cy + r * sp.ng.y, cz + r * sp.ng.z);
            sp.n.set(sp.ng);
            sphereTexCoords(r, sp);
        }
    }

    /**
     * A sphere's u = φ/2π, v = 1 − θ/π and dp/du = 2π r (−z', 0, x') at the point with outward
     * normal {@code sp.ng}; (dp/du, dp/dv, ng) is left-handed, so {@code sp.tangentSign} = −1.
     */
    private static void sphereTexCoords(double r, SurfacePoint sp) {
        double phi = Math.atan2(sp.ng.z, sp.ng.x);
        if (phi < 0) {
            phi += 2 * Math.PI;
        }
        double theta = Math.acos(Math.max(-1, Math.min(1, sp.ng.y)));
        sp.uv.set(phi * (0.5 / Math.PI), 1 - theta / Math.PI);
        sp.dpdu.set(-2 * Math.PI * r * sp.ng.z, 0, 2 * Math.PI * r * sp.ng.x);
        sp.tangentSign = -1;
    }

    /** The texture coordinates and dp/du of a point with barycentrics (b0, b1, b2) on the triangle (a, b, c). */
    private void texCoords(int a, int b, int c, double b0, double b1, double b2, SurfacePoint sp) {
        float[] t = uv;
        sp.tangentSign = 1;
        if (t == null || Float.isNaN(t[2 * a]) || Float.isNaN(t[2 * b]) || Float.isNaN(t[2 * c])) {
            sp.uv.set(b1, b2);
            sp.dpdu.set((double) pos[3 * b] - pos[3 * a], (double) pos[3 * b + 1] - pos[3 * a + 1], (double) pos[3 * b + 2] - pos[3 * a + 2]);
            return;
        }
        double u0 = t[2 * a], v0 = t[2 * a + 1], u1 = t[2 * b], v1 = t[2 * b + 1], u2 = t[2 * c], v2 = t[2 * c + 1];
        sp.uv.set(b0 * u0 + b1 * u1 + b2 * u2, b0 * v0 + b1 * v1 + b2 * v2);
        // Solve dp02 = du02 dpdu + dv02 dpdv, dp12 = du12 dpdu + dv12 dpdv for dpdu (pbrt-v4 §6.5.3).
        double du02 = u0 - u2, dv02 = v0 - v2, du12 = u1 - u2, dv12 = v1 - v2;
        double det = du02 * dv12 - dv02 * du12;
        int i0 = 3 * a, i1 = 3 * b, i2 = 3 * c;
        double p02x = (double) pos[i0] - pos[i2], p02y = (double) pos[i0 + 1] - pos[i2 + 1], p02z = (double) pos[i0 + 2] - pos[i2 + 2];
        double p12x = (double) pos[i1] - pos[i2], p12y = (double) pos[i1 + 1] - pos[i2 + 1], p12z = (double) pos[i1 + 2] - pos[i2 + 2];
        if (Math.abs(det) < 1e-12) {
            sp.dpdu.set(p12x, p12y, p12z);
            return;
        }
        double inv = 1 / det;
        // cross(dp/du, dp/dv) = ng·|e1 × e2| / det: a negative det is a mirrored mapping.
        sp.tangentSign = det < 0 ? -1 : 1;
        sp.dpdu.set((dv12 * p02x - dv02 * p12x) * inv, (dv12 * p02y - dv02 * p12y) * inv, (dv12 * p02z - dv02 * p12z) * inv);
    }

    /** Whether any mesh has texture coordinates. */
    public boolean hasTexCoords() {
        return uv != null;
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
     * {@code sp.p}, its geometric normal into {@code sp.ng} (and {@code sp.n}) and its texture
     * coordinates (as {@link #surface} gives them) into {@code sp.uv}. The one
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
            texCoords(i0 / 3, i1 / 3, i2 / 3, 1 - su, b1, b2, sp);
        } else {
            int k = 4 * (prim - triangleCount);
            double z = 1 - 2 * u1;
            double rr = Math.sqrt(Math.max(0, 1 - z * z));
            double phi = 2 * Math.PI * u2;
            sp.ng.set(rr * Math.cos(phi), rr * Math.sin(phi), z);
            double r = sph[k + 3];
            sp.p.set(sph[k] + r * sp.ng.x, sph[k + 1] + r * sp.ng.y, sph[k + 2] + r * sp.ng.z);
            sphereTexCoords(r, sp);
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
}
