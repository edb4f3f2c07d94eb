package dev.strahl.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import static dev.strahl.codec.exr.ExrPixelType.FLOAT;
import static dev.strahl.codec.exr.ExrPixelType.HALF;

import dev.strahl.film.Film;
import dev.strahl.color.DisplayEncoding;
import dev.strahl.image.ToneMapping;
import dev.strahl.codec.exr.ExrCompression;
import dev.strahl.codec.exr.ExrHeader;
import dev.strahl.codec.exr.ExrReader;
import dev.strahl.codec.exr.Half;
import dev.strahl.codec.ChannelImage;
import dev.strahl.render.Aov;
import dev.strahl.render.RenderBuffers;
import dev.strahl.files.AtomicFile;
import dev.strahl.codec.PfmReader;
import dev.strahl.image.Image;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ImageWritersTest {

    @TempDir
    Path dir;

    private static Image gradient(int w, int h, float offset) {
        float[] rgb = new float[3 * w * h];
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = offset + i * 0.01f;
        }
        return new Image(w, h, rgb);
    }

    private List<String> filesIn(Path d) throws IOException {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().collect(Collectors.toList());
        }
    }

    @Test
    void pngHoldsTheSrgbCodesOfTheClampedPixelsTopRowFirst() throws IOException {
        // linear value -> 8-bit sRGB code: 0 -> 0, 0.001 -> 3 (12.92·x), 0.01 -> 25, 0.18 -> 118,
        // 0.5 -> 188, 1 -> 255, and clamping: 2 -> 255, -1 -> 0
        float[] linear = {0, 0.001f, 0.01f, 0.18f, 0.5f, 1, 2, -1};
        int[] code = {0, 3, 25, 118, 188, 255, 255, 0};
        float[] rgb = new float[3 * 8];
        for (int i = 0; i < 8; i++) {
            rgb[3 * i] = linear[i];
            rgb[3 * i + 1] = linear[7 - i];
            rgb[3 * i + 2] = 0.2f;                               // -> 124
        }
        Path out = dir.resolve("codes.png");
        ImageWriters.write(new Image(4, 2, rgb), out);

        BufferedImage png = ImageIO.read(out.toFile());
        assertThat(png.getWidth()).isEqualTo(4);
        assertThat(png.getHeight()).isEqualTo(2);
        assertThat(png.getColorModel().hasAlpha()).isFalse();
        assertThat(png.getSampleModel().getSampleSize(0)).isEqualTo(8);
        for (int i = 0; i < 8; i++) {
            int argb = png.getRGB(i % 4, i / 4);
            assertThat((argb >> 16) & 0xFF).as("red of pixel %d", i).isEqualTo(code[i]);
            assertThat((argb >> 8) & 0xFF).as("green of pixel %d", i).isEqualTo(code[7 - i]);
            assertThat(argb & 0xFF).as("blue of pixel %d", i).isEqualTo(124);
        }
    }

    @Test
    void pfmRoundTripIsExact() throws IOException {
        Image img = gradient(5, 3, -0.3f);
        Path out = dir.resolve("img.pfm");
        ImageWriters.write(img, out);
        assertThat(PfmReader.read(out)).isEqualTo(img);
    }

    @Test
    void extensionIsCaseInsensitive() throws IOException {
        Image img = gradient(2, 2, 0);
        ImageWriters.write(img, dir.resolve("A.PNG"));
        ImageWriters.write(img, dir.resolve("b.PfM"));
        assertThat(ImageIO.read(dir.resolve("A.PNG").toFile())).isNotNull();
        assertThat(PfmReader.read(dir.resolve("b.PfM"))).isEqualTo(img);
    }

    @Test
    void writingAFilmWritesItsMeanImage() throws IOException {
        Film film = new Film(3, 2);
        film.add(film.pixelIndex(0, 0), 1, 2, 3);
        film.add(film.pixelIndex(0, 0), 3, 2, 1);
        film.add(film.pixelIndex(2, 1), 0.5, 0.25, 8);
        Path out = dir.resolve("film.pfm");
        ImageWriters.write(film.toImage(), out);
        assertThat(PfmReader.read(out)).isEqualTo(film.toImage());
    }

    @Test
    void isSupportedKnowsPngPfmAndExrInAnyCase() {
        assertThat(ImageWriters.isSupported(Path.of("a.png"))).isTrue();
        assertThat(ImageWriters.isSupported(Path.of("dir/b.PFM"))).isTrue();
        assertThat(ImageWriters.isSupported(Path.of("c.Exr"))).isTrue();
        assertThat(ImageWriters.isSupported(Path.of("d.hdr"))).isFalse();
        assertThat(ImageWriters.isSupported(Path.of("png"))).isFalse();
        assertThat(ImageWriters.isSupported(Path.of("archive.png.gz"))).isFalse();
    }

    @Test
    void unknownExtensionThrowsAndWritesNothing() throws IOException {
        Path out = dir.resolve("out.xyz");
        assertThatThrownBy(() -> ImageWriters.write(gradient(1, 1, 0), out))
                .isExactlyInstanceOf(IllegalArgumentException.class)
                .hasMessage("unknown image format '.xyz' of " + out + ": use .png, .pfm or .exr");
        Path bare = dir.resolve("out");
        assertThatThrownBy(() -> ImageWriters.write(new Film(1, 1).toImage(), bare))
                .isExactlyInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("no extension");
        assertThat(filesIn(dir)).isEmpty();
    }

    @Test
    void missingOutputDirectoryThrowsAndCreatesNothing() throws IOException {
        Path missing = dir.resolve("missing");
        assertThatThrownBy(() -> ImageWriters.write(gradient(1, 1, 0), missing.resolve("x.png")))
                .isExactlyInstanceOf(IOException.class)
                .hasMessage("output directory does not exist: " + missing.toAbsolutePath());
        assertThat(filesIn(dir)).isEmpty();
    }

    @Test
    void aDirectoryInTheWayIsNotReplaced() throws IOException {
        Path target = Files.createDirectory(dir.resolve("x.png"));
        assertThatThrownBy(() -> ImageWriters.write(gradient(1, 1, 0), target)).isInstanceOf(IOException.class);
        assertThat(Files.isDirectory(target)).isTrue();
        assertThat(filesIn(dir)).containsExactly("x.png");
    }

    @Test
    void overwriteReplacesTheFileWithTheCompleteNewImage() throws IOException {
        Path out = dir.resolve("x.pfm");
        ImageWriters.write(gradient(4, 4, 0), out);
        Image second = gradient(3, 5, 7);
        ImageWriters.write(second, out);
        assertThat(PfmReader.read(out)).isEqualTo(second);
        Path png = dir.resolve("x.png");
        ImageWriters.write(gradient(4, 4, 0), png);
        ImageWriters.write(second, png);
        assertThat(ImageIO.read(png.toFile()).getHeight()).isEqualTo(5);
        assertThat(filesIn(dir)).containsExactly("x.pfm", "x.png");
    }

    @Test
    void aFailingEncoderLeavesTheOldFileAndNoTemporaryFile() throws IOException {
        Path out = dir.resolve("keep.pfm");
        Image old = gradient(2, 2, 1);
        ImageWriters.write(old, out);

        IOException diskFull = new IOException("disk full");
        assertThatThrownBy(() -> AtomicFile.write(out, os -> {
            os.write(new byte[200_000]);                       // more than the stream buffers
            throw diskFull;
        })).isSameAs(diskFull);
        RuntimeException bug = new UncheckedIOException(new IOException("encoder bug"));
        assertThatThrownBy(() -> AtomicFile.write(out, os -> {
            os.write(1);
            throw bug;
        })).isSameAs(bug);

        assertThat(PfmReader.read(out)).isEqualTo(old);
        assertThat(filesIn(dir)).containsExactly("keep.pfm");
    }

    @Test
    void theImageGetsTheDirectorysUsualPermissionsNotThoseOfATemporaryFile() throws IOException {
        assumeTrue(Files.getFileAttributeView(dir, PosixFileAttributeView.class) != null, "POSIX file system");
        Path plain = Files.createFile(dir.resolve("plain"));    // 0666 minus the umask
        Path out = dir.resolve("img.png");
        ImageWriters.write(gradient(1, 1, 0), out);
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(out)))
                .isEqualTo(PosixFilePermissions.toString(Files.getPosixFilePermissions(plain)));
    }

    /** Buffers whose every value differs: color ramps, albedo, normal, a depth beyond half's range. */
    private static RenderBuffers buffers(int w, int h) {
        float[] albedo = new float[3 * w * h], normal = new float[3 * w * h], depth = new float[3 * w * h];
        for (int p = 0; p < w * h; p++) {
            for (int c = 0; c < 3; c++) {
                albedo[3 * p + c] = 0.1f * c + 0.001f * p;
                normal[3 * p + c] = c == 2 ? 1 - 0.01f * p : -0.5f + 0.02f * p;
                depth[3 * p + c] = 70000f + p;                         // above 65504: FLOAT, not HALF
            }
        }
        Image color = gradient(w, h, 0.25f);
        return new RenderBuffers(color, new Image(w, h, new float[3 * w * h]), new Image(w, h, albedo), new Image(w, h, normal),
                new Image(w, h, depth));
    }

    @Test
    void exrHoldsTheImageAndItsFeatureBuffersInOneFileWithTheNamesOfTheLayers() throws IOException {
        RenderBuffers b = buffers(5, 3);
        Path out = dir.resolve("out.exr");
        ImageWriters.defaults().write(b, out);
        ExrReader.ExrImage read = ExrReader.readFile(out);
        assertThat(read.header().compression()).isEqualTo(ExrCompression.ZIP);
        assertThat(read.header().channels()).extracting(ExrHeader.Channel::name)
                .containsExactly("B", "G", "R", "albedo.B", "albedo.G", "albedo.R", "depth.Z", "normal.X", "normal.Y", "normal.Z");
        assertThat(read.header().channels()).extracting(ExrHeader.Channel::type)
                .containsExactly(HALF, HALF, HALF, HALF, HALF, HALF, FLOAT, HALF, HALF, HALF);
        ChannelImage px = read.pixels();
        String[][] layers = {{"R", "G", "B"}, {"albedo.R", "albedo.G", "albedo.B"}, {"normal.X", "normal.Y", "normal.Z"}};
        Image[] images = {b.color(), b.albedo(), b.normal()};
        for (int l = 0; l < 3; l++) {
            for (int y = 0; y < 3; y++) {
                for (int x = 0; x < 5; x++) {
                    for (int c = 0; c < 3; c++) {
                        float v = images[l].get(x, y, c);
                        assertThat(px.get(x, y, px.channel(layers[l][c]))).as("%s at %d,%d", layers[l][c], x, y)
                                .isEqualTo(Half.toFloat(Half.fromFloat(v)));
                    }
                }
                for (int x = 0; x < 5; x++) {
                    assertThat(px.get(x, y, px.channel("depth.Z"))).isEqualTo(b.depth().get(x, y, 0));
                }
            }
        }
        // float samples, no compression: every value exactly
        Path flat = dir.resolve("flat.exr");
        ImageWriters.defaults().withExrFloat(true).withExrZip(false).write(b, flat);
        ExrReader.ExrImage f = ExrReader.readFile(flat);
        assertThat(f.header().compression()).isEqualTo(ExrCompression.NONE);
        assertThat(f.header().channels()).extracting(ExrHeader.Channel::type).containsOnly(FLOAT);
        assertThat(f.pixels().get(4, 2, f.pixels().channel("normal.Y"))).isEqualTo(b.normal().get(4, 2, 1));
        // an image alone: R, G, B only
        ImageWriters.write(b.color(), dir.resolve("plain.exr"));
        assertThat(ExrReader.readFile(dir.resolve("plain.exr")).header().channels()).extracting(ExrHeader.Channel::name)
                .containsExactly("B", "G", "R");
    }

    @Test
    void openExrReadsTheLayersStrahlWrites() throws Exception {
        boolean available;
        try {
            Process p = new ProcessBuilder("python3", "-c", "import OpenEXR, numpy").redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            available = p.waitFor() == 0;
        } catch (IOException e) {
            available = false;
        }
        assumeTrue(available, "python3 with the OpenEXR package is not installed");
        RenderBuffers b = buffers(4, 2);
        Path out = dir.resolve("layers.exr");
        ImageWriters.defaults().write(b, out);
        Process p = new ProcessBuilder("python3", "docs/anchors/exr_dump.py", out.toString()).redirectErrorStream(true).start();
        String dump = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertThat(p.waitFor()).as(dump).isZero();
        List<String> channels = dump.lines().filter(l -> l.startsWith("channel ")).map(l -> l.split(" ")[1] + " " + l.split(" ")[2])
                .collect(Collectors.toList());
        assertThat(channels).containsExactly("B HALF", "G HALF", "R HALF", "albedo.B HALF", "albedo.G HALF", "albedo.R HALF",
                "depth.Z FLOAT", "normal.X HALF", "normal.Y HALF", "normal.Z HALF");
        // the first depth sample, as OpenEXR read it: the float's bits
        String depth = dump.lines().filter(l -> l.startsWith("channel depth.Z ")).findFirst().orElseThrow();
        assertThat(Integer.parseUnsignedInt(depth.split(" ")[3], 16)).isEqualTo(Float.floatToIntBits(70000f));
    }

    @Test
    void featureBuffersGoBesideAPngOrPfmAsPfmFiles() throws IOException {
        RenderBuffers b = buffers(3, 2);
        Path png = dir.resolve("shot.png");
        ImageWriters.defaults().write(new RenderBuffers(b.color(), b.variance(), b.albedo(), null, b.depth()), png);
        assertThat(filesIn(dir)).containsExactly("shot.albedo.pfm", "shot.depth.pfm", "shot.png");
        assertThat(PfmReader.read(dir.resolve("shot.albedo.pfm"))).isEqualTo(b.albedo());
        assertThat(PfmReader.read(dir.resolve("shot.depth.pfm"))).isEqualTo(b.depth());
        assertThat(ImageWriters.featureFile(Path.of("a/b.c.pfm"), Aov.NORMAL)).isEqualTo(Path.of("a/b.c.normal.pfm"));
    }

    @Test
    void pngToneCurveAndExposureApplyToPngOnly() throws IOException {
        Image img = new Image(1, 1, new float[] {4, 1, 0.25f});
        Path clamp = dir.resolve("clamp.png");
        Path aces = dir.resolve("aces.png");
        ImageWriters.defaults().write(RenderBuffers.of(img), clamp);
        ImageWriters.defaults().withToneMapping(ToneMapping.ACES).withExposure(-1).write(RenderBuffers.of(img), aces);
        int c = ImageIO.read(clamp.toFile()).getRGB(0, 0);
        int a = ImageIO.read(aces.toFile()).getRGB(0, 0);
        assertThat(c & 0xFFFFFF).isEqualTo(0xFFFF89);                   // 4 and 1 clamp to 255, 0.25 -> 137
        // ACES at −1 EV: 2 -> 0.908 -> 245, 0.5 -> 0.616 -> 205, 0.125 -> 0.167 -> 114
        assertThat((a >> 16) & 0xFF).isEqualTo(DisplayEncoding.toSrgb8(DisplayEncoding.aces(2)));
        assertThat((a >> 8) & 0xFF).isEqualTo(DisplayEncoding.toSrgb8(DisplayEncoding.aces(0.5)));
        assertThat(a & 0xFF).isEqualTo(DisplayEncoding.toSrgb8(DisplayEncoding.aces(0.125)));
        Path pfm = dir.resolve("linear.pfm");
        ImageWriters.defaults().withToneMapping(ToneMapping.AGX).withExposure(3).write(RenderBuffers.of(img), pfm);
        assertThat(PfmReader.read(pfm)).isEqualTo(img);
    }
}
