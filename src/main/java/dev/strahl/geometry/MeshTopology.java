package dev.strahl.geometry;

import java.util.Arrays;

/**
 * Tells which parts of a mesh are closed, consistently oriented and facing outwards: the parts
 * whose back faces no ray from outside can reach, so that back-face culling is safe on them.
 *
 * <p>Works on primitive arrays (welding is a hash table of vertex indices, edge matching a sort
 * and binary searches), so a million-triangle mesh takes a fraction of a second and no boxed map
 * entries.
 */
public final class MeshTopology {
    private MeshTopology() {}

    /**
     * For each group of triangles (group[t] in 0..groupCount-1), whether it is a closed surface
     * with outward winding: after welding vertices with equal positions, every directed edge a→b
     * occurs once and its twin b→a occurs once, and the enclosed signed volume is positive.
     */
    public static boolean[] closedOutwardGroups(float[] positions, int[] indices, int[] group, int groupCount) {
        int triangles = indices.length / 3;
        int[] weld = weld(positions);

        // Triangles bucketed by group (a counting sort), so that each group is one contiguous run.
        int[] start = new int[groupCount + 1];
        for (int t = 0; t < triangles; t++) {
            start[group[t] + 1]++;
        }
        for (int g = 0; g < groupCount; g++) {
            start[g + 1] += start[g];
        }
        int[] byGroup = new int[triangles];
        int[] fill = Arrays.copyOf(start, groupCount);
        for (int t = 0; t < triangles; t++) {
            byGroup[fill[group[t]]++] = t;
        }

        boolean[] closed = new boolean[groupCount];
        long[] edges = new long[3 * triangles];
        for (int g = 0; g < groupCount; g++) {
            closed[g] = isClosedOutward(positions, indices, weld, byGroup, start[g], start[g + 1], edges);
        }
        return closed;
    }

    /** The test for the triangles byGroup[from..to); {@code edges} is scratch of at least 3 entries per triangle. */
    private static boolean isClosedOutward(float[] p, int[] idx, int[] weld, int[] byGroup, int from, int to, long[] edges) {
        int count = to - from;
        if (count < 4) {
            return false;
        }
        double volume = 0;
        int e = 0;
        for (int k = from; k < to; k++) {
            int t = byGroup[k];
            for (int c = 0; c < 3; c++) {
                long a = weld[idx[3 * t + c]];
                long b = weld[idx[3 * t + (c + 1) % 3]];
                edges[e++] = (a << 32) | b;
            }
            int i0 = 3 * idx[3 * t], i1 = 3 * idx[3 * t + 1], i2 = 3 * idx[3 * t + 2];
            // Signed volume of the tetrahedron (origin, v0, v1, v2): v0 · (v1 × v2) / 6.
            double cx = (double) p[i1 + 1] * p[i2 + 2] - (double) p[i1 + 2] * p[i2 + 1];
            double cy = (double) p[i1 + 2] * p[i2] - (double) p[i1] * p[i2 + 2];
            double cz = (double) p[i1] * p[i2 + 1] - (double) p[i1 + 1] * p[i2];
            volume += (p[i0] * cx + p[i0 + 1] * cy + p[i0 + 2] * cz) / 6;
        }
        Arrays.parallelSort(edges, 0, e);
        for (int i = 1; i < e; i++) {
            if (edges[i] == edges[i - 1]) {
                return false;                          // the same directed edge twice: not a 2-manifold
            }
        }
        for (int i = 0; i < e; i++) {
            long twin = (edges[i] << 32) | (edges[i] >>> 32);
            if (Arrays.binarySearch(edges, 0, e, twin) < 0) {
                return false;                          // an edge without its opposite: a hole or a flipped face
            }
        }
        return volume > 0;
    }

    /**
     * Maps each vertex to a weld id shared by exactly the vertices with the same position (-0 and
     * +0 count as equal), numbered in order of first appearance: an open-addressing hash table on
     * the coordinate bits holds the first vertex of each position.
     */
    private static int[] weld(float[] positions) {
        int n = positions.length / 3;
        int[] weld = new int[n];
        int mask = Integer.highestOneBit(Math.max(1, 2 * n - 1)) * 2 - 1;   // load factor at most 1/2
        int[] slot = new int[mask + 1];                                       // first vertex + 1; 0 = empty
        int ids = 0;
        for (int v = 0; v < n; v++) {
            int x = bits(positions[3 * v]), y = bits(positions[3 * v + 1]), z = bits(positions[3 * v + 2]);
            int h = mix(x, y, z) & mask;
            while (true) {
                int u = slot[h] - 1;
                if (u < 0) {
                    slot[h] = v + 1;
                    weld[v] = ids++;
                    break;
                }
                if (bits(positions[3 * u]) == x && bits(positions[3 * u + 1]) == y && bits(positions[3 * u + 2]) == z) {
                    weld[v] = weld[u];
                    break;
                }
                h = (h + 1) & mask;
            }
        }
        return weld;
    }

    /** A hash of three ints whose every input bit reaches the low bits (a multiply-xorshift finaliser). */
    private static int mix(int x, int y, int z) {
        long h = ((long) x * 0x9E3779B97F4A7C15L) ^ ((long) y * 0xC2B2AE3D27D4EB4FL) ^ ((long) z * 0x165667B19E3779F9L);
        h ^= h >>> 31;
        h *= 0xBF58476D1CE4E5B9L;
        return (int) (h ^ (h >>> 29));
    }

    /** Coordinate bits with -0 folded into +0 ({@code x + 0.0f} turns -0.0f into +0.0f). */
    private static int bits(float x) {
        return Float.floatToIntBits(x + 0.0f);
    }
}
