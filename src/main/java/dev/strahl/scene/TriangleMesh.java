package dev.strahl.scene;

import java.util.Arrays;

/**
 * An indexed triangle mesh in flat arrays: {@code positions} (x, y, z per vertex), {@code indices}
 * (three vertex indices per triangle) and optional per-vertex {@code normals} (same layout as
 * positions; {@code null} when the mesh has none, NaN triples for single vertices without one)
 * and optional per-vertex texture coordinates {@code uvs} (u, v per vertex, (0, 0) at the bottom-left
 * corner of an image, as in OBJ files; {@code null} when the mesh has none, NaN pairs for single
 * vertices without them). Arrays are copied on construction so that the mesh is immutable.
 *
 * @param positions x, y, z per vertex, finite
 * @param indices   three vertex indices per triangle, each in [0, vertex count)
 * @param normals   x, y, z per vertex, or null
 * @param uvs       u, v per vertex, or null
 */
public record TriangleMesh(float[] positions, int[] indices, float[] normals, float[] uvs) {

    /**
     * Checks the array lengths, the indices and that positions are finite; copies the arrays.
     *
     * @param positions x, y, z per vertex, finite
     * @param indices   three vertex indices per triangle, each in [0, vertex count)
     * @param normals   x, y, z per vertex, or null
     * @param uvs       u, v per vertex, or null
     */
    public TriangleMesh {
        if (positions.length % 3 != 0) {
            throw new IllegalArgumentException("positions must hold x, y, z triples, got length " + positions.length);
        }
        if (indices.length % 3 != 0) {
            throw new IllegalArgumentException("indices must hold triangles (3 per face), got length " + indices.length);
        }
        if (normals != null && normals.length != positions.length) {
            throw new IllegalArgumentException("normals must have one triple per vertex: " + normals.length + " values for " + positions.length / 3 + " vertices");
        }
        if (uvs != null && uvs.length != positions.length / 3 * 2) {
            throw new IllegalArgumentException("uvs must have one u, v pair per vertex: " + uvs.length + " values for " + positions.length / 3 + " vertices");
        }
        int vertexCount = positions.length / 3;
        for (int i = 0; i < indices.length; i++) {
            if (indices[i] < 0 || indices[i] >= vertexCount) {
                throw new IllegalArgumentException("triangle " + i / 3 + " refers to vertex " + indices[i] + " of " + vertexCount);
            }
        }
        for (float p : positions) {
            if (!Float.isFinite(p)) {
                throw new IllegalArgumentException("vertex positions must be finite, got " + p);
            }
        }
        positions = positions.clone();
        indices = indices.clone();
        normals = normals == null ? null : normals.clone();
        uvs = uvs == null ? null : uvs.clone();
    }

    /**
     * A mesh without texture coordinates.
     *
     * @param positions x, y, z per vertex, finite
     * @param indices   three vertex indices per triangle, each in [0, vertex count)
     * @param normals   x, y, z per vertex, or null
     */
    public TriangleMesh(float[] positions, int[] indices, float[] normals) {
        this(positions, indices, normals, null);
    }

    /**
     * The number of triangles.
     *
     * @return indices.length / 3
     */
    public int triangleCount() {
        return indices.length / 3;
    }

    /**
     * The number of vertices.
     *
     * @return positions.length / 3
     */
    public int vertexCount() {
        return positions.length / 3;
    }

    /**
     * The positions.
     *
     * @return a copy
     */
    @Override
    public float[] positions() {
        return positions.clone();
    }

    /**
     * The indices.
     *
     * @return a copy
     */
    @Override
    public int[] indices() {
        return indices.clone();
    }

    /**
     * The normals.
     *
     * @return a copy, or null
     */
    @Override
    public float[] normals() {
        return normals == null ? null : normals.clone();
    }

    /**
     * The texture coordinates.
     *
     * @return a copy, or null
     */
    @Override
    public float[] uvs() {
        return uvs == null ? null : uvs.clone();
    }

    /**
     * The same mesh with other texture coordinates.
     *
     * @param newUvs u, v per vertex, or null
     * @return a new mesh
     */
    public TriangleMesh withUvs(float[] newUvs) {
        return new TriangleMesh(positions, indices, normals, newUvs);
    }

    /** The arrays themselves, not copies, for the scene builder and transforms; never modified. */
    float[] positionsUnsafe() {
        return positions;
    }

    int[] indicesUnsafe() {
        return indices;
    }

    float[] normalsUnsafe() {
        return normals;
    }

    float[] uvsUnsafe() {
        return uvs;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof TriangleMesh m && Arrays.equals(positions, m.positions)
                && Arrays.equals(indices, m.indices) && Arrays.equals(normals, m.normals) && Arrays.equals(uvs, m.uvs);
    }

    @Override
    public int hashCode() {
        return 31 * (31 * (31 * Arrays.hashCode(positions) + Arrays.hashCode(indices)) + Arrays.hashCode(normals)) + Arrays.hashCode(uvs);
    }

    @Override
    public String toString() {
        return "TriangleMesh[" + triangleCount() + " triangles, " + vertexCount() + " vertices" + (normals != null ? ", normals" : "") + (uvs != null ? ", uvs" : "") + "]";
    }
}
