package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.cli.HostileGltf.Asset;
import dev.strahl.cli.HostileGltf.ImageUse;
import dev.strahl.cli.HostileImages.Hostile;
import dev.strahl.medium.VolFiles;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Issue 32: truncated, corrupt, unsupported and bomb files of every image format and of glTF/GLB,
 * through the real command line, each used where such a file can be named: an image as
 * {@code --envmap}, as a scene file's environment, as an MTL {@code map_Kd}, as a scene file's
 * texture and as a glTF texture (a file beside it, a data: URI, a GLB buffer view); an asset as the
 * scene; a Mitsuba {@code .vol} grid as a scene file's medium (issue 29). Every one must give exit code 2 and one line on stderr that is printable ASCII, names the
 * file (the asset, for an embedded image) and says what its case says (the element, the size a bomb
 * claims), with no stack trace, no output file and within 60 s. A missing texture, wherever it is
 * named, is a warning instead, and the image is rendered.
 */
class HostileFilesTest {
    static final String TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nmtllib m.mtl\nusemtl m\nf 1/1 2/2 3/3\n";
    static final String SPHERE = "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\"}";

    @TempDir
    Path in;

    @TempDir
    Path out;

    /** How a scene names an image file. */
    enum Use { ENVMAP, SCENE_ENVMAP, MAP_KD, SCENE_TEXTURE, GLTF_FILE, GLTF_DATA_URI, GLB_VIEW }

    static Stream<Arguments> images() {
        List<Arguments> cases = new ArrayList<>();
        for (Hostile h : HostileImages.all()) {
            boolean environment = List.of("exr", "hdr", "pfm").contains(h.format());
            List<Use> uses = environment ? List.of(Use.ENVMAP, Use.SCENE_ENVMAP, Use.MAP_KD, Use.SCENE_TEXTURE)
                    : List.of(Use.MAP_KD, Use.SCENE_TEXTURE, Use.GLTF_FILE, Use.GLTF_DATA_URI, Use.GLB_VIEW, Use.ENVMAP);
            for (Use use : uses) {
                cases.add(Arguments.of(h, use));
            }
        }
        return cases.stream();
    }

