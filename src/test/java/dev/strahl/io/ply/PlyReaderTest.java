package dev.strahl.io.ply;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.bench.BenchMeshes;
import dev.strahl.io.mesh.MeshFiles;
import dev.strahl.scene.TestScenes;
import dev.strahl.io.SceneLoader;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.image.Image;
import dev.strahl.scene.TriangleMesh;
import dev.strahl.material.Lambert;
import dev.strahl.image.Rgb;
import dev.strahl.render.RenderSettings;
import dev.strahl.io.ply.PlyFiles.Elem;
import dev.strahl.io.ply.PlyFiles.Prop;
import dev.strahl.io.ply.PlyHeader.Format;
import dev.strahl.io.ply.PlyHeader.Type;
import dev.strahl.testing.Renders;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.EnumSource;

class PlyReaderTest {
    @TempDir
    Path dir;

    // ---- the same mesh in every encoding ---------------------------------------------------------

    @ParameterizedTest
    @CsvSource({
        "float,  uchar,  int,    false",
        "double, uchar,  uint,   true",
        "float,  ushort, short,  true",
        "float,  int,    ushort, false",
        "double, char,   int,    false",
        "float,  uint,   uint,   true"})
    void asciiAndBothBinaryEncodingsGiveTheSameMeshAsTheWrittenData(String coordinate, String count, String index,
                                                                     boolean normals) throws Exception {
        List<Elem> elements = PlyFiles.randomMesh(42, 300, 700, Type.of(coordinate), Type.of(count), Type.of(index), normals);
        TriangleMesh expected = expected(elements);
        for (Format f : Format.values()) {
            TriangleMesh mesh = read(PlyFiles.write(f, elements)).mesh();
            assertThat(mesh).as("%s", f).isEqualTo(expected);
        }
        assertThat(expected.triangleCount()).isGreaterThan(700);          // polygons were split
        assertThat(expected.normals() != null).isEqualTo(normals);
    }

    @Test
    void aBufferFullOfDataIsReadAcrossRefills() throws Exception {
        // ~70 000 vertices * 28 bytes: several refills of the 1 MiB buffer, in the middle of records
        List<Elem> elements = PlyFiles.randomMesh(7, 70_000, 50_000, Type.FLOAT, Type.UCHAR, Type.INT, true);
        TriangleMesh expected = expected(elements);
        for (Format f : Format.values()) {
            assertThat(read(PlyFiles.write(f, elements)).mesh()).as("%s", f).isEqualTo(expected);
        }
    }

    @Test
    void polygonsAreFanTriangulatedInTheFilesWinding() throws Exception {
        TriangleMesh m = read(ascii("element vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                + "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                + "0 0 0\n1 0 0\n1 1 0\n0.5 1.5 0\n0 1 0\n5 0 1 2 3 4\n")).mesh();
        assertThat(m.indices()).containsExactly(0, 1, 2, 0, 2, 3, 0, 3, 4);
        assertThat(m.positions()).containsExactly(0, 0, 0, 1, 0, 0, 1, 1, 0, 0.5f, 1.5f, 0, 0, 1, 0);
    }

    @Test
    void vertexIndexIsAcceptedAsTheListNameAndOtherElementsAndPropertiesAreSkipped() throws Exception {
        Elem material = new Elem("material", Prop.scalar("red", Type.UCHAR), Prop.list("name", Type.UCHAR, Type.CHAR))
                .row(new double[] {200}, new double[] {65, 66, 67});
        Elem vertex = new Elem("vertex", Prop.scalar("confidence", Type.DOUBLE), Prop.scalar("z", Type.FLOAT),
                Prop.list("tags", Type.USHORT, Type.SHORT), Prop.scalar("y", Type.FLOAT), Prop.scalar("x", Type.FLOAT),
                Prop.scalar("intensity", Type.UINT))
                .row(new double[] {0.5}, new double[] {3}, new double[] {-1, 2}, new double[] {2}, new double[] {1}, new double[] {7})
                .row(new double[] {0.5}, new double[] {6}, new double[] {}, new double[] {5}, new double[] {4}, new double[] {8})
                .row(new double[] {0.5}, new double[] {9}, new double[] {9}, new double[] {8}, new double[] {7}, new double[] {9});
        Elem face = new Elem("face", Prop.scalar("flags", Type.CHAR), Prop.list("vertex_index", Type.UINT, Type.UINT),
                Prop.list("texcoord", Type.UCHAR, Type.FLOAT))
                .row(new double[] {-3}, new double[] {2, 1, 0}, new double[] {0.25, 0.5, 0.75, 1, 0, 0});
        Elem edge = new Elem("edge", Prop.scalar("vertex1", Type.INT), Prop.scalar("vertex2", Type.INT))
                .row(new double[] {0}, new double[] {1});
        for (Format f : Format.values()) {
            TriangleMesh m = read(PlyFiles.write(f, List.of(material, vertex, face, edge))).mesh();
            assertThat(m.positions()).as("%s", f).containsExactly(1, 2, 3, 4, 5, 6, 7, 8, 9);
            assertThat(m.indices()).as("%s", f).containsExactly(2, 1, 0);
            assertThat(m.normals()).isNull();
        }
    }

