package dev.strahl.io;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.codec.ChannelImage;
import dev.strahl.codec.HdrReader;
import dev.strahl.codec.ImageFormatException;
import dev.strahl.codec.PfmReader;
import dev.strahl.codec.TextureImages;
import dev.strahl.codec.exr.ExrReader;
import dev.strahl.io.gltf.GltfFuzzInputs;
import dev.strahl.io.gltf.GltfFuzzSeeds;
import dev.strahl.io.obj.MtlReader;
import dev.strahl.medium.VolFile;
import dev.strahl.medium.VolFuzzInputs;
import dev.strahl.scene.SceneException;
import dev.strahl.testing.Fuzzer;
import dev.strahl.texture.Bitmap;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Example;
import net.jqwik.api.Tuple;
import net.jqwik.api.lifecycle.AfterContainer;
import net.jqwik.api.lifecycle.BeforeContainer;

/**
 * Fuzzing of the OBJ, MTL, PLY, glTF (GLB and JSON) and scene-file readers, of the image readers (EXR, Radiance HDR,
 * PFM, PNG/JPEG textures) and of Mitsuba's {@code .vol} density grids: random and mutated files may be accepted or rejected with the reader's own
 * error (a {@link SceneException}; an {@link ImageFormatException} for images and grids), never end in
 * another exception, a hang or running out of memory. Each parser gets a bounded budget ({@link Fuzzer#budget()}); every input that once
 * broke a parser is kept in {@code src/test/resources/fuzz/} and replayed by
 * {@link FuzzRegressionTest}. jqwik examples, since its generators run only inside jqwik.
 */
class ParserFuzzTest {
    private static Path work;

    /** The shipped scenes next to the fuzzed file, so that its mtllib and file references resolve. */
    @BeforeContainer
    static void copyTheShippedScenes() throws IOException {
        work = workDirectory();
    }

    @AfterContainer
    static void deleteTheCopies() throws IOException {
        deleteTree(work);
    }

    static Path workDirectory() throws IOException {
        Path dir = Files.createTempDirectory("strahl-fuzz");
        try (Stream<Path> files = Files.list(Path.of("scenes"))) {
            for (Path f : files.toList()) {
                Files.copy(f, dir.resolve(f.getFileName()));
            }
        }
        return dir;
    }

    static void deleteTree(Path dir) throws IOException {
        if (dir == null) {
            return;
        }
        try (Stream<Path> files = Files.walk(dir)) {
            for (Path f : files.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(f);
            }
        }
    }

    static Fuzzer.Target objTarget() {
        return SceneLoader::load;                   // reading, then building the scene and its BVH
    }

    static Fuzzer.Target mtlTarget() {
        return file -> MtlReader.read(file, new ArrayList<>());
    }

    static Fuzzer.Target plyTarget() {
        return SceneLoader::load;                   // reading, then building the scene and its BVH
    }

    static Fuzzer.Target jsonTarget() {
        return SceneLoader::load;
    }

    static Fuzzer.Target exrTarget() {
        return ExrReader::read;
    }

    static Fuzzer.Target hdrTarget() {
        return HdrReader::read;
    }

    /** PNG or JPEG (told apart by content) as the texture loader reads it: the reader, then the texture's bitmap and its sRGB twin. */
    static Fuzzer.Target pngTarget() {
        return file -> {
            ChannelImage image = TextureImages.read(file);
            Bitmap.fromTopDown("fuzz", image.width(), image.height(), image.channelCount(), image.data()).srgbDecoded();
        };
    }

    static Fuzzer.Target pfmTarget() {
        return PfmReader::read;
    }

    static Fuzzer.Target volTarget() {
        return VolFile::read;
    }

    @Example
    void objReaderOnlyEverThrowsSceneException() throws IOException {
        fuzz("obj", objTarget(), "fuzz.obj", mix(FuzzInputs.randomObj(),
                FuzzInputs.mutated(FuzzInputs.shippedFiles(".obj"), FuzzInputs.OBJ_WORDS)));
    }

    @Example
    void mtlReaderOnlyEverThrowsSceneException() throws IOException {
        fuzz("mtl", mtlTarget(), "fuzz.mtl", mix(FuzzInputs.randomMtl(),
                FuzzInputs.mutated(FuzzInputs.shippedFiles(".mtl"), FuzzInputs.MTL_WORDS)));
    }

    @Example
    void sceneFileReaderOnlyEverThrowsSceneException() throws IOException {
        fuzz("json", jsonTarget(), "fuzz.json", Arbitraries.frequencyOf(Tuple.of(1, FuzzInputs.randomJson()),
                Tuple.of(2, FuzzInputs.randomScene()),
                Tuple.of(2, FuzzInputs.mutated(FuzzInputs.shippedFiles(".json"), FuzzInputs.JSON_WORDS))));
    }

