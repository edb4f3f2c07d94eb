package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import dev.strahl.io.gltf.GltfWriter;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.io.SceneLoader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every bad input of issue 8 through the real command line: the exit code, the one line on
 * stderr naming file and line, no stack trace and no output file; for the inputs that only
 * deserve a warning or a note, the line and the image. {@code $IN} and {@code $OUT} in the
 * arguments and messages stand for the input and output directories.
 */
class BadInputTest {
    static final String CORNELL = Path.of("scenes", "cornell-box.json").toAbsolutePath().toString();
    static final String SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
    static final String LIT = "mtllib lit.mtl\nusemtl lamp\n";
    static final String LIT_MTL = "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\n";

    static final String PLY_HEADER = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            + "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

    @TempDir
    Path in;

    @TempDir
    Path out;

    /** One row: the files to create, the arguments, the exit code and what the line says. */
    record Row(String name, Map<String, byte[]> files, List<String> args, int code, String prefix, List<String> fragments) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Row refused(String name, Map<String, byte[]> files, List<String> args, String... fragments) {
        return new Row(name, files, args, 2, "strahl: ", List.of(fragments));
    }

    static Row warned(String name, Map<String, byte[]> files, List<String> args, String... fragments) {
        return new Row(name, files, args, 0, "strahl: warning: ", List.of(fragments));
    }

    static Row noted(String name, Map<String, byte[]> files, List<String> args, String... fragments) {
        return new Row(name, files, args, 0, "strahl: note: ", List.of(fragments));
    }

    static Map<String, byte[]> files(String... nameContent) {
        Map<String, byte[]> m = new LinkedHashMap<>();
        for (int i = 0; i < nameContent.length; i += 2) {
            m.put(nameContent[i], nameContent[i + 1].getBytes(StandardCharsets.UTF_8));
        }
        return m;
    }