    @ParameterizedTest(name = "{0} as {1}")
    @MethodSource("images")
    void aHostileImageIsOneLineNamingIt(Hostile h, Use use) throws IOException {
        String name = h.name();
        Path image = in.resolve(name);
        List<String> args = new ArrayList<>();
        Path named = image;                  // the file the line must name
        // a PNG as an environment map, an EXR as a texture: refused for its format, whatever its content
        boolean wrongKind = (use == Use.MAP_KD || use == Use.SCENE_TEXTURE) && List.of("exr", "hdr", "pfm").contains(h.format())
                || use == Use.ENVMAP && !List.of("exr", "hdr", "pfm").contains(h.format());
        switch (use) {
            case ENVMAP -> {
                write(image, h.bytes());
                litTriangle("newmtl m\nKd 0.5 0.5 0.5\nKe 1 1 1\n");
                args.addAll(List.of(in.resolve("t.obj").toString(), "--envmap", image.toString()));
            }
            case SCENE_ENVMAP -> {
                write(image, h.bytes());
                write(in.resolve("s.json"), "{\"shapes\": [" + SPHERE + "], \"materials\": {\"m\": {\"type\": \"diffuse\"}},"
                        + " \"environment\": {\"type\": \"envmap\", \"file\": \"" + name + "\"}}");
                args.add(in.resolve("s.json").toString());
            }
            case MAP_KD -> {
                write(image, h.bytes());
                litTriangle("newmtl m\nKd 0.5 0.5 0.5\nKe 1 1 1\nmap_Kd " + name + "\n");
                args.add(in.resolve("t.obj").toString());
            }
            case SCENE_TEXTURE -> {
                write(image, h.bytes());
                write(in.resolve("s.json"), "{\"shapes\": [" + SPHERE + "], \"materials\": {\"m\": {\"type\": \"diffuse\", \"albedo\":"
                        + " {\"texture\": \"" + name + "\"}}}}");
                args.add(in.resolve("s.json").toString());
            }
            default -> {
                ImageUse how = use == Use.GLTF_FILE ? ImageUse.FILE : use == Use.GLTF_DATA_URI ? ImageUse.DATA_URI : ImageUse.GLB_VIEW;
                Map<String, byte[]> files = HostileGltf.textured(name, h.bytes(), how);
                for (var f : files.entrySet()) {
                    write(in.resolve(f.getKey()), f.getValue());
                }
                Path asset = in.resolve(files.keySet().iterator().next());
                args.add(asset.toString());
                if (how != ImageUse.FILE) {
                    named = asset;
                }
            }
        }
        List<String> fragments = new ArrayList<>(wrongKind ? List.of() : h.fragments());
        if (use == Use.GLTF_DATA_URI || use == Use.GLB_VIEW) {
            fragments.add("images[0]");
        }
        assertRefused(h + " as " + use, args, named, fragments);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("dev.strahl.cli.HostileGltf#all")
    void aHostileGltfAssetIsOneLineNamingIt(Asset a) throws IOException {
        for (var f : a.files().entrySet()) {
            write(in.resolve(f.getKey()), f.getValue());
        }
        Path asset = in.resolve(a.main());
        assertRefused(a.name(), List.of(asset.toString()), asset, a.fragments());
    }

    /** Hostile {@code .vol} density grids: each {name, bytes, what the line says}. */
    static Stream<Arguments> grids() {
        float[] box = {0, 0, 0, 1, 1, 1};
        byte[] escape = VolFiles.bytes(2, 2, 2, box, new float[8]);
        escape[0] = 0x1b;
        escape[1] = '[';
        escape[2] = '3';
        byte[] bomb = VolFiles.bytes(1, 1, 1, box, new float[0]);
        ByteBuffer.wrap(bomb).order(ByteOrder.LITTLE_ENDIAN).putInt(8, 1290).putInt(12, 1290).putInt(16, 1290);
        byte[] huge = VolFiles.bytes(1, 1, 1, box, new float[0]);
        ByteBuffer.wrap(huge).order(ByteOrder.LITTLE_ENDIAN).putInt(8, 0x7fffffff).putInt(12, 0x7fffffff).putInt(16, 0x7fffffff);
        byte[] rgb = VolFiles.bytes(2, 2, 2, box, new float[24]);
        ByteBuffer.wrap(rgb).order(ByteOrder.LITTLE_ENDIAN).putInt(20, 3);
        byte[] nan = VolFiles.bytes(2, 1, 1, box, new float[] {1, Float.NaN});
        byte[] truncated = java.util.Arrays.copyOf(VolFiles.bytes(4, 4, 4, box, new float[64]), 100);
        return Stream.of(
                Arguments.of("an escape sequence for a magic", escape, List.of("not a Mitsuba volume file", "\\x1b[3")),
                Arguments.of("a bomb: 1290^3 voxels in 48 bytes", bomb, List.of("truncated: a 1290x1290x1290 grid needs 8586756000 bytes after the header, the file holds 0")),
                Arguments.of("2^93 voxels", huge, List.of("too large to load")),
                Arguments.of("three channels", rgb, List.of("holds 3 channels per voxel")),
                Arguments.of("a NaN density", nan, List.of("media.m.file")),
                Arguments.of("truncated", truncated, List.of("truncated: a 4x4x4 grid needs 256 bytes after the header, the file holds 52")));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("grids")
    void aHostileVolumeGridIsOneLineNamingIt(String label, byte[] bytes, List<String> fragments) throws IOException {
        write(in.resolve("g.vol"), bytes);
        write(in.resolve("s.json"), "{\"media\": {\"m\": {\"type\": \"grid\", \"file\": \"g.vol\"}},"
                + " \"materials\": {\"m\": {\"type\": \"null\"}},"
                + " \"shapes\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\", \"interior\": \"m\"}]}");
        assertRefused(label, List.of(in.resolve("s.json").toString()), in.resolve("g.vol"), fragments);
    }

    /** Exit code 2, one printable line naming the file with every fragment, no trace, nothing written, within 60 s. */
    private void assertRefused(String label, List<String> scene, Path named, List<String> fragments) throws IOException {
        List<String> args = new ArrayList<>(List.of("render"));
        args.addAll(scene);
        args.addAll(List.of("-o", out.resolve("a.png").toString(), "--width", "8", "--height", "8", "--spp", "1"));
        long start = System.nanoTime();
        RenderCommandTest.Run r = RenderCommandTest.strahl(args.toArray(String[]::new));
        double seconds = (System.nanoTime() - start) * 1e-9;
        assertThat(r.code()).as("%s: exit code; stderr: %s", label, r.err()).isEqualTo(2);
        assertThat(r.errLines()).as("one line on stderr").hasSize(1);
        String line = r.errLines().get(0);
        assertThat(line).startsWith("strahl: ").contains(named.toString());
        assertThat(line.chars().filter(c -> c < 0x20 || c > 0x7e).toArray()).as("characters outside printable ASCII in: %s", line).isEmpty();
        for (String f : fragments) {
            assertThat(line).contains(f);
        }
        assertThat(r.err()).doesNotContain("\tat ").doesNotContain("Exception").doesNotContain("OutOfMemoryError");
        assertThat(r.out()).isEmpty();
        try (Stream<Path> written = Files.list(out)) {
            assertThat(written).as("files written").isEmpty();
        }
        assertThat(seconds).as("seconds").isLessThan(60);
    }

    /** A missing texture is a warning wherever it is named; the image is rendered. */
    @Test
    void aMissingTextureIsAWarningWhereverItIsNamed() throws IOException {
        litTriangle("newmtl m\nKd 0.5 0.5 0.5\nKe 1 1 1\nmap_Kd gone.png\n");
        assertWarned(in.resolve("t.obj"), in.resolve("gone.png"));
        write(in.resolve("s.json"), "{\"shapes\": [" + SPHERE + "], \"materials\": {\"m\": {\"type\": \"diffuse\", \"albedo\": {\"texture\":"
                + " \"gone.jpg\"}}}, \"environment\": [1, 1, 1]}");
        assertWarned(in.resolve("s.json"), in.resolve("gone.jpg"));
        write(in.resolve("s.json"), "{\"shapes\": [" + SPHERE + "], \"materials\": {\"m\": {\"type\": \"diffuse\", \"albedo\": {\"texture\":"
                + " \"gone.exr\"}}}, \"environment\": [1, 1, 1]}");
        assertWarned(in.resolve("s.json"), in.resolve("gone.exr"));
        Map<String, byte[]> gltf = HostileGltf.textured("gone.png", new byte[0], ImageUse.FILE);
        write(in.resolve("t.gltf"), gltf.get("t.gltf"));
        assertWarned(in.resolve("t.gltf"), in.resolve("gone.png"));
    }

    private void assertWarned(Path scene, Path missing) throws IOException {
        Path image = out.resolve(scene.getFileName() + ".png");
        RenderCommandTest.Run r = RenderCommandTest.strahl("render", scene.toString(), "-o", image.toString(), "--width", "8",
                "--height", "8", "--spp", "1");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.errLines().stream().filter(l -> l.startsWith("strahl: warning: ")).toList()).as(r.err()).singleElement()
                .asString().contains(missing.toString());
        assertThat(image).isRegularFile();
    }

    /** A node hierarchy 100 000 deep is read (without a stack overflow), its one mesh at the bottom. */
    @Test
    void aDeepNodeHierarchyIsRead() throws IOException {
        StringBuilder nodes = new StringBuilder();
        int depth = 100_000;
        for (int i = 0; i < depth; i++) {
            nodes.append("{\"children\": [").append(i + 1).append("]},");
        }
        String json = dev.strahl.io.gltf.GltfWriter.json(HostileGltf.withBuffer(HostileGltf.plain(), "t.bin"));
        byte[] bin = HostileGltf.plain().binary();
        json = json.replace("\"nodes\":[{\"mesh\":0}]", "\"nodes\":[" + nodes + "{\"mesh\":0}]");
        write(in.resolve("t.gltf"), json);
        write(in.resolve("t.bin"), bin);
        RenderCommandTest.Run r = RenderCommandTest.strahl("render", in.resolve("t.gltf").toString(), "-o", out.resolve("a.png").toString(),
                "--width", "8", "--height", "8", "--spp", "1");
        assertThat(json).contains("{\"children\": [100000]},{\"mesh\":0}");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(out.resolve("a.png")).isRegularFile();
    }

    private void litTriangle(String mtl) throws IOException {
        write(in.resolve("t.obj"), TRIANGLE);
        write(in.resolve("m.mtl"), mtl);
    }

    private static void write(Path file, String text) throws IOException {
        Files.writeString(file, text, StandardCharsets.UTF_8);
    }

    private static void write(Path file, byte[] bytes) throws IOException {
        Files.write(file, bytes);
    }
}