    @Example
    void plyReaderOnlyEverThrowsSceneException() throws IOException {
        fuzz("ply", plyTarget(), "fuzz.ply", mix(FuzzInputs.randomPly(), FuzzInputs.mutated(FuzzInputs.plySeeds(), FuzzInputs.PLY_WORDS)));
    }

    @Example
    void glbReaderOnlyEverThrowsSceneException() throws Exception {
        fuzz("glb", SceneLoader::load, "fuzz.glb", mix(GltfFuzzInputs.randomGlb(),
                FuzzInputs.mutated(GltfFuzzSeeds.glb(), GltfFuzzSeeds.WORDS)));
    }

    @Example
    void gltfReaderOnlyEverThrowsSceneException() throws Exception {
        fuzz("gltf", SceneLoader::load, "fuzz.gltf", Arbitraries.frequencyOf(Tuple.of(1, FuzzInputs.randomJson()),
                Tuple.of(2, GltfFuzzInputs.randomGltf()), Tuple.of(2, FuzzInputs.mutated(GltfFuzzSeeds.gltf(), GltfFuzzSeeds.WORDS))));
    }

    @Example
    void exrReaderOnlyEverThrowsImageFormatException() throws IOException {
        fuzz("exr", exrTarget(), ImageFormatException.class, "fuzz.exr", mix(ImageFuzzInputs.randomExr(),
                ImageFuzzInputs.mutated(ImageFuzzInputs.exrSeeds(), ImageFuzzInputs.EXR_WORDS)));
    }

    @Example
    void hdrReaderOnlyEverThrowsImageFormatException() throws IOException {
        fuzz("hdr", hdrTarget(), ImageFormatException.class, "fuzz.hdr", mix(ImageFuzzInputs.randomHdr(),
                ImageFuzzInputs.mutated(ImageFuzzInputs.hdrSeeds(), ImageFuzzInputs.HDR_WORDS)));
    }

    @Example
    void textureReaderOnlyEverThrowsImageFormatException() throws IOException {
        fuzz("png", pngTarget(), ImageFormatException.class, "fuzz.png", mix(ImageFuzzInputs.randomPng(),
                ImageFuzzInputs.mutated(ImageFuzzInputs.pngSeeds(), ImageFuzzInputs.PNG_WORDS)));
    }

    @Example
    void pfmReaderOnlyEverThrowsImageFormatException() throws IOException {
        fuzz("pfm", pfmTarget(), ImageFormatException.class, "fuzz.pfm", mix(PfmFuzzInputs.random(),
                ImageFuzzInputs.mutated(PfmFuzzInputs.seeds(), PfmFuzzInputs.WORDS)));
    }

    @Example
    void volReaderOnlyEverThrowsImageFormatException() throws IOException {
        fuzz("vol", volTarget(), ImageFormatException.class, "fuzz.vol", mix(VolFuzzInputs.fromTheGrammar(), VolFuzzInputs.mutated()));
    }

    private static Arbitrary<byte[]> mix(Arbitrary<byte[]> random, Arbitrary<byte[]> mutated) {
        return Arbitraries.frequencyOf(Tuple.of(1, random), Tuple.of(1, mutated));
    }

    private static void fuzz(String name, Fuzzer.Target target, String fileName, Arbitrary<byte[]> inputs) throws IOException {
        fuzz(name, target, SceneException.class, fileName, inputs);
    }

    private static void fuzz(String name, Fuzzer.Target target, Class<? extends Exception> allowed, String fileName,
            Arbitrary<byte[]> inputs) throws IOException {
        String only = System.getProperty("strahl.fuzz.only", "");
        if (!only.isEmpty() && !List.of(only.split(",")).contains(name)) {
            return;                                 // a campaign runs the parsers one by one (docs/reliability/fuzz.sh)
        }
        Fuzzer.Report report = new Fuzzer(name, target, allowed, work.resolve(fileName))
                .run(inputs, Fuzzer.budget(), Fuzzer.inputs(), Fuzzer.seed());
        System.out.println(report);
        Path reports = Fuzzer.output().resolve("fuzz-reports");
        Files.createDirectories(reports);
        Files.writeString(reports.resolve(name + ".txt"), report + "\n", StandardCharsets.UTF_8);
        assertThat(report.findings()).as(report.toString()).isEmpty();
        assertThat(report.inputs()).as("inputs run").isGreaterThan(100);
        assertThat(report.rejected()).as("some inputs are rejected").isPositive();
        assertThat(report.accepted()).as("some inputs are accepted").isPositive();
    }
}
