package dev.strahl.io.obj;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.fail;
import static org.assertj.core.api.Assertions.offset;

import dev.strahl.io.text.HeapBudget;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.image.Rgb;
import dev.strahl.testing.TestData;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

public class ObjReaderTest {


    private static final String SQUARE = """
            v 0 0 0
            v 1 0 0
            v 1 1 0
            v 0 1 0
            vt 0 0
            vt 1 1
            vn 0 0 1
            """;

    @TempDir
    Path dir;

    // ---- geometry ----------------------------------------------------------------------------

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "f 1 2 3 4",
        "f 1/1 2/2 3/1 4/2",
        "f 1//1 2//1 3//1 4//1",
        "f 1/2/1 2/1/1 3/2/1 4/1/1",
        "f -4 -3 -2 -1",
        "f -4/-2 -3/-1 -2/-2 -1/-1",
        "f -4//-1 -3//-1 -2//-1 -1//-1",
        "f -4/-1/-1 -3/-2/-1 -2/-1/-1 -1/-2/-1",
        "f 1/ 2/ 3// 4/1/",
    })
    void everyIndexFormGivesTheSameTriangles(String face) throws Exception {
        TriangleMesh mesh = read(SQUARE + face + "\n").mesh();
        assertThat(corners(mesh)).containsExactly(
                0, 0, 0, 1, 0, 0, 1, 1, 0,
                0, 0, 0, 1, 1, 0, 0, 1, 0);
    }

    @Test
    void negativeIndicesCountBackFromTheVerticesDefinedSoFar() throws Exception {
        ObjModel relative = read("""
                v 0 0 0
                v 1 0 0
                v 0 1 0
                f -3 -2 -1
                v 5 0 0
                v 6 0 0
                v 5 1 0
                f -3 -2 -1
                f -6 -2 -1
                """);
        ObjModel absolute = read("""
                v 0 0 0
                v 1 0 0
                v 0 1 0
                v 5 0 0
                v 6 0 0
                v 5 1 0
                f 1 2 3
                f 4 5 6
                f 1 5 6
                """);
        assertThat(corners(relative.mesh())).containsExactly(corners(absolute.mesh()));
    }

    @Test
    void quadsAndPentagonsAreFannedFromTheirFirstVertexKeepingTheWinding() throws Exception {
        var text = new StringBuilder();
        for (int i = 0; i < 5; i++) { // a counter-clockwise pentagon in the plane z = 2
            double a = 2 * Math.PI * i / 5;
            text.append(String.format(Locale.ROOT, "v %.6f %.6f 2%n", Math.cos(a), Math.sin(a)));
        }
        text.append("f 1 2 3 4\nf 1 2 3 4 5\n");
        TriangleMesh mesh = read(text.toString()).mesh();

        assertThat(mesh.triangleCount()).isEqualTo(2 + 3);
        int[] idx = mesh.indices();
        float[] p = mesh.positions();
        int[][] expectedCorners = {{0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
        for (int t = 0; t < expectedCorners.length; t++) {
            for (int k = 0; k < 3; k++) {
                assertThat(x(p, idx[3 * t + k])).as("triangle %d corner %d", t, k)
                        .isEqualTo((float) Math.cos(2 * Math.PI * expectedCorners[t][k] / 5), offset(1e-6f));
            }
            assertThat(geometricNormal(mesh, t)[2]).as("winding kept: normal of triangle %d is +z", t).isPositive();
        }
    }

    @Test
    void normalsAreAbsentWhenNoFaceUsesVn() throws Exception {
        assertThat(read(SQUARE + "f 1 2 3\n").mesh().normals()).isNull();
    }

    @Test
    void vnBecomeUnitPerVertexNormals() throws Exception {
        TriangleMesh mesh = read("""
                v 0 0 0
                v 1 0 0
                v 0 1 0
                vn 0 0 2
                vn 3 0 4
                vn 0 -1e-30 0
                f 1//1 2//2 3//3
                """).mesh();
        assertThat(mesh.normals()).containsExactly(0, 0, 1, 0.6f, 0, 0.8f, 0, -1, 0);
    }

    @Test
    void verticesWithoutVnGetNaNNormalsWhenOthersHaveOne() throws Exception {
        TriangleMesh mesh = read(SQUARE + "f 1//1 2//1 3\nf 1 3 4\n").mesh();
        float[] n = mesh.normals();
        assertThat(n).hasSize(mesh.vertexCount() * 3);
        int[] idx = mesh.indices();
        assertThat(normalOf(n, idx[0])).containsExactly(0, 0, 1);
        assertThat(normalOf(n, idx[1])).containsExactly(0, 0, 1);
        assertThat(normalOf(n, idx[2])).containsOnly(Float.NaN);
        assertThat(normalOf(n, idx[5])).containsOnly(Float.NaN);
    }

    @Test
    void zeroLengthVnMeansNoNormal() throws Exception {
        TriangleMesh mesh = read(SQUARE + "vn 0 0 0\nf 1//2 2//1 3//1\n").mesh();
        assertThat(normalOf(mesh.normals(), mesh.indices()[0])).containsOnly(Float.NaN);
        assertThat(normalOf(mesh.normals(), mesh.indices()[1])).containsExactly(0, 0, 1);
    }

    @Test
    void outputVerticesAreTheDistinctPositionNormalPairsThatFacesUse() throws Exception {
        TriangleMesh mesh = read(SQUARE + """
                v 9 9 9
                vn 1 0 0
                f 1//1 2//1 3//1
                f 1//1 3//1 4//1
                f 1//2 2//2 3
                """).mesh();
        // (1,n1) (2,n1) (3,n1) (4,n1) shared by the first two faces, then (1,n2) (2,n2) (3,none);
        // vertex 5 is never used
        assertThat(mesh.vertexCount()).isEqualTo(7);
        int[] idx = mesh.indices();
        assertThat(idx[3]).isEqualTo(idx[0]);
        assertThat(idx[4]).isEqualTo(idx[2]);
        assertThat(idx[6]).isNotEqualTo(idx[0]);
        assertThat(mesh.positions()).doesNotContain(9f);
    }

    @Test
    void aLargeGridSharesItsVerticesAndKeepsEveryFace() throws Exception {
        int n = 200;
        var text = new StringBuilder();
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                text.append("v ").append(i).append(' ').append(j).append(" 0\n");
            }
        }
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i + 1;
                text.append("f ").append(a).append(' ').append(a + 1).append(' ').append(a + n + 2).append(' ')
                        .append(a + n + 1).append('\n');
            }
        }
        TriangleMesh mesh = read(text.toString()).mesh();
        assertThat(mesh.triangleCount()).isEqualTo(2 * n * n);
        assertThat(mesh.vertexCount()).isEqualTo((n + 1) * (n + 1));
    }

    @Test
    void toleratesCommentsTabsCrlfBomAndContinuationLines() throws Exception {
        ObjModel model = read("\uFEFF# header\r\n"
                + "v\t0 0 0 # first\r\n"
                + "  v 1 0 0 1.0\r\n"          // w is ignored
                + "v 1 1 0 0.5 0.5 0.5\r\n"    // so are vertex colours
                + "v 0 1 0\r\n"
                + "\r\n"
                + "f 1 2 \\\r\n"
                + "  3 4# comment\r\n"
                + "f 1 2 3\n");
        assertThat(corners(model.mesh())).startsWith(0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0);
        assertThat(model.mesh().triangleCount()).isEqualTo(3);
        assertThat(model.warnings()).isEmpty();
    }

    // ---- materials ---------------------------------------------------------------------------

    @Test
    void facesTakeTheMaterialOfTheLastUsemtlBeforeThem() throws Exception {
        write("m.mtl", "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\nnewmtl unused\n");
        ObjModel model = read("mtllib m.mtl\n" + SQUARE + """
                f 1 2 3
                usemtl a
                f 1 2 3 4
                usemtl b
                usemtl unused
                usemtl b
                f 1 2 3
                usemtl a
                f 1 2 3
                """);
        assertThat(model.materials()).extracting(MtlMaterial::name).containsExactly("default", "a", "b");
        assertThat(namesPerTriangle(model)).containsExactly("default", "a", "a", "b", "a");
        assertThat(model.materials().get(1).kd()).isEqualTo(new Rgb(1, 0, 0));
        assertThat(model.warnings()).isEmpty();
    }

    @Test
    void anUnknownMaterialGivesOneWarningAndTheDefault() throws Exception {
        write("m.mtl", "newmtl a\n");
        ObjModel model = read("mtllib m.mtl\n" + SQUARE + """
                usemtl nope
                f 1 2 3
                usemtl a
                f 1 2 3
                usemtl nope
                f 1 2 3
                """);
        assertThat(namesPerTriangle(model)).containsExactly("default", "a", "default");
        assertThat(model.warnings()).singleElement().asString()
                .contains("t.obj").contains("unknown material 'nope' (line 9): using the default grey diffuse");
    }

    @Test
    void aMissingMaterialLibraryGivesOneWarningNamingItAndDefaultMaterials() throws Exception {
        ObjModel model = read("mtllib missing.mtl\n" + SQUARE + "usemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\n");
        assertThat(model.materials()).containsExactly(MtlMaterial.defaultMaterial());
        assertThat(model.warnings()).singleElement().asString().contains("missing.mtl").contains("line 1");
    }

    @Test
    void mtllibNamesAreRelativeToTheObjAndMayListSeveralFilesOrContainSpaces() throws Exception {
        Files.createDirectories(dir.resolve("mats"));
        write("mats/one.mtl", "newmtl a\nKd 1 0 0\n");
        write("two.mtl", "newmtl b\nKd 0 1 0\nnewmtl a\nKd 0 0 1\n");
        write("with space.mtl", "newmtl c\nKd 0 0 1\n");
        ObjModel model = read("mtllib mats/one.mtl two.mtl\nmtllib with space.mtl\n" + SQUARE
                + "usemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\nusemtl c\nf 1 2 3\n");
        assertThat(model.materials()).extracting(MtlMaterial::name).containsExactly("a", "b", "c");
        assertThat(model.materials().get(0).kd()).as("the first library defining a name wins").isEqualTo(new Rgb(1, 0, 0));
        assertThat(model.warnings()).singleElement().asString().contains("two.mtl").contains("'a'");
    }

    @Test
    void aMalformedMaterialLibraryIsAnErrorAtItsOwnLine() throws Exception {
        write("m.mtl", "newmtl a\nKd 1 oops 0\n");
        assertThatThrownBy(() -> read("mtllib m.mtl\n" + SQUARE + "f 1 2 3\n"))
                .isInstanceOf(SceneException.class).hasMessageContaining("m.mtl:2:").hasMessageContaining("'oops'");
    }

    @Test
    void groupingStatementsAreSilentWhileLinesPointsAndUnknownStatementsWarnOncePerKeyword() throws Exception {
        ObjModel model = read(SQUARE + """
                o thing
                g group
                s 1
                s off
                l 1 2
                l 2 3
                p 1
                curv 0 1 1 2
                frobnicate 1
                frobnicate 2
                f 1 2 3
                """);
        assertThat(model.warnings()).hasSize(4);
        assertThat(model.warnings()).anySatisfy(w -> assertThat(w).contains("'l'").contains("line 12"));
        assertThat(model.warnings()).anySatisfy(w -> assertThat(w).contains("'p'").contains("line 14"));
        assertThat(model.warnings()).anySatisfy(w -> assertThat(w).contains("'curv'"));
        assertThat(model.warnings()).anySatisfy(w -> assertThat(w).contains("unknown statement 'frobnicate' (line 16)"));
    }

    // ---- the Cornell Box ---------------------------------------------------------------------

    @Test
    void cornellOriginalIs18QuadsWithAWarmLightFacingDown() throws Exception {
        // 5 walls + 6 faces of each box + the light = 18 quads ("f" lines), 2 triangles each
        ObjModel model = ObjReader.read(TestData.cornell("CornellBox-Original.obj"));
        assertThat(model.mesh().triangleCount()).isEqualTo(36);
        assertThat(model.warnings()).isEmpty();
        assertThat(model.materials()).extracting(MtlMaterial::name).containsExactly(
                "floor", "ceiling", "backWall", "rightWall", "leftWall", "shortBox", "tallBox", "light");
        List<String> names = namesPerTriangle(model);
        assertThat(names.subList(34, 36)).as("the light is the last quad").containsOnly("light");
        assertThat(names.subList(0, 34)).doesNotContain("light");
        for (int t = 0; t < 36; t++) {
            assertThat(model.materialOf(t).isEmissive()).as("triangle %d emits", t).isEqualTo(t >= 34);
        }
        MtlMaterial light = model.materialOf(35);
        assertThat(light.ke()).isEqualTo(new Rgb(17, 12, 4));
        assertThat(geometricNormal(model.mesh(), 34)[1]).as("one-sided light emits downwards").isNegative();
        assertThat(geometricNormal(model.mesh(), 35)[1]).isNegative();
    }

    @ParameterizedTest
    @CsvSource({
        "CornellBox-Original.obj, 36",
        "CornellBox-Mirror.obj, 36",
        "CornellBox-Empty-RG.obj, 12",
        "CornellBox-Sphere.obj, 2188",
        "CornellBox-Glossy.obj, 1112",
    })
    void everyCornellVariantLoadsWithoutWarnings(String file, int triangles) throws Exception {
        // counts: quads count twice, the spheres are triangles ("f" lines of the files)
        ObjModel model = ObjReader.read(TestData.cornell(file));
        assertThat(model.mesh().triangleCount()).isEqualTo(triangles);
        assertThat(model.warnings()).isEmpty();
        assertThat(model.materials()).extracting(MtlMaterial::name).contains("light").doesNotContain("default");
        for (int t = 0; t < triangles; t++) {
            if (model.materialOf(t).isEmissive()) {
                assertThat(geometricNormal(model.mesh(), t)[1]).as("light triangle %d faces down", t).isNegative();
            }
        }
    }

    // ---- errors ------------------------------------------------------------------------------

    static Stream<Arguments> malformedFiles() {
        String eight = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n";
        return Stream.of(
                Arguments.of("v 1 abc 3\n", 1, "bad number 'abc' in 'v'"),
                Arguments.of(eight + "v 1 2\n", 9, "'v' needs 3 numbers (x y z), got 2"),
                Arguments.of("v\n", 1, "'v' needs 3 numbers (x y z), got 0"),
                Arguments.of("v NaN 0 0\n", 1, "'NaN' in 'v' is not finite"),
                Arguments.of("v 0 -Infinity 0\n", 1, "'-Infinity' in 'v' is not finite"),
                Arguments.of("v 0 0 1e39\n", 1, "'1e39' in 'v' is too large for a float"),
                Arguments.of("v 0 0 1e30\n", 1, "'1e30' in 'v' is too large (the limit is 1e18 in magnitude)"),
                Arguments.of("v 0 -2e18 0\n", 1, "'-2e18' in 'v' is too large"),
                Arguments.of("vn 0 0 1e39\n", 1, "'1e39' in 'vn' is too large for a float"),
                Arguments.of("v 0 0 0 w\n", 1, "bad number 'w' in 'v'"),
                Arguments.of("vn 0 1\n", 1, "'vn' needs 3 numbers"),
                Arguments.of("vn 0 x 1\n", 1, "bad number 'x' in 'vn'"),
                Arguments.of("vt\n", 1, "'vt' needs at least 1 number"),
                Arguments.of("vt 0 NaN\n", 1, "coordinate 'NaN' in 'vt' is not finite"),
                Arguments.of(eight + "f 1 2\n", 9, "face with 2 vertices (needs at least 3)"),
                Arguments.of(eight + "f\n", 9, "face with 0 vertices"),
                Arguments.of(eight + "f 0 1 2\n", 9, "vertex index '0' is invalid (OBJ indices start at 1)"),
                Arguments.of(eight + "f 1 2 12\n", 9, "vertex index 12 out of range (8 vertices defined so far)"),
                Arguments.of(eight + "f -9 1 2\n", 9, "vertex index -9 out of range (8 vertices defined so far)"),
                Arguments.of("v 0 0 0\nf 1 1 2\n", 2, "vertex index 2 out of range (1 vertex defined so far)"),
                Arguments.of(eight + "f 99999999999999999999 1 2\n", 9, "vertex index 99999999999999999999 out of range"),
                Arguments.of(eight + "f 2147483648 1 2\n", 9, "vertex index 2147483648 out of range"),
                Arguments.of(eight + "f -2147483649 1 2\n", 9, "vertex index -2147483649 out of range"),
                Arguments.of(eight + "vn 0 0 1\nf 1//2 2//1 3//1\n", 10, "normal index 2 out of range (1 normal defined so far)"),
                Arguments.of(eight + "f 1//1 2//1 3//1\n", 9, "normal index 1 out of range (0 normals defined so far)"),
                Arguments.of(eight + "vt 0 0\nf 1/5 2/1 3/1\n", 10, "texture index 5 out of range (1 texture coordinate defined so far)"),
                Arguments.of(eight + "f 1/2/3/4 2 3\n", 9, "bad face vertex '1/2/3/4': expected v, v/t, v//n or v/t/n"),
                Arguments.of(eight + "f /1 2 3\n", 9, "bad face vertex '/1'"),
                Arguments.of(eight + "f // 2 3\n", 9, "bad face vertex '//'"),
                Arguments.of(eight + "f 1 2 x\n", 9, "bad vertex index 'x' in 'f'"),
                Arguments.of(eight + "f 1 2 -\n", 9, "bad vertex index '-' in 'f'"),
                Arguments.of(eight + "f 1 2 1.5\n", 9, "bad vertex index '1.5' in 'f'"),
                Arguments.of(eight + "f 1/x 2 3\n", 9, "bad texture index 'x' in 'f'"),
                Arguments.of(eight + "f 1//-0 2 3\n", 9, "normal index '-0' is invalid"),
                Arguments.of("# nothing\n" + eight + "g only vertices\n", 0, "no faces: the file holds no geometry"),
                Arguments.of(eight + "f 1 2 2\nf 1 1 1 1\n", 0, "no geometry: all 3 triangles have zero area"));
    }

    @ParameterizedTest
    @MethodSource("malformedFiles")
    void malformedInputIsASceneExceptionAtItsLine(String text, int line, String message) throws Exception {
        Path file = write("t.obj", text);
        assertThatThrownBy(() -> ObjReader.read(file))
                .isInstanceOf(SceneException.class)
                .hasMessageStartingWith(file + (line > 0 ? ":" + line + ": " : ": "))
                .hasMessageContaining(message)
                .satisfies(e -> assertThat(((SceneException) e).line()).isEqualTo(line));
    }

    @Test
    void aFileWithNulBytesIsNotText() throws Exception {
        Path file = dir.resolve("t.obj");
        Files.write(file, new byte[] {'v', ' ', '1', '\n', 0x7f, 'E', 'L', 'F', 0, 0, 1, '\n'});
        assertThatThrownBy(() -> ObjReader.read(file)).isInstanceOf(SceneException.class)
                .hasMessage(file + ":2: not a text OBJ file (NUL byte)");
    }

    @Test
    void aFileThatIsNotUtf8IsReadAsLatin1WithOneNoteNamingTheFirstLineThatIsNot() throws Exception {
        Path file = dir.resolve("t.obj");
        var text = new StringBuilder("# caf\u00e9 is fine\n");
        for (int i = 0; i < 5000; i++) {
            text.append("v 0 0 0\n");
        }
        byte[] good = text.toString().getBytes(StandardCharsets.UTF_8);
        byte[] tail = "g caf\u00e9\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\ng \u00e9\u00e8\n".getBytes(StandardCharsets.ISO_8859_1);
        byte[] bytes = Arrays.copyOf(good, good.length + tail.length);
        System.arraycopy(tail, 0, bytes, good.length, tail.length);
        Files.write(file, bytes);
        ObjModel model = ObjReader.read(file);
        assertThat(model.mesh().triangleCount()).isEqualTo(1);
        assertThat(model.warnings()).containsExactly(file + ": not UTF-8 (first at line 5002): read as Latin-1");
    }

    @Test
    void binaryContentAfterTextIsStillRefusedAtItsLine() throws Exception {
        Path file = dir.resolve("t.obj");
        var text = new StringBuilder();
        for (int i = 0; i < 2000; i++) {
            text.append("v 0 0 0\n");            // beyond the first kilobyte, where the NUL check looks
        }
        byte[] good = text.toString().getBytes(StandardCharsets.US_ASCII);
        byte[] bytes = Arrays.copyOf(good, good.length + 8);
        System.arraycopy(new byte[] {'#', ' ', (byte) 0xE9, '\n', 'x', 0x01, (byte) 0x90, '\n'}, 0, bytes, good.length, 8);
        Files.write(file, bytes);
        assertThatThrownBy(() -> ObjReader.read(file)).isInstanceOf(SceneException.class)
                .hasMessage(file + ":2002: not a text OBJ file (binary content)");
        bytes[good.length + 5] = 0;
        Files.write(file, bytes);
        assertThatThrownBy(() -> ObjReader.read(file)).isInstanceOf(SceneException.class)
                .hasMessage(file + ":2002: not a text OBJ file (NUL byte)");
    }

    @Test
    void usemtlMatchesNewmtlByteForByteWhateverEachFilesEncoding() throws Exception {
        // The MTL is Latin-1 (one 0xE6 byte, from a real loader's regression data); the first OBJ
        // is Latin-1 too, so the names match; the second OBJ is UTF-8, its name has other bytes.
        Files.write(dir.resolve("t.mtl"), "newmtl Terraind\u00e6k\nKd 0.1 0.2 0.3\n".getBytes(StandardCharsets.ISO_8859_1));
        String obj = "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Terraind\u00e6k\nf 1 2 3\n";
        Path latin = dir.resolve("latin.obj");
        Files.write(latin, obj.getBytes(StandardCharsets.ISO_8859_1));
        ObjModel model = ObjReader.read(latin);
        assertThat(model.materials()).hasSize(1);
        assertThat(model.materials().get(0).name()).isEqualTo("Terraind\u00e6k");
        assertThat(model.materials().get(0).kd()).isEqualTo(new Rgb(0.1, 0.2, 0.3));
        assertThat(model.warnings()).containsExactly(
                latin + ": not UTF-8 (first at line 5): read as Latin-1",
                dir.resolve("t.mtl") + ": not UTF-8 (first at line 1): read as Latin-1");

        Path utf8 = dir.resolve("utf8.obj");
        Files.write(utf8, obj.getBytes(StandardCharsets.UTF_8));
        ObjModel other = ObjReader.read(utf8);
        assertThat(other.materials().get(0).kd()).isEqualTo(MtlMaterial.DEFAULT_KD);
        assertThat(other.warnings()).anyMatch(w -> w.contains("unknown material 'Terraind\u00e6k'"));
    }

    @Test
    void aMissingFileIsFileNotFound() {
        Path file = dir.resolve("nope.obj");
        assertThatThrownBy(() -> ObjReader.read(file)).isInstanceOf(SceneException.class)
                .hasMessage(file + ": file not found");
    }

    @Test
    void aDirectoryIsNotAnObjFile() {
        assertThatThrownBy(() -> ObjReader.read(dir)).isInstanceOf(SceneException.class)
                .hasMessageStartingWith(dir + ": ").hasMessageContaining("directory");
    }

    /** Thousands of random edits of valid files: every outcome is a model or a SceneException. */
    @Test
    void mutatedInputGivesAModelOrASceneExceptionNeverAnythingElse() throws Exception {
        write("m.mtl", "newmtl a\nKd 1 0 0\nKe 1 1 1\n");
        List<String> seeds = List.of(
                Files.readString(TestData.cornell("CornellBox-Original.obj")),
                "mtllib m.mtl\n" + SQUARE + "usemtl a\nf 1/1/1 2/2/1 3/1/1\nf -4//-1 -3//-1 -1//-1\nf 1/2 2/1 3/2 4/1\n");
        String alphabet = "0123456789-+./ \t\n\r#\\ve+fnt\u0000\u00e9eEx";
        var random = new SplittableRandom(42);
        Path file = dir.resolve("fuzz.obj");
        for (int round = 0; round < 3000; round++) {
            var text = new StringBuilder(seeds.get(round % seeds.size()));
            int edits = 1 + random.nextInt(8);
            for (int e = 0; e < edits && text.length() > 0; e++) {
                int at = random.nextInt(text.length());
                switch (random.nextInt(4)) {
                    case 0 -> text.deleteCharAt(at);
                    case 1 -> text.insert(at, alphabet.charAt(random.nextInt(alphabet.length())));
                    case 2 -> text.insert(at, random.nextBoolean() ? "99999999999" : "-2147483648");
                    default -> text.setLength(at);
                }
            }
            Files.writeString(file, text);
            assertOnlySceneException(file, text);
        }
        for (int round = 0; round < 300; round++) {
            byte[] bytes = new byte[random.nextInt(200)];
            for (int i = 0; i < bytes.length; i++) {
                bytes[i] = (byte) random.nextInt(256);
            }
            Files.write(file, bytes);
            assertOnlySceneException(file, "random bytes, round " + round);
        }
    }

    // ---- helpers -----------------------------------------------------------------------------

    private Path write(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, text);
        return file;
    }

    private ObjModel read(String text) throws Exception {
        return ObjReader.read(write("t.obj", text));
    }

    private static void assertOnlySceneException(Path file, CharSequence input) {
        try {
            ObjReader.read(file);
        } catch (SceneException expected) {
            assertThat(expected.getMessage()).startsWith(file.toString());
        } catch (RuntimeException | StackOverflowError e) {
            fail("unexpected " + e + " for input:\n" + input, e);
        }
    }

    /** The corner positions of every triangle in order: what a renderer sees, whatever the vertex numbering. */
    private static float[] corners(TriangleMesh mesh) {
        float[] p = mesh.positions();
        int[] idx = mesh.indices();
        float[] out = new float[idx.length * 3];
        for (int i = 0; i < idx.length; i++) {
            System.arraycopy(p, idx[i] * 3, out, i * 3, 3);
        }
        return out;
    }

    private static float x(float[] positions, int vertex) {
        return positions[vertex * 3];
    }

    private static float[] normalOf(float[] normals, int vertex) {
        return Arrays.copyOfRange(normals, vertex * 3, vertex * 3 + 3);
    }

    /** cross(v1 - v0, v2 - v0), DESIGN.md §3 (not normalised). */
    private static double[] geometricNormal(TriangleMesh mesh, int t) {
        float[] c = Arrays.copyOfRange(corners(mesh), t * 9, t * 9 + 9);
        double ax = c[3] - c[0], ay = c[4] - c[1], az = c[5] - c[2];
        double bx = c[6] - c[0], by = c[7] - c[1], bz = c[8] - c[2];
        return new double[] {ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx};
    }

    private static List<String> namesPerTriangle(ObjModel model) {
        List<String> names = new ArrayList<>();
        for (int t = 0; t < model.mesh().triangleCount(); t++) {
            names.add(model.materialOf(t).name());
        }
        return names;
    }

    @Test
    void aMeshTooLargeForTheHeapIsRefusedWhileReadingSayingWhatItNeeds() throws Exception {
        StringBuilder text = new StringBuilder("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n");
        for (int i = 0; i < 3000; i++) {
            text.append(i % 2 == 0 ? "f 1 2 3\n" : "f 2 4 3\n");
        }
        Path file = write("big.obj", text.toString());
        long saved = HeapBudget.limit;
        try {
            HeapBudget.limit = 100_000;                       // room for 666 triangles at 150 bytes each
            assertThatThrownBy(() -> ObjReader.read(file)).isInstanceOf(SceneException.class)
                    .hasMessageStartingWith(file + ":")
                    .hasMessageContaining("the mesh needs at least ")
                    .hasMessageContaining(" KiB (")
                    .hasMessageContaining("triangles so far, at least 150 bytes each), more than the Java heap's 97.7 KiB")
                    .hasMessageEndingWith("give Java more memory (java -Xmx...)")
                    .satisfies(e -> assertThat(((SceneException) e).line()).isBetween(5 + 666, 5 + 3000));
            HeapBudget.limit = 2999 * 150;                    // passes every check while reading, not the one at the end
            assertThatThrownBy(() -> ObjReader.read(file)).isInstanceOf(SceneException.class)
                    .hasMessage(file + ": the mesh needs at least 439.5 KiB (3000 triangles, at least 150 bytes each), more than"
                            + " the Java heap's 439.3 KiB: give Java more memory (java -Xmx...)");
            HeapBudget.limit = 3000 * 150;
            assertThat(ObjReader.read(file).mesh().triangleCount()).isEqualTo(3000);
        } finally {
            HeapBudget.limit = saved;
        }
    }
}