    @Test
    void normalsAreNormalisedAndZeroOnesMeanNoNormalWithAWarning() throws Exception {
        PlyReader.PlyModel model = read(ascii("element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                + "property float nx\nproperty float ny\nproperty float nz\n"
                + "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                + "0 0 0 0 0 2\n1 0 0 0 0 0\n0 1 0 3 4 0\n3 0 1 2\n"));
        float[] n = model.mesh().normals();
        assertThat(n[0]).isEqualTo(0);
        assertThat(n[2]).isEqualTo(1);
        assertThat(n[3]).isNaN();
        assertThat(n[6]).isEqualTo(0.6f);
        assertThat(n[7]).isEqualTo(0.8f);
        assertThat(model.warnings()).singleElement().asString().contains("1 vertex normal is zero or not finite");
    }

    @Test
    void facesWithFewerThanThreeVerticesAreSkippedWithAWarning() throws Exception {
        PlyReader.PlyModel model = read(ascii("element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                + "element face 3\nproperty list uchar int vertex_indices\nend_header\n"
                + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n3 0 1 2\n0\n"));
        assertThat(model.mesh().indices()).containsExactly(0, 1, 2);
        assertThat(model.warnings()).singleElement().asString().contains("skipped 2 faces with fewer than 3 vertices");
    }

    @Test
    void crLfHeaderLinesCommentsAnywhereAndTrailingDataWarning() throws Exception {
        String header = "ply\r\nformat binary_big_endian 1.0\r\ncomment one\r\nelement vertex 3\r\nobj_info two\r\n"
                + "property float x\r\nproperty float y\r\nproperty float z\r\nelement face 1\r\n"
                + "property list uchar int vertex_indices\r\ncomment three\r\nend_header\r\n";
        var body = java.nio.ByteBuffer.allocate(3 * 12 + 13 + 5);
        for (float v : new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0}) {
            body.putFloat(v);
        }
        body.put((byte) 3).putInt(0).putInt(1).putInt(2);
        body.put(new byte[] {1, 2, 3, 4, 5});
        byte[] h = header.getBytes(StandardCharsets.US_ASCII);
        byte[] file = new byte[h.length + body.capacity()];
        System.arraycopy(h, 0, file, 0, h.length);
        System.arraycopy(body.array(), 0, file, h.length, body.capacity());
        PlyReader.PlyModel model = read(file);
        assertThat(model.mesh().positions()).containsExactly(0, 0, 0, 1, 0, 0, 0, 1, 0);
        assertThat(model.warnings()).singleElement().asString().contains("5 bytes after the last element ignored");
    }

    @ParameterizedTest
    @EnumSource(Format.class)
    void anEmptyExtraElementAndOneWithoutPropertiesAreFine(Format f) throws Exception {
        List<Elem> mesh = new ArrayList<>(PlyFiles.randomMesh(3, 10, 5, Type.FLOAT, Type.UCHAR, Type.INT, false));
        mesh.add(0, new Elem("nothing", Prop.scalar("a", Type.INT)));
        mesh.add(new Elem("empty"));
        assertThat(read(PlyFiles.write(f, mesh)).mesh()).isEqualTo(expected(mesh.subList(1, 3)));
    }

    // ---- meshes of a scanned model's size and layout -------------------------------------------

    /** 1.1 M triangles in the layout of the subdivided Stanford bunny: binary, float x y z, uchar count + int indices. */
    @Test
    void aMillionTrianglesInBinaryLoadExactly() throws Exception {
        TriangleMesh mesh = BenchMeshes.displacedSphere(303);
        assertThat(mesh.triangleCount()).isGreaterThan(1_000_000);
        ByteBuffer body = ByteBuffer.allocate(12 * mesh.vertexCount() + 13 * mesh.triangleCount()).order(ByteOrder.LITTLE_ENDIAN);
        float[] positions = mesh.positions();          // the accessors return copies: take each once
        int[] indices = mesh.indices();
        for (float p : positions) {
            body.putFloat(p);
        }
        for (int t = 0; t < indices.length; t += 3) {
            body.put((byte) 3).putInt(indices[t]).putInt(indices[t + 1]).putInt(indices[t + 2]);
        }
        String header = "ply\nformat binary_little_endian 1.0\nelement vertex " + mesh.vertexCount()
                + "\nproperty float x\nproperty float y\nproperty float z\nelement face " + mesh.triangleCount()
                + "\nproperty list uchar int vertex_indices\nend_header\n";
        Path file = dir.resolve("big.ply");
        Files.write(file, concat(header.getBytes(StandardCharsets.US_ASCII), body.array()));
        PlyReader.PlyModel model = PlyReader.read(file);
        assertThat(model.mesh().positions()).isEqualTo(positions);
        assertThat(model.mesh().indices()).isEqualTo(indices);
        assertThat(model.warnings()).isEmpty();
    }

    /** 69 k triangles in the layout of the scanned Stanford bunny: ASCII, x y z confidence intensity per vertex. */
    @Test
    void aScanSizedAsciiMeshWithExtraPropertiesLoadsExactly() throws Exception {
        TriangleMesh mesh = BenchMeshes.displacedSphere(76);
        StringBuilder text = new StringBuilder("element vertex " + mesh.vertexCount() + "\nproperty float x\nproperty float y\nproperty float z\n"
                + "property float confidence\nproperty float intensity\nelement face " + mesh.triangleCount()
                + "\nproperty list uchar int vertex_indices\nend_header\n");
        float[] p = mesh.positions();
        for (int v = 0; v < mesh.vertexCount(); v++) {
            text.append(p[3 * v]).append(' ').append(p[3 * v + 1]).append(' ').append(p[3 * v + 2]).append(" 1 0.5\n");
        }
        int[] i = mesh.indices();
        for (int t = 0; t < mesh.triangleCount(); t++) {
            text.append("3 ").append(i[3 * t]).append(' ').append(i[3 * t + 1]).append(' ').append(i[3 * t + 2]).append('\n');
        }
        PlyReader.PlyModel model = read(ascii(text.toString()));
        assertThat(model.mesh().positions()).isEqualTo(p);
        assertThat(model.mesh().indices()).isEqualTo(i);
    }

    @Test
    void sceneLoaderTakesAPlyWithTheGreyDefaultMaterialAndAFramingCamera() throws Exception {
        Path ply = dir.resolve("Mesh.PLY");
        Files.write(ply, PlyFiles.write(Format.BINARY_LITTLE_ENDIAN, PlyFiles.randomMesh(5, 50, 60, Type.FLOAT, Type.UCHAR, Type.INT, false)));
        Scene scene = SceneLoader.load(ply);
        assertThat(scene.materials()).containsExactly(MeshFiles.DEFAULT_MATERIAL);
        assertThat(((Lambert) TestScenes.bsdf(scene.materials().get(0))).albedo().mean()).isEqualTo(Rgb.gray(0.8));
        assertThat(scene.camera().lookFrom().z()).isGreaterThan(1);
        Image img = Renders.render(scene, RenderSettings.defaults().withSize(16, 16).withSamplesPerPixel(2));
        assertThat(img.mean()[1]).isPositive();
    }

    // ---- helpers -----------------------------------------------------------------------------------

    private PlyReader.PlyModel read(byte[] content) throws IOException, SceneException {
        Path file = dir.resolve("mesh.ply");
        Files.write(file, content);
        return PlyReader.read(file);
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] all = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }

    static byte[] ascii(String afterFormat) {
        return ("ply\nformat ascii 1.0\n" + afterFormat).getBytes(StandardCharsets.US_ASCII);
    }

    /** The mesh the written data describe: an independent fan triangulation of the face lists. */
    static TriangleMesh expected(List<Elem> elements) {
        Elem v = elements.get(0), f = elements.get(1);
        int nx = indexOf(v, "nx");
        float[] pos = new float[3 * v.rows.size()];
        float[] nrm = nx >= 0 ? new float[pos.length] : null;
        for (int i = 0; i < v.rows.size(); i++) {
            double[][] row = v.rows.get(i);
            for (int k = 0; k < 3; k++) {
                pos[3 * i + k] = (float) row[indexOf(v, "xyz".substring(k, k + 1))][0];
            }
            if (nrm != null) {
                double a = (float) row[nx][0], b = (float) row[nx + 1][0], c = (float) row[nx + 2][0];
                double len = Math.sqrt(a * a + b * b + c * c);
                nrm[3 * i] = (float) (a / len);
                nrm[3 * i + 1] = (float) (b / len);
                nrm[3 * i + 2] = (float) (c / len);
            }
        }
        List<Integer> tri = new ArrayList<>();
        for (double[][] row : f.rows) {
            double[] idx = row[0];
            for (int k = 1; k + 1 < idx.length; k++) {
                tri.addAll(List.of((int) idx[0], (int) idx[k], (int) idx[k + 1]));
            }
        }
        return new TriangleMesh(pos, tri.stream().mapToInt(Integer::intValue).toArray(), nrm);
    }

    private static int indexOf(Elem e, String name) {
        for (int i = 0; i < e.props.size(); i++) {
            if (e.props.get(i).name().equals(name)) {
                return i;
            }
        }
        return -1;
    }
}
