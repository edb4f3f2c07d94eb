package dev.strahl.geometry;

import java.util.Arrays;

/**
 * Collects meshes and spheres with their material indices into a {@link Geometry}: triangles of
 * every mesh concatenated (indexed vertices), degenerate ones skipped.
 */
public final class GeometryBuilder {
    private float[] pos = new float[48];
    private int[] tri = new int[48];
    private float[] nrm = new float[48];
    private float[] uv = new float[32];
    private int[] triMaterial = new int[16];
    private byte[] triFlags = new byte[16];
    private double[] sph = new double[16];
    private int[] sphMaterial = new int[4];
    private int vertexCount, triangleCount, sphereCount;
    private boolean hasNormals, hasUvs;
    private int degenerateCount;

    /** Creates an empty builder. */
    public GeometryBuilder() {}

    /**
     * Adds every non-degenerate triangle of an indexed mesh with its material and flags
     * ({@link Geometry#CLOSED}) per triangle. Triangles of zero area are skipped and counted.
     *
     * @param p         vertex positions, x, y, z per vertex
     * @param idx       three vertex indices per triangle, each in range
     * @param n         vertex normals like {@code p}, or null
     * @param materials the material index of each triangle
     * @param flags     the flags of each triangle
     */
    public GeometryBuilder addMesh(float[] p, int[] idx, float[] n, int[] materials, byte[] flags) {
        return addMesh(p, idx, n, null, materials, flags);
    }

    /**
     * {@link #addMesh(float[], int[], float[], int[], byte[])} with texture coordinates.
     *
     * @param uvs u, v per vertex, or null
     */
    public GeometryBuilder addMesh(float[] p, int[] idx, float[] n, float[] uvs, int[] materials, byte[] flags) {
        int triangles = idx.length / 3;
        if (materials.length != triangles || flags.length != triangles) {
            throw new IllegalArgumentException("need one material and flag per triangle: " + materials.length + " for " + triangles);
        }
        int base = vertexCount;
        ensureVertices(vertexCount + p.length / 3);
        System.arraycopy(p, 0, pos, 3 * base, p.length);
        hasNormals = addAttribute(n, nrm, 3, base, p.length / 3, hasNormals);
        if (uvs != null && uvs.length != 2 * (p.length / 3)) {
            throw new IllegalArgumentException("need u, v per vertex: " + uvs.length + " values for " + p.length / 3 + " vertices");
        }
        hasUvs = addAttribute(uvs, uv, 2, base, p.length / 3, hasUvs);
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

    /**
     * Copies a vertex attribute ({@code perVertex} floats a vertex: normals, texture coordinates)
     * of {@code count} new vertices from {@code base} on into {@code dest}: NaN where the mesh has
     * none, and once a mesh has it, NaN for the vertices before that had none.
     *
     * @return whether the geometry has the attribute now
     */
    private static boolean addAttribute(float[] values, float[] dest, int perVertex, int base, int count, boolean had) {
        if (values == null) {
            Arrays.fill(dest, perVertex * base, perVertex * (base + count), Float.NaN);
            return had;
        }
        if (!had) {
            Arrays.fill(dest, 0, perVertex * base, Float.NaN);
        }
        System.arraycopy(values, 0, dest, perVertex * base, values.length);
        return true;
    }

    public GeometryBuilder addSphere(Sphere sphere, int material) {
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
        return new Geometry(Arrays.copyOf(pos, 3 * vertexCount), Arrays.copyOf(tri, 3 * triangleCount),
                hasNormals ? Arrays.copyOf(nrm, 3 * vertexCount) : null, hasUvs ? Arrays.copyOf(uv, 2 * vertexCount) : null,
                Arrays.copyOf(triMaterial, triangleCount),
                Arrays.copyOf(triFlags, triangleCount), Arrays.copyOf(sph, 4 * sphereCount), Arrays.copyOf(sphMaterial, sphereCount));
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
            uv = Arrays.copyOf(uv, 2 * (size / 3));
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
