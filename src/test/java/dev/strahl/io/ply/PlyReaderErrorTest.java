package dev.strahl.io.ply;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import dev.strahl.scene.SceneException;
import dev.strahl.io.ply.PlyFiles.Elem;
import dev.strahl.io.ply.PlyFiles.Prop;
import dev.strahl.io.ply.PlyHeader.Format;
import dev.strahl.io.ply.PlyHeader.Type;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** Every way a PLY file is refused, with the message a user sees: file, line or element and index, and the cause. */
class PlyReaderErrorTest {
    /** Three vertices and one face: header lines 1-9, vertices on lines 10-12, the face on line 13. */
    private static final String HEADER = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            + "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    private static final String VERTICES = "0 0 0\n1 0 0\n0 1 0\n";

    @TempDir
    Path dir;

    static Stream<Arguments> badFiles() {
        return Stream.of(
            // the header
            bad("empty file", "", ":1: not a PLY file (empty)"),
            bad("wrong magic", "plx\nformat ascii 1.0\n", ":1: not a PLY file (the first line must be 'ply')"),
            bad("no end_header", "ply\nformat ascii 1.0\nelement vertex 3\n", ":4: the header has no 'end_header' line"),
            bad("unknown keyword", "ply\nformat ascii 1.0\nvertices 3\nend_header\n", ":3: unknown PLY header keyword 'vertices'"),
            bad("unknown format", "ply\nformat binary 1.0\n", ":2: unknown PLY format 'binary'"),
            bad("unknown version", "ply\nformat ascii 2.0\n", ":2: unsupported PLY version '2.0' (expected 1.0)"),
            bad("short format line", "ply\nformat ascii\n", ":2: expected 'format ascii|binary_little_endian|binary_big_endian 1.0'"),
            bad("second format", "ply\nformat ascii 1.0\nformat ascii 1.0\n", ":3: a second 'format' line"),
            bad("no format", "ply\n" + HEADER + VERTICES, ":8: the header has no 'format' line"),
            bad("short element line", ascii("element vertex\n"), ":3: expected 'element NAME COUNT'"),
            bad("negative count", ascii("element vertex -3\n"), ":3: bad count '-3' for element 'vertex'"),
            bad("word as count", ascii("element vertex many\n"), ":3: bad count 'many' for element 'vertex'"),
            bad("element twice", ascii("element vertex 1\nelement vertex 1\n"), ":4: element 'vertex' is declared twice"),
            bad("property first", ascii("property float x\n"), ":3: 'property' before any 'element'"),
            bad("unknown type", ascii("element vertex 1\nproperty float128 x\n"), ":4: unknown PLY type 'float128'"),
            bad("float list count", ascii("element face 1\nproperty list float int vertex_indices\n"),
                    ":4: the count type of list 'vertex_indices' must be an integer type, got float"),
            bad("short list line", ascii("element face 1\nproperty list uchar vertex_indices\n"),
                    ":4: expected 'property list COUNT_TYPE ITEM_TYPE NAME'"),
            bad("short property line", ascii("element vertex 1\nproperty float\n"), ":4: expected 'property TYPE NAME'"),
            bad("property twice", ascii("element vertex 1\nproperty float x\nproperty double x\n"),
                    ":5: property 'x' of element 'vertex' is declared twice"),
            bad("words after end_header", ascii("end_header now\n"), ":3: unexpected words after 'end_header'"),
            bad("empty header line", ascii("\nend_header\n"), ":3: empty line in the PLY header"),
            bad("header longer than the buffer", ascii("comment " + "x".repeat(PlyReader.BUFFER) + "\nend_header\n"),
                    "no 'end_header' line within its first 1024 KiB"),
            // what the mesh needs
            bad("no vertex element", ascii("element face 0\nproperty list uchar int vertex_indices\nend_header\n"),
                    ":5: the header declares no 'vertex' element"),
            bad("no face element", ascii("element vertex 0\nproperty float x\nend_header\n"),
                    ":5: the header declares no 'face' element (a point cloud cannot be rendered)"),
            bad("no z", ascii("element vertex 0\nproperty float x\nproperty float y\nelement face 0\n"
                    + "property list uchar int vertex_indices\nend_header\n"), ":3: element 'vertex' has no property 'z'"),
            bad("x as a list", ascii("element vertex 0\nproperty list uchar float x\nproperty float y\nproperty float z\n"
                    + "element face 0\nproperty list uchar int vertex_indices\nend_header\n"),
                    ":4: property 'x' of element 'vertex' must be a scalar, not a list"),
            bad("two of three normals", ascii(HEADER.replace("property float z\n", "property float z\nproperty float nx\nproperty float ny\n")),
                    ":3: element 'vertex' has only some of the normal properties nx, ny, nz"),
            bad("no index list", ascii(HEADER.replace("vertex_indices", "indices")),
                    ":7: element 'face' has no list property 'vertex_indices' (or 'vertex_index')"),
            bad("scalar index property", ascii(HEADER.replace("list uchar int vertex_indices", "int vertex_indices")),
                    ":8: property 'vertex_indices' of element 'face' must be a list"),
            bad("float indices", ascii(HEADER.replace("uchar int", "uchar float")),
                    ":8: list 'vertex_indices' must hold an integer type, got float"),
            bad("too many vertices", ascii(HEADER.replace("vertex 3", "vertex 3000000000")), ":3: too many vertices for one mesh: 3000000000"),
            bad("too many faces", ascii(HEADER.replace("face 1", "face 3000000000")), ":7: too many faces for one mesh: 3000000000"),
            bad("header promises more than the file holds", ascii(HEADER.replace("vertex 3", "vertex 300")) + VERTICES + "3 0 1 2\n",
                    ":9: the file is truncated: its header declares elements that need at least 1802 bytes of text, but only 26 follow"),
            // an ASCII body
            bad("index out of range", ascii(HEADER) + VERTICES + "3 0 1 5\n",
                    ":13: element 'face' 0: vertex index 5 is out of range (the file has 3 vertices)"),
            bad("negative index", ascii(HEADER) + VERTICES + "3 0 -1 2\n",
                    ":13: element 'face' 0: vertex index -1 is out of range (the file has 3 vertices)"),
            bad("NaN coordinate", ascii(HEADER) + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n",
                    ":11: element 'vertex' 1: position (NaN, 0.0, 0.0) is not a finite float"),
            bad("infinite coordinate", ascii(HEADER) + "0 0 0\n1 -inf 0\n0 1 0\n3 0 1 2\n",
                    ":11: element 'vertex' 1: position (1.0, -Infinity, 0.0) is not a finite float"),
            bad("coordinate beyond float range", ascii(HEADER.replace("float z", "double z")) + "0 0 1e300\n1 0 0\n0 1 0\n3 0 1 2\n",
                    ":10: element 'vertex' 0: position (0.0, 0.0, 1.0E300) is not a finite float"),
            bad("word as number", ascii(HEADER) + "0 abc 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                    ":10: element 'vertex' 0: bad value 'abc' for property 'y' of type float"),
            bad("fraction as index", ascii(HEADER) + VERTICES + "3 0 1 2.5\n",
                    ":13: element 'face' 0: bad value '2.5' for property 'vertex_indices' of type int"),
            bad("count beyond its type", ascii(HEADER) + VERTICES + "300 0 1 2\n",
                    ":13: element 'face' 0: value 300 of property 'vertex_indices' does not fit its type uchar"),
            bad("negative list length", ascii(HEADER.replace("list uchar", "list char")) + VERTICES + "-1 0 1 2\n",
                    ":13: element 'face' 0: list 'vertex_indices' has a negative length -1"),
            bad("too few values on a line", ascii(HEADER) + "0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                    ":10: element 'vertex' 0: the line ends before property 'z'"),
            bad("too many values on a line", ascii(HEADER) + "0 0 0 7\n1 0 0\n0 1 0\n3 0 1 2\n",
                    ":10: element 'vertex' 0: more values on the line than the header declares"),
            bad("too many values on the last line", ascii(HEADER) + VERTICES + "3 0 1 2 9\n",
                    ":13: element 'face' 0: more values on the line than the header declares"),
            bad("body ends early", ascii(HEADER) + "0.0000 0 0\n1 0 0\n0 1 0\n",
                    ":13: element 'face' 0: the file ends here: it is truncated or its header promises more than it holds"),
            bad("endless value", ascii(HEADER) + "0." + "1".repeat(300) + " 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                    ":10: a value longer than 256 characters"),
            bad("only short faces", ascii(HEADER.replace("face 1", "face 2")) + VERTICES + "2 0 1\n1 2\n",
                    "mesh.ply: the mesh has no triangles"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badFiles")
    void badFileIsOneErrorNamingFileAndPlace(String name, byte[] content, String fragment) throws Exception {
        assertThat(error(content)).contains(fragment).doesNotContain("\n").startsWith(dir.resolve("mesh.ply").toString());
    }

    // ---- binary bodies: the element, its index and the byte offset ---------------------------------

    private static final int HEADER_BYTES = ("ply\nformat binary_little_endian 1.0\n" + HEADER).length();

    @Test
    void binaryIndexOutOfRangeNamesTheFaceAndTheByteOfTheIndex() throws Exception {
        ByteBuffer b = binary(0, 0, 0, 1, 0, 0, 0, 1, 0).put((byte) 3).putInt(0).putInt(1).putInt(7);
        assertThat(error(file(b))).endsWith("mesh.ply: element 'face' 0 (byte " + (HEADER_BYTES + 36 + 1 + 8)
                + "): vertex index 7 is out of range (the file has 3 vertices)");
    }

    @Test
    void binaryNaNNamesTheVertex() throws Exception {
        ByteBuffer b = binary(0, 0, 0, Float.NaN, 0, 0, 0, 1, 0).put((byte) 3).putInt(0).putInt(1).putInt(2);
        assertThat(error(file(b))).endsWith("mesh.ply: element 'vertex' 1 (byte " + (HEADER_BYTES + 12)
                + "): position (NaN, 0.0, 0.0) is not a finite float");
    }

    @Test
    void binaryNegativeListLengthIsRefused() throws Exception {
        byte[] f = file(binary(0, 0, 0, 1, 0, 0, 0, 1, 0).put((byte) -1).putInt(0).putInt(1).putInt(2));
        String header = "ply\nformat binary_little_endian 1.0\n" + HEADER;
        System.arraycopy(header.replace("list uchar", "list char ").getBytes(StandardCharsets.US_ASCII), 0, f, 0, header.length());
        assertThat(error(f)).contains("element 'face' 0 (byte ").endsWith("): list 'vertex_indices' has a negative length -1");
    }

    @Test
    void binaryFileThatEndsInsideAFaceIsTruncated() throws Exception {
        ByteBuffer b = binary(0, 0, 0, 1, 0, 0, 0, 1, 0).put((byte) 200).putInt(0).putInt(1).putInt(2);
        assertThat(error(file(b))).contains("mesh.ply: element 'face' 0 (byte ")
                .endsWith("): the file ends here: it is truncated or its header promises more than it holds");
    }

    @Test
    void binaryFileThatEndsInsideASkippedElementIsTruncated() throws Exception {
        List<Elem> mesh = new java.util.ArrayList<>(PlyFiles.randomMesh(1, 3, 1, Type.FLOAT, Type.UCHAR, Type.INT, false));
        mesh.add(new Elem("extra", Prop.list("data", Type.UINT, Type.DOUBLE)).row(new double[40]));
        byte[] full = PlyFiles.write(Format.BINARY_BIG_ENDIAN, mesh);
        byte[] cut = java.util.Arrays.copyOf(full, full.length - 8);
        assertThat(error(cut)).contains("mesh.ply: element 'extra' 0 (byte ").contains("the file ends here");
    }

    @Test
    void aMissingFileAndADirectoryAreNamedAsSuch() {
        SceneException missing = catchThrowableOfType(SceneException.class, () -> PlyReader.read(dir.resolve("none.ply")));
        assertThat(missing).hasMessage(dir.resolve("none.ply") + ": file not found");
        SceneException directory = catchThrowableOfType(SceneException.class, () -> PlyReader.read(dir));
        assertThat(directory).hasMessage(dir + ": is a directory, not a PLY file");
    }

    // ---- helpers -----------------------------------------------------------------------------------

    private static Arguments bad(String name, String content, String fragment) {
        return Arguments.of(name, content.getBytes(StandardCharsets.ISO_8859_1), fragment);
    }

    private static String ascii(String afterFormat) {
        return "ply\nformat ascii 1.0\n" + afterFormat;
    }

    private static ByteBuffer binary(float... positions) {
        ByteBuffer b = ByteBuffer.allocate(4096).order(ByteOrder.LITTLE_ENDIAN);
        for (float p : positions) {
            b.putFloat(p);
        }
        return b;
    }

    private static byte[] file(ByteBuffer body) {
        byte[] h = ("ply\nformat binary_little_endian 1.0\n" + HEADER).getBytes(StandardCharsets.US_ASCII);
        byte[] out = new byte[h.length + body.position()];
        System.arraycopy(h, 0, out, 0, h.length);
        System.arraycopy(body.array(), 0, out, h.length, body.position());
        return out;
    }

    private String error(byte[] content) throws Exception {
        Path file = dir.resolve("mesh.ply");
        Files.write(file, content);
        SceneException e = catchThrowableOfType(SceneException.class, () -> PlyReader.read(file));
        assertThat(e).as("an error for %s", new String(content, 0, Math.min(content.length, 200), StandardCharsets.ISO_8859_1)).isNotNull();
        return e.getMessage();
    }
}
