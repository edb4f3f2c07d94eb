package dev.strahl.geometry;

import java.util.HashMap;
import java.util.Map;

/**
 * Tells which parts of a mesh are closed, consistently oriented and facing outwards: the parts
 * whose back faces no ray from outside can reach, so that back-face culling is safe on them.
 */
public final class MeshTopology {
    private MeshTopology() {}

    /**
     * For each group of triangles (group[t] in 0..groupCount-1), whether it is a closed surface
     * with outward winding: after welding vertices with equal positions, every directed edge a→b
     * occurs once and its twin b→a occurs once, and the enclosed signed volume is positive.
     */
    public static boolean[] closedOutwardGroups(float[] positions, int[] indices, int[] group, int groupCount) {
        int[] weld = weld(positions);
        boolean[] closed = new boolean[groupCount];
        for (int g = 0; g < groupCount; g++) {
            closed[g] = isClosedOutward(positions, indices, weld, group, g);
        }
        return closed;
    }

    private static boolean isClosedOutward(float[] p, int[] idx, int[] weld, int[] group, int g) {
        Map<Long, Integer> edges = new HashMap<>();
        double volume = 0;
        int triangles = 0;
        for (int t = 0; t < idx.length / 3; t++) {
            if (group[t] != g) {
                continue;
            }
            triangles++;
            for (int k = 0; k < 3; k++) {
                long a = weld[idx[3 * t + k]];
                long b = weld[idx[3 * t + (k + 1) % 3]];
                if (edges.merge((a << 32) | b, 1, Integer::sum) > 1) {
                    return false;                      // the same directed edge twice: not a 2-manifold
                }
            }
            int i0 = 3 * idx[3 * t], i1 = 3 * idx[3 * t + 1], i2 = 3 * idx[3 * t + 2];
            // Signed volume of the tetrahedron (origin, v0, v1, v2): v0 · (v1 × v2) / 6.
            double cx = (double) p[i1 + 1] * p[i2 + 2] - (double) p[i1 + 2] * p[i2 + 1];
            double cy = (double) p[i1 + 2] * p[i2] - (double) p[i1] * p[i2 + 2];
            double cz = (double) p[i1] * p[i2 + 1] - (double) p[i1 + 1] * p[i2];
            volume += (p[i0] * cx + p[i0 + 1] * cy + p[i0 + 2] * cz) / 6;
        }
        if (triangles < 4) {
            return false;
        }
        for (long key : edges.keySet()) {
            long twin = (key << 32) | (key >>> 32);
            if (!edges.containsKey(twin)) {
                return false;
            }
        }
        return volume > 0;
    }

    /** Maps each vertex to the first vertex with exactly the same position (-0 and +0 are the same). */
    private static int[] weld(float[] positions) {
        int n = positions.length / 3;
        int[] weld = new int[n];
        Map<String, Integer> first = new HashMap<>();
        for (int v = 0; v < n; v++) {
            // x + 0.0f turns -0.0f into +0.0f, whose bits differ although the positions are equal
            String key = Float.floatToIntBits(positions[3 * v] + 0.0f) + "," + Float.floatToIntBits(positions[3 * v + 1] + 0.0f)
                    + "," + Float.floatToIntBits(positions[3 * v + 2] + 0.0f);
            weld[v] = first.computeIfAbsent(key, k -> first.size());
        }
        return weld;
    }
}
