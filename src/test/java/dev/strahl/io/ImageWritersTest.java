package dev.strahl.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import dev.strahl.film.Film;
import dev.strahl.io.image.AtomicFile;
import dev.strahl.io.image.PfmReader;
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
        ImageWriters.write(film, out);
        assertThat(PfmReader.read(out)).isEqualTo(film.toImage());
    }

    @Test
    void isSupportedKnowsPngAndPfmInAnyCase() {
        assertThat(ImageWriters.isSupported(Path.of("a.png"))).isTrue();
        assertThat(ImageWriters.isSupported(Path.of("dir/b.PFM"))).isTrue();
        assertThat(ImageWriters.isSupported(Path.of("c.exr"))).isFalse();
        assertThat(ImageWriters.isSupported(Path.of("png"))).isFalse();
        assertThat(ImageWriters.isSupported(Path.of("archive.png.gz"))).isFalse();
    }

    @Test
    void unknownExtensionThrowsAndWritesNothing() throws IOException {
        Path out = dir.resolve("out.xyz");
        assertThatThrownBy(() -> ImageWriters.write(gradient(1, 1, 0), out))
                .isExactlyInstanceOf(IllegalArgumentException.class)
                .hasMessage("unknown image format '.xyz' of " + out + ": use .png or .pfm");
        Path bare = dir.resolve("out");
        assertThatThrownBy(() -> ImageWriters.write(new Film(1, 1), bare))
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
}
