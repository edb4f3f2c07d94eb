package dev.strahl.geometry;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.scene.TriangleMesh;
import dev.strahl.testing.Meshes;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class MeshTopologyTest {

    /** Corner i of the unit cube is (i & 1, i >> 1 & 1, i >> 2 & 1). */
    private static final int[][] CUBE_FACES = {
        {0, 4, 6, 2}, {1, 3, 7, 5},   // -x, +x
        {0, 1, 5, 4}, {2, 6, 7, 3},   // -y, +y
        {0, 2, 3, 1}, {4, 5, 7, 6},   // -z, +z
    };

    /** A soup of quads: every quad has its own four vertices, as in an OBJ with one 'v' block per face. */
    private static final class Soup {
        final List<Float> pos = new ArrayList<>();
        final List<Integer> idx = new ArrayList<>();
        final List<Integer> group = new ArrayList<>();

        /** Adds a quad (fan-triangulated like the OBJ reader: (v0, v1, v2), (v0, v2, v3)). */
        Soup quad(float[][] corners, int g) {
            int base = pos.size() / 3;
            for (float[] c : corners) {
                pos.add(c[0]);
                pos.add(c[1]);
                pos.add(c[2]);
            }
            for (int i = 1; i + 1 < corners.length; i++) {
                idx.addAll(List.of(base, base + i, base + i + 1));
                group.add(g);
            }
            return this;
        }

        /** The faces of an axis-aligned cube at {@code origin} with edge {@code size}, skipping face {@code skip}. */
        Soup cube(float[] origin, float size, int g, boolean reversed, int skip, int flipFace) {
            for (int f = 0; f < CUBE_FACES.length; f++) {
                if (f == skip) {
                    continue;
                }
                int[] face = CUBE_FACES[f];
                float[][] corners = new float[4][];
                for (int k = 0; k < 4; k++) {
                    int c = face[(reversed ^ f == flipFace) ? 3 - k : k];
                    corners[k] = new float[] {origin[0] + size * (c & 1), origin[1] + size * (c >> 1 & 1), origin[2] + size * (c >> 2 & 1)};
                }
                quad(corners, g);
            }
            return this;
        }

        Soup cube(float[] origin, float size, int g) {
            return cube(origin, size, g, false, -1, -1);
        }

        float[] positions() {
            float[] p = new float[pos.size()];
            for (int i = 0; i < p.length; i++) {
                p[i] = pos.get(i);
            }
            return p;
        }

        int[] indices() {
            return idx.stream().mapToInt(Integer::intValue).toArray();
        }

        int[] groups() {
            return group.stream().mapToInt(Integer::intValue).toArray();
        }

        boolean[] closed(int groupCount) {
            return MeshTopology.closedOutwardGroups(positions(), indices(), groups(), groupCount);
        }
    }

    private static final float[] OFF_ORIGIN = {5, -3, 2};

    @Test
    void cubeHelperWindsEveryFaceOutwards() {
        // Guards the test data: each face normal cross(v1 - v0, v2 - v0) points away from the centre.
        Soup s = new Soup().cube(new float[] {0, 0, 0}, 1, 0);
        float[] p = s.positions();
        int[] idx = s.indices();
        for (int t = 0; t < idx.length / 3; t++) {
            double[] a = vertex(p, idx[3 * t]), b = vertex(p, idx[3 * t + 1]), c = vertex(p, idx[3 * t + 2]);
            double[] e1 = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2 = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            double[] n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
            double[] towardsFace = {(a[0] + b[0] + c[0]) / 3 - 0.5, (a[1] + b[1] + c[1]) / 3 - 0.5, (a[2] + b[2] + c[2]) / 3 - 0.5};
            assertThat(n[0] * towardsFace[0] + n[1] * towardsFace[1] + n[2] * towardsFace[2]).as("triangle %d", t).isPositive();
        }
    }

    @Test
    void unweldedCubeWithSharedPositionsIsClosedAndOutward() {
        assertThat(new Soup().cube(new float[] {0, 0, 0}, 1, 0).closed(1)).containsExactly(true);
    }

    @Test
    void closednessDoesNotDependOnWhereTheCubeIs() {
        // The signed volume is summed over tetrahedra with the origin: translation must not matter.
        assertThat(new Soup().cube(OFF_ORIGIN, 0.5f, 0).closed(1)).containsExactly(true);
        assertThat(new Soup().cube(new float[] {-100, -100, -100}, 0.5f, 0).closed(1)).containsExactly(true);
    }

    @Test
    void weldedCubeIsClosedAndOutward() {
        float[] p = new float[24];
        for (int c = 0; c < 8; c++) {
            p[3 * c] = c & 1;
            p[3 * c + 1] = c >> 1 & 1;
            p[3 * c + 2] = c >> 2 & 1;
        }
        int[] idx = new int[36];
        int n = 0;
        for (int[] f : CUBE_FACES) {
            for (int[] t : new int[][] {{f[0], f[1], f[2]}, {f[0], f[2], f[3]}}) {
                for (int v : t) {
                    idx[n++] = v;
                }
            }
        }
        assertThat(MeshTopology.closedOutwardGroups(p, idx, new int[12], 1)).containsExactly(true);
    }

    @Test
    void reversedWindingIsClosedButNotOutward() {
        assertThat(new Soup().cube(OFF_ORIGIN, 1, 0, true, -1, -1).closed(1)).containsExactly(false);
    }

    @Test
    void openBoxIsNotClosed() {
        for (int skip = 0; skip < 6; skip++) {
            assertThat(new Soup().cube(OFF_ORIGIN, 1, 0, false, skip, -1).closed(1)).as("without face %d", skip).containsExactly(false);
        }
    }

    @Test
    void oneInconsistentlyWoundFaceBreaksTheSurface() {
        for (int flip = 0; flip < 6; flip++) {
            assertThat(new Soup().cube(OFF_ORIGIN, 1, 0, false, -1, flip).closed(1)).as("face %d flipped", flip).containsExactly(false);
        }
    }

    @Test
    void signedZeroCoordinatesWeldWithZero() {
        // Exporters write "-0.000000"; -0.0 and 0.0 are the same position.
        Soup s = new Soup().cube(new float[] {0, 0, 0}, 1, 0);
        float[] p = s.positions();
        for (int i = 0; i < p.length; i += 2) {
            if (p[i] == 0) {
                p[i] = -0.0f;
            }
        }
        assertThat(MeshTopology.closedOutwardGroups(p, s.indices(), s.groups(), 1)).containsExactly(true);
    }

    @Test
    void icosphereIsClosedAndOutwardAndItsInwardTwinIsNot() {
        TriangleMesh out = Meshes.icosphere(2, 1, false);
        TriangleMesh in = Meshes.icosphere(2, 1, true);
        assertThat(MeshTopology.closedOutwardGroups(out.positions(), out.indices(), new int[out.triangleCount()], 1)).containsExactly(true);
        assertThat(MeshTopology.closedOutwardGroups(in.positions(), in.indices(), new int[in.triangleCount()], 1)).containsExactly(false);
    }

    @Test
    void groupsAreEvaluatedIndependently() {
        Soup s = new Soup()
                .cube(new float[] {0, 0, 0}, 1, 0)                        // group 0: closed, outward
                .cube(new float[] {3, 0, 0}, 1, 1, false, 2, -1)           // group 1: open
                .cube(new float[] {6, 0, 0}, 1, 2, true, -1, -1);          // group 2: inward
        assertThat(s.closed(4)).containsExactly(true, false, false, false); // group 3 has no triangles
    }

    @Test
    void twoClosedCubesInOneGroupAreClosed() {
        Soup s = new Soup().cube(new float[] {0, 0, 0}, 1, 0).cube(new float[] {3, 0, 0}, 1, 0);
        assertThat(s.closed(1)).containsExactly(true);
    }

    @Test
    void aCubeSplitOverTwoGroupsIsClosedInNeither() {
        Soup s = new Soup().cube(new float[] {0, 0, 0}, 1, 0);
        int[] g = s.groups();
        for (int t = 6; t < g.length; t++) {
            g[t] = 1;
        }
        assertThat(MeshTopology.closedOutwardGroups(s.positions(), s.indices(), g, 2)).containsExactly(false, false);
    }

    // ---- the shipped Cornell Box ----------------------------------------------------------------

    @Test
    void cornellBoxesAreClosedAndOutwardTheRoomIsNot() throws IOException {
        Map<String, Soup> groups = cornellByMaterial(Path.of("scenes", "cornell-box.obj"));
        for (String box : List.of("shortBox", "tallBox")) {
            assertThat(groups.get(box).closed(1)).as(box).containsExactly(true);
        }
        for (String part : List.of("floor", "ceiling", "backWall", "leftWall", "rightWall", "light")) {
            assertThat(groups.get(part).closed(1)).as(part).containsExactly(false);
        }
        // All five walls as one group: an open box seen from inside, still not closed.
        Soup walls = new Soup();
        for (String w : List.of("floor", "ceiling", "backWall", "leftWall", "rightWall")) {
            Soup part = groups.get(w);
            float[] p = part.positions();
            int[] idx = part.indices();
            float[][] corners = new float[4][];
            // each wall is one quad: triangles (0, 1, 2), (0, 2, 3)
            for (int k = 0; k < 4; k++) {
                int v = k < 3 ? idx[k] : idx[5];
                corners[k] = Arrays.copyOfRange(p, 3 * v, 3 * v + 3);
            }
            walls.quad(corners, 0);
        }
        assertThat(walls.closed(1)).containsExactly(false);
    }

    /** A minimal reader of the v/f/usemtl lines of a simple OBJ: one quad soup per material. */
    private static Map<String, Soup> cornellByMaterial(Path obj) throws IOException {
        List<float[]> v = new ArrayList<>();
        Map<String, Soup> groups = new LinkedHashMap<>();
        String material = "";
        for (String line : Files.readAllLines(obj)) {
            String[] t = line.trim().split("\\s+");
            switch (t[0]) {
                case "v" -> v.add(new float[] {Float.parseFloat(t[1]), Float.parseFloat(t[2]), Float.parseFloat(t[3])});
                case "usemtl" -> material = t[1];
                case "f" -> {
                    float[][] corners = new float[t.length - 1][];
                    for (int k = 1; k < t.length; k++) {
                        int i = Integer.parseInt(t[k].split("/")[0]);
                        corners[k - 1] = v.get(i > 0 ? i - 1 : v.size() + i);
                    }
                    groups.computeIfAbsent(material, m -> new Soup()).quad(corners, 0);
                }
                default -> { }
            }
        }
        return groups;
    }

    private static double[] vertex(float[] p, int i) {
        return new double[] {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
    }
}