    /** A case the PLY fuzzer found: an 856-byte binary file whose face list length ran the heap out. */
    static Map<String, byte[]> plyFuzzCase() {
        try {
            Map<String, byte[]> m = new LinkedHashMap<>();
            m.put("t.ply", Files.readAllBytes(Path.of("src/test/resources/fuzz/ply/binary-face-list-longer-than-file-1.ply")));
            return m;
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** A lit OBJ and an environment map file of the given bytes. */
    static Map<String, byte[]> envmap(String name, byte[] content) {
        Map<String, byte[]> m = obj(LIT + SQUARE + "f 1 2 3\n");
        m.put(name, content);
        return m;
    }

    /** A scene file s.json whose environment is the map sky.* (any extension), and the given file. */
    static Map<String, byte[]> envmapScene(String name, byte[] content) {
        Map<String, byte[]> m = new LinkedHashMap<>();
        String sky = name.startsWith("other") ? "sky.hdr" : name;
        m.put("s.json", ("{\"shapes\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\"}],"
                + " \"materials\": {\"m\": {\"type\": \"diffuse\"}}, \"environment\": {\"type\": \"envmap\", \"file\": \"" + sky
                + "\"}}").getBytes(StandardCharsets.UTF_8));
        m.put(name, content);
        return m;
    }

    static byte[] fixture(String name) {
        try {
            return Files.readAllBytes(Path.of("src/test/resources", name));
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    static byte[] labelledHdr() {
        return fixture("golden/envcam-labelled.hdr");
    }

    static Map<String, byte[]> obj(String text) {
        return files("t.obj", text, "lit.mtl", LIT_MTL);
    }

    /** A one-triangle GLB as t.glb: its positions accessor counting one vertex too many, or the file cut short. */
    static Map<String, byte[]> glb(boolean accessorTooLong, boolean truncated) {
        GltfWriter w = new GltfWriter();
        w.rootNode(GltfWriter.map("mesh", w.mesh(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, null, null)));
        if (accessorTooLong) {
            @SuppressWarnings("unchecked")
            Map<String, Object> positions = (Map<String, Object>) w.list("accessors").get(0);
            positions.put("count", 4);
        }
        byte[] bytes = w.glb();
        Map<String, byte[]> m = new LinkedHashMap<>();
        m.put("t.glb", truncated ? Arrays.copyOf(bytes, bytes.length - 7) : bytes);
        return m;
    }

    /** A render of $IN/t.obj (or the given scene) to $OUT/a.png, small and quick, with extra options. */
    static List<String> args(String... extra) {
        List<String> a = new ArrayList<>(List.of("render", "$IN/t.obj"));
        List<String> given = Arrays.asList(extra);
        String[][] defaults = {{"-o", "$OUT/a.png"}, {"--width", "8"}, {"--height", "8"}, {"--spp", "1"}};
        for (String[] d : defaults) {
            if (!given.contains(d[0])) {
                a.addAll(List.of(d));
            }
        }
        a.addAll(given);
        return a;
    }

    static List<String> scene(String scene, String... extra) {
        List<String> a = args(extra);
        a.set(1, scene);
        return a;
    }

    static Stream<Row> rows() {
        byte[] elf = {0x7f, 'E', 'L', 'F', 2, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3, 0, 0x3e, 0};
        Map<String, byte[]> binary = new LinkedHashMap<>();
        binary.put("t.obj", elf);
        Map<String, byte[]> latin1 = new LinkedHashMap<>();
        latin1.put("t.obj", ("# caf\u00e9\n" + SQUARE + "# gr\u00fc\u00dfe\nf 1 2 3\n").getBytes(StandardCharsets.ISO_8859_1));
        Map<String, byte[]> binaryLater = new LinkedHashMap<>();
        byte[] text = ("# caf\u00e9\n" + SQUARE + "f 1 2 3\n").getBytes(StandardCharsets.ISO_8859_1);
        byte[] tail = java.util.Arrays.copyOf(text, text.length + elf.length);
        System.arraycopy(elf, 0, tail, text.length, elf.length);
        binaryLater.put("t.obj", tail);
        String sphere = "{ \"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\" }";
        return Stream.of(
            // ---- OBJ ----
            refused("OBJ syntax: too few numbers", obj(SQUARE + "v 1 2\n"), args(), "$IN/t.obj:5: ", "'v' needs 3 numbers (x y z), got 2"),
            refused("OBJ number that does not parse", obj("v 0 0 0\nv 1 2,5 3\n"), args(), "$IN/t.obj:2: ", "bad number '2,5' in 'v'"),
            refused("OBJ NaN coordinate", obj("v NaN 0 0\n"), args(), "$IN/t.obj:1: ", "'NaN' in 'v' is not finite"),
            refused("OBJ infinite coordinate", obj("v 0 0 0\nv 1e400 0 0\n"), args(), "$IN/t.obj:2: ", "'1e400' in 'v' is not finite"),
            refused("OBJ absurd coordinate", obj("v 3e37 0 0\n"), args(), "$IN/t.obj:1: ", "'3e37' in 'v' is too large"),
            refused("OBJ face index out of range", obj(SQUARE + "f 1 2 5\n"), args(), "$IN/t.obj:5: ", "vertex index 5 out of range (4 vertices"),
            refused("OBJ face index zero", obj(SQUARE + "f 0 1 2\n"), args(), "$IN/t.obj:5: ", "vertex index '0' is invalid (OBJ indices start at 1)"),
            refused("OBJ relative index out of range", obj(SQUARE + "f -5 1 2\n"), args(), "$IN/t.obj:5: ", "vertex index -5 out of range"),
            refused("OBJ face with two vertices", obj(SQUARE + "f 1 2\n"), args(), "$IN/t.obj:5: ", "face with 2 vertices (needs at least 3)"),
            refused("OBJ bad face vertex", obj(SQUARE + "f 1/2/3/4 2 3\n"), args(), "$IN/t.obj:5: ", "bad face vertex '1/2/3/4'"),
            refused("OBJ binary file", binary, args(), "$IN/t.obj:1: ", "not a text OBJ file (NUL byte)"),
            warned("OBJ not UTF-8: read as Latin-1", latin1, args(), "$IN/t.obj: ", "not UTF-8 (first at line 1): read as Latin-1"),
            refused("OBJ not UTF-8, then binary", binaryLater, args(), "$IN/t.obj:7: ", "not a text OBJ file (NUL byte)"),
            refused("OBJ without faces", obj(SQUARE + "g empty\n"), args(), "$IN/t.obj: ", "no faces: the file holds no geometry"),
            refused("OBJ empty file", obj(""), args(), "$IN/t.obj: ", "no faces"),
            refused("OBJ of degenerate triangles only", obj(SQUARE + "f 1 2 2\nf 3 3 3\n"), args(), "$IN/t.obj: ",
                    "no geometry: all 2 triangles have zero area"),
            refused("OBJ missing", files(), args(), "$IN/t.obj: ", "file not found"),
            warned("OBJ missing .mtl", obj("mtllib gone.mtl\n" + SQUARE + "f 1 2 3\n"), args(), "$IN/t.obj: ",
                    "material library 'gone.mtl' (line 1) not found", "default grey diffuse"),
            warned("OBJ unknown material", obj(LIT + SQUARE + "usemtl chalk\nf 1 2 3\n"), args(), "$IN/t.obj: ",
                    "unknown material 'chalk' (line 7): using the default grey diffuse"),
            warned("OBJ degenerate triangles", obj(LIT + SQUARE + "f 1 2 3\nf 1 2 2\nf 1 3 1\n"), args(), "$IN/t.obj: ",
                    "skipped 2 degenerate triangles (zero area), the first at line 8"),
            noted("scene without light", files("t.obj", SQUARE + "f 1 2 3\n"), args(), "the scene has no light",
                    "studio sky"),
            // ---- MTL ----
            refused("MTL number that does not parse", files("t.obj", LIT + SQUARE + "f 1 2 3\n", "lit.mtl", "newmtl lamp\nKd 0.5 x 0.5\n"),
                    args(), "$IN/lit.mtl:2: ", "bad number 'x' in 'Kd'"),
            refused("MTL colour with two numbers", files("t.obj", LIT + SQUARE + "f 1 2 3\n", "lit.mtl", "newmtl lamp\n\nKe 1 1\n"),
                    args(), "$IN/lit.mtl:3: ", "'Ke' needs 1 or 3 numbers, got 2"),
            refused("MTL negative colour", files("t.obj", LIT + SQUARE + "f 1 2 3\n", "lit.mtl", "newmtl lamp\nKd -1 0 0\n"),
                    args(), "$IN/lit.mtl:2: ", "must be finite and >= 0"),
            refused("MTL NaN", files("t.obj", LIT + SQUARE + "f 1 2 3\n", "lit.mtl", "newmtl lamp\nNs NaN\n"),
                    args(), "$IN/lit.mtl:2: ", "'Ns' must be a finite number >= 0"),
            refused("MTL key before newmtl", files("t.obj", LIT + SQUARE + "f 1 2 3\n", "lit.mtl", "Kd 1 1 1\nnewmtl lamp\n"),
                    args(), "$IN/lit.mtl:1: ", "'Kd' before any newmtl"),
            refused("MTL illum out of range", files("t.obj", LIT + SQUARE + "f 1 2 3\n", "lit.mtl", "newmtl lamp\nillum 12\n"),
                    args(), "$IN/lit.mtl:2: ", "'illum' must be an integer 0..10"),
            refused("MTL binary file", files("t.obj", LIT + SQUARE + "f 1 2 3\n", "lit.mtl", "newmtl \u0000\u0001\u0002\n"),
                    args(), "$IN/lit.mtl:1: ", "not a text MTL file (NUL byte)"),
            // ---- PLY ----
            refused("PLY without magic", files("t.ply", "plx\nformat ascii 1.0\n"), scene("$IN/t.ply"), "$IN/t.ply:1: ", "not a PLY file"),
            refused("PLY header syntax", files("t.ply", "ply\nformat ascii 1.0\nelement vertex many\n"), scene("$IN/t.ply"),
                    "$IN/t.ply:3: ", "bad count 'many' for element 'vertex'"),
            refused("PLY number that does not parse", files("t.ply", PLY_HEADER + "0 abc 0\n1 0 0\n0 1 0\n3 0 1 2\n"), scene("$IN/t.ply"),
                    "$IN/t.ply:10: ", "bad value 'abc' for property 'y'"),
            refused("PLY NaN coordinate", files("t.ply", PLY_HEADER + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"), scene("$IN/t.ply"),
                    "$IN/t.ply:11: ", "is not a finite float"),
            refused("PLY index out of range", files("t.ply", PLY_HEADER + "0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n"), scene("$IN/t.ply"),
                    "$IN/t.ply:13: ", "vertex index 5 is out of range"),
            refused("PLY truncated", files("t.ply", PLY_HEADER + "0 0 0\n1 0 0\n"), scene("$IN/t.ply"), "$IN/t.ply", "truncated"),
            refused("PLY binary face list beyond the file", plyFuzzCase(), scene("$IN/t.ply"), "$IN/t.ply: element 'face' 0 (byte ",
                    "the file ends here"),
            refused("PLY without triangles", files("t.ply", PLY_HEADER.replace("face 1", "face 2") + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n1 2\n"),
                    scene("$IN/t.ply"), "$IN/t.ply: ", "the mesh has no triangles"),
            // ---- scene file (JSON) ----
            refused("JSON syntax", files("s.json", "{\n  \"shapes\": [\n    " + sphere + ",\n  ]\n}\n"), scene("$IN/s.json"),
                    "$IN/s.json:4: ", "malformed JSON"),
            refused("JSON unknown key", files("s.json", "{\n \"materials\": { \"m\": { \"type\": \"diffuse\" } },\n \"shapes\": [ " + sphere
                    + " ],\n \"lamps\": 1\n}\n"), scene("$IN/s.json"), "$IN/s.json:4: ", "unknown key 'lamps'"),
            refused("JSON wrong type", files("s.json", "{\n \"materials\": { \"m\": { \"type\": \"diffuse\", \"albedo\": \"red\" } },\n \"shapes\": [ "
                    + sphere + " ]\n}\n"), scene("$IN/s.json"), "$IN/s.json:2: ", "albedo"),
            refused("JSON infinite number", files("s.json", "{\n \"materials\": { \"m\": { \"type\": \"diffuse\" } },\n \"shapes\": [\n  "
                    + sphere.replace("\"radius\": 1", "\"radius\": 1e999") + " ]\n}\n"), scene("$IN/s.json"), "$IN/s.json:4: ", "radius"),
            refused("JSON photons out of range", files("s.json", "{\n \"integrator\": { \"type\": \"photon\", \"photons\": 0 },\n"
                    + " \"materials\": { \"m\": { \"type\": \"diffuse\" } },\n \"shapes\": [ " + sphere + " ]\n}\n"), scene("$IN/s.json"),
                    "$IN/s.json:2: ", "'integrator.photons' must be in [1, 10000000], got 0"),
            refused("JSON without geometry", files("s.json", "{\n \"shapes\": [ ]\n}\n"), scene("$IN/s.json"), "$IN/s.json:2: ", "no geometry"),
            refused("JSON naming a broken OBJ", files("s.json", "{ \"shapes\": [ { \"type\": \"mesh\", \"file\": \"t.obj\" } ] }\n",
                    "t.obj", SQUARE + "f 1 2 9\n"), scene("$IN/s.json"), "$IN/t.obj:5: ", "vertex index 9 out of range"),
            refused("JSON transform moving a mesh beyond floats", files("s.json", "{ \"shapes\": [ { \"type\": \"mesh\", \"file\": \"t.obj\",\n"
                    + "  \"transform\": [ { \"scale\": 1e39 } ] } ] }\n", "t.obj", SQUARE + "f 1 2 3\n"), scene("$IN/s.json"), "$IN/t.obj: ",
                    "the transform moves vertex 2 (1.0, 0.0, 0.0) to (1.00e+39, 0.00, 0.00), beyond the range of float coordinates"),
            refused("JSON transform moving triangles beyond floats", files("s.json", "{ \"materials\": { \"m\": { \"type\": \"diffuse\" } },\n"
                    + " \"shapes\": [ { \"type\": \"triangles\", \"positions\": [0,0,0, 1,0,0, 0,1,0], \"indices\": [0,1,2], \"material\": \"m\",\n"
                    + "  \"transform\": [ { \"translate\": [0, 0, 1e300] } ] } ] }\n"), scene("$IN/s.json"), "$IN/s.json:3: ",
                    "'shapes[].transform': the transform moves vertex 1"),
            refused("JSON transform steps that overflow", files("s.json", "{ \"materials\": { \"m\": { \"type\": \"diffuse\" } },\n"
                    + " \"shapes\": [ { \"type\": \"triangles\", \"positions\": [0,0,0, 1,0,0, 0,1,0], \"indices\": [0,1,2], \"material\": \"m\",\n"
                    + "  \"transform\": [ { \"scale\": 1e200 }, { \"scale\": 1e200 } ] } ] }\n"), scene("$IN/s.json"), "$IN/s.json:3: ",
                    "bad 'shapes[].transform[].scale': the steps multiply to a matrix beyond the range of numbers"),
            // ---- glTF ----
            refused("glTF truncated GLB", glb(false, true), scene("$IN/t.glb"), "$IN/t.glb: ", "truncated GLB: the header says"),
            refused("glTF accessor past its buffer view", glb(true, false), scene("$IN/t.glb"),
                    "$IN/t.glb: accessors[0]: byteOffset + count x stride past the end of bufferView 0"),
            refused("glTF required extension", files("t.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"extensionsRequired\": [\"KHR_draco_mesh_compression\"]}"),
                    scene("$IN/t.gltf"), "$IN/t.gltf: extensionsRequired[0]: required extension KHR_draco_mesh_compression is not supported"),
            refused("unknown scene format", files("t.txt", SQUARE), scene("$IN/t.txt"), "$IN/t.txt: ", "unknown scene format"),
            // ---- options ----
            refused("unknown option", files(), scene(CORNELL, "--frobnicate"), "Unknown option: '--frobnicate'"),
            refused("misspelt option", files(), scene(CORNELL, "--sp", "4"), "'--sp'", "did you mean"),
            refused("width zero", files(), scene(CORNELL, "--width", "0"), "image size must be positive, got 0x8"),
            refused("height negative", files(), scene(CORNELL, "--height", "-1"), "image size must be positive, got 8x-1"),
            refused("width absurd", files(), scene(CORNELL, "--width", "1000000"), "larger than 32768 pixels on a side"),
            refused("film larger than the heap", files(), scene(CORNELL, "--width", "32000", "--height", "32000"),
                    "a 32000x32000 image needs ", "GiB for its film and image buffers", "java -Xmx"),
            refused("spp zero", files(), scene(CORNELL, "--spp", "0"), "samples per pixel must be positive, got 0"),
            refused("spp negative", files(), scene(CORNELL, "--spp", "-4"), "samples per pixel must be positive, got -4"),
            refused("spp not a number", files(), scene(CORNELL, "--spp", "lots"), "--spp", "'lots'"),
            refused("time limit not a duration", files(), scene(CORNELL, "--time-limit", "soon"), "'soon' is not a duration"),
            refused("checkpoint interval zero", files(), scene(CORNELL, "--checkpoint-interval", "0s"), "must be a positive duration"),
            refused("output directory missing", files(), scene(CORNELL, "-o", "$OUT/no/a.png"), "output directory does not exist: $OUT/no"),
            refused("output is a directory", files("d.png/x", ""), scene(CORNELL, "-o", "$IN/d.png"), "output $IN/d.png is a directory"),
            refused("output extension unknown", files(), scene(CORNELL, "-o", "$OUT/a.jpg"), "unknown image format of $OUT/a.jpg: use .png, .pfm or .exr"),
            refused("output without extension", files(), scene(CORNELL, "-o", "$OUT/a"), "unknown image format of $OUT/a"),
            // ---- environment maps ----
            refused("envmap truncated HDR", envmap("sky.hdr", Arrays.copyOf(labelledHdr(), 3000)), args("--envmap", "$IN/sky.hdr"),
                    "$IN/sky.hdr: ", "the file ends inside the scanline: it is truncated"),
            refused("envmap HDR whose header promises more than the file holds", envmap("sky.hdr",
                    "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 60000 +X 60000\n".getBytes(StandardCharsets.US_ASCII)),
                    args("--envmap", "$IN/sky.hdr"), "$IN/sky.hdr:4: ", "the file is truncated"),
            refused("envmap EXR of an unsupported compression", envmap("sky.exr", fixture("exr/refused-b44.exr")),
                    args("--envmap", "$IN/sky.exr"), "$IN/sky.exr: ", "EXR compression B44 is not supported"),
            refused("envmap that is no EXR", envmap("sky.exr", "hello".getBytes(StandardCharsets.US_ASCII)),
                    args("--envmap", "$IN/sky.exr"), "$IN/sky.exr: ", "not an OpenEXR file"),
            refused("envmap missing", obj(LIT + SQUARE + "f 1 2 3\n"), args("--envmap", "$IN/none.hdr"), "$IN/none.hdr: ",
                    "environment map not found"),
            refused("envmap of an image format strahl does not read", envmap("sky.png", new byte[8]), args("--envmap", "$IN/sky.png"),
                    "$IN/sky.png: ", "not an environment map format"),
            refused("scene file whose envmap is truncated", envmapScene("sky.exr", Arrays.copyOf(fixture("exr/rgba-half-zip.exr"), 400)),
                    scene("$IN/s.json"), "$IN/sky.exr: ", "the file ends"),
            refused("scene file whose envmap is missing", envmapScene("other.hdr", labelledHdr()), scene("$IN/s.json"), "$IN/s.json:1: ",
                    "environment map not found"),
            refused("negative aperture", files(), scene(CORNELL, "--aperture", "-1"), "--aperture: the lens radius must be finite and >= 0"),
            refused("zero focus distance", files(), scene(CORNELL, "--focus-distance", "0"), "--focus-distance: the distance must be"),
            // ---- checkpoints ----
            refused("resume from a missing checkpoint", files(), scene(CORNELL, "--resume", "$IN/none.ck"), "$IN/none.ck: checkpoint not found"),
            refused("resume from a file that is no checkpoint", files("x.ck", "hello, world\n"), scene(CORNELL, "--resume", "$IN/x.ck"),
                    "$IN/x.ck: not a strahl checkpoint"),
            refused("checkpoint directory missing", files(), scene(CORNELL, "--checkpoint", "$OUT/no/a.ck"), "checkpoint directory does not exist"),
            refused("checkpoint is the output", files(), scene(CORNELL, "--checkpoint", "$OUT/a.png"), "must be different files"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("rows")
    void badInput(Row row) throws IOException {
        for (var f : row.files().entrySet()) {
            Path p = in.resolve(f.getKey());
            Files.createDirectories(p.getParent());
            Files.write(p, f.getValue());
        }
        RenderCommandTest.Run r = RenderCommandTest.strahl(row.args().stream().map(this::expand).toArray(String[]::new));
        assertThat(r.code()).as("exit code; stderr: %s", r.err()).isEqualTo(row.code());
        assertThat(r.err()).as("no stack trace").doesNotContain("\tat ").doesNotContain("Exception");
        assertThat(r.out()).isEmpty();
        List<String> lines = r.errLines().stream().filter(l -> l.startsWith(row.prefix())).toList();
        assertThat(lines).as("stderr: %s", r.err()).hasSize(1);
        for (String fragment : row.fragments()) {
            assertThat(lines.get(0)).contains(expand(fragment));
        }
        if (row.code() == 0) {
            assertThat(out.resolve("a.png")).isRegularFile();
        } else {
            assertThat(r.errLines()).as("one line").hasSize(1);
            try (Stream<Path> written = Files.list(out)) {
                assertThat(written).as("files written").isEmpty();
            }
        }
    }

    /** A checkpoint of other settings or another scene: refused with the reason, nothing written. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("mismatches")
    void checkpointOfOtherSettingsOrSceneIsRefused(String name, String sceneFile, List<String> options, String fragment) throws Exception {
        Path ck = in.resolve("a.ck");
        RenderSettings settings = RenderSettings.defaults().withSize(8, 8).withSamplesPerPixel(1);
        try (RenderJob job = RenderJob.start(SceneLoader.load(Path.of(CORNELL)), settings)) {
            job.awaitStats();
            job.saveCheckpoint(ck);
        }
        List<String> extra = new ArrayList<>(List.of("--resume", ck.toString()));
        extra.addAll(options);
        List<String> a = scene(sceneFile, extra.toArray(String[]::new));
        RenderCommandTest.Run r = RenderCommandTest.strahl(a.stream().map(this::expand).toArray(String[]::new));
        assertThat(r.code()).as(r.err()).isEqualTo(2);
        assertThat(r.errLines()).singleElement().asString().startsWith("strahl: " + ck + ": ").contains(fragment);
        try (Stream<Path> written = Files.list(out)) {
            assertThat(written).isEmpty();
        }
    }

    static Stream<org.junit.jupiter.params.provider.Arguments> mismatches() {
        return Stream.of(
            org.junit.jupiter.params.provider.Arguments.of("seed", CORNELL, List.of("--seed", "3"), "seed 0 in the checkpoint, 3 now"),
            org.junit.jupiter.params.provider.Arguments.of("size", CORNELL, List.of("--width", "9"), "width 8 in the checkpoint, 9 now"),
            org.junit.jupiter.params.provider.Arguments.of("camera", CORNELL, List.of("--fov", "41"), "another scene"),
            org.junit.jupiter.params.provider.Arguments.of("scene", Path.of("scenes", "cornell-mirror.json").toString(), List.of(), "another scene"));
    }

    @org.junit.jupiter.api.Test
    void unwritableOutputDirectory() throws IOException {
        Path proc = Path.of("/proc");
        assumeTrue(Files.isDirectory(proc.resolve("self")), "Linux /proc");
        RenderCommandTest.Run r = RenderCommandTest.strahl(scene(CORNELL, "-o", "/proc/strahl-test.png").stream().map(this::expand)
                .toArray(String[]::new));
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.errLines()).singleElement().asString().isEqualTo("strahl: output directory is not writable: /proc");
    }

    @org.junit.jupiter.api.Test
    void debugShowsTheStackTraceAfterTheOneLine() {
        RenderCommandTest.Run r = RenderCommandTest.strahl(expand(scene("$IN/none.obj", "--debug")).toArray(String[]::new));
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.errLines().get(0)).isEqualTo("strahl: " + in.resolve("none.obj") + ": file not found");
        assertThat(r.err()).contains("SceneException").contains("\tat ");
    }

    private List<String> expand(List<String> args) {
        return args.stream().map(this::expand).toList();
    }

    private String expand(String s) {
        return s.replace("$IN", in.toString()).replace("$OUT", out.toString());
    }
}
