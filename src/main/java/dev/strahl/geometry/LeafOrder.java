package dev.strahl.geometry;

import java.util.Arrays;

/**
 * Reorders a {@link Geometry}'s primitives, as a BVH does to store them in the order of its
 * leaves ({@link Geometry#permute}): triangles and spheres move with their materials and flags,
 * and vertices are renumbered in the order the reordered triangles first use them, so that
 * neighbouring triangles (of one leaf) find their vertices close together in memory; vertices no
 * triangle uses are dropped.
 */
final class LeafOrder {
    private LeafOrder() {}

    /** Primitive i of the result is primitive {@code order[i]} of {@code g}; triangles must stay before spheres. */
    static Geometry permute(Geometry g, int[] order) {
        int triangleCount = g.triangleCount();
        int[] tri = new int[g.tri.length];
        int[] triMaterial = new int[g.triMaterial.length];
        byte[] triFlags = new byte[g.triFlags.length];
        double[] sph = new double[g.sph.length];
        int[] sphMaterial = new int[g.sphMaterial.length];
        int vertexCount = g.pos.length / 3;
        int[] newVertex = new int[vertexCount];         // old vertex -> new, -1 while unused
        Arrays.fill(newVertex, -1);
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
        float[] pos = new float[3 * used];
        float[] nrm = g.nrm == null ? null : new float[3 * used];
        float[] uv = g.uv == null ? null : new float[2 * used];
        for (int v = 0; v < vertexCount; v++) {
            int n = newVertex[v];
            if (n >= 0) {
                System.arraycopy(g.pos, 3 * v, pos, 3 * n, 3);
                if (nrm != null) {
                    System.arraycopy(g.nrm, 3 * v, nrm, 3 * n, 3);
                }
                if (uv != null) {
                    System.arraycopy(g.uv, 2 * v, uv, 2 * n, 2);
                }
            }
        }
        return new Geometry(pos, tri, nrm, uv, triMaterial, triFlags, sph, sphMaterial);
    }
}
