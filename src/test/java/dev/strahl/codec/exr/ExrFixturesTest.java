package dev.strahl.codec.exr;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.codec.ChannelImage;
import dev.strahl.codec.ImageFormatException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Known answers: files written by the OpenEXR library (docs/anchors/exr_fixtures.py, OpenEXR
 * 3.5.3; src/test/resources/exr/README.md) read value by value. The formulas below are those of
 * the script; every value is exact in its pixel type.
 */
class ExrFixturesTest {
    private static final Path DIR = Path.of("src", "test", "resources", "exr");

    private static final float[] SPECIAL = {0f, -0f, 0x1p-24f, -0x1p-24f, 0x1p-14f, 65504f, -65504f, Float.POSITIVE_INFINITY,
        Float.NEGATIVE_INFINITY, Float.NaN, 1f, 0.5f, 3f / 1024, 1000f};

    private static void assertSame(float actual, float expected, String where) {
        assertThat(Float.floatToIntBits(actual)).as("%s: %s, expected %s", where, actual, expected)
                .isEqualTo(Float.floatToIntBits(expected));
    }

    @ParameterizedTest
    @ValueSource(strings = {"none", "rle", "zips", "zip", "piz"})
    void rgbaHalfIsReadValueByValue(String compression) throws IOException {
        ExrReader.ExrImage file = ExrReader.readFile(DIR.resolve("rgba-half-" + compression + ".exr"));
        ChannelImage img = file.pixels();
        assertThat(file.header().compression().name().toLowerCase(java.util.Locale.ROOT)).isEqualTo(compression);
        assertThat(img.channels()).containsExactly("A", "B", "G", "R");
        assertThat(file.header().channels()).extracting(ExrHeader.Channel::type).containsOnly(ExrPixelType.HALF);
        assertThat(img.width()).isEqualTo(7);
        assertThat(img.height()).isEqualTo(5);
        for (int y = 0; y < 5; y++) {
            for (int x = 0; x < 7; x++) {
                String at = compression + " (" + x + ", " + y + ")";
                assertSame(img.get(x, y, 3), x + 8 * y, "R " + at);
                assertSame(img.get(x, y, 2), (x - 3) * 0.25f + y * 0.125f, "G " + at);
                assertSame(img.get(x, y, 1), SPECIAL[(y * 7 + x) % SPECIAL.length], "B " + at);
                assertSame(img.get(x, y, 0), 1 - y / 4f, "A " + at);
            }
        }
        assertCompressedChunks(file, compression);
    }

    /** PIZ does not pay for the small fixtures: OpenEXR stored them raw (piz-mixed is the compressed one). */
    private static void assertCompressedChunks(ExrReader.ExrImage file, String compression) {
        if (compression.equals("none") || compression.equals("piz")) {
            assertThat(file.compressedChunks()).as("chunks stored compressed").isZero();
        } else {
            assertThat(file.compressedChunks()).as("chunks the test decompresses").isPositive();
        }
    }

    @ParameterizedTest
    @CsvSource({"none, 37, 0", "rle, 37, 0", "zips, 37, 0", "zip, 3, 1", "piz, 2, 1"})
    void mixedTypesWindowsAndLineOrderAreReadValueByValue(String compression, int chunks, int lineOrder) throws IOException {
        ExrReader.ExrImage file = ExrReader.readFile(DIR.resolve("mixed-" + compression + ".exr"));
        ChannelImage img = file.pixels();
        ExrHeader h = file.header();
        assertThat(h.dataWindow()).isEqualTo(new ExrHeader.Box(-3, 10, 5, 46));
        assertThat(h.displayWindow()).isEqualTo(new ExrHeader.Box(0, 0, 15, 63));
        assertThat(h.lineOrder()).isEqualTo(lineOrder);
        assertThat((h.dataWindow().height() + h.compression().linesPerChunk() - 1) / h.compression().linesPerChunk()).isEqualTo(chunks);
        assertThat(h.channels()).containsExactly(new ExrHeader.Channel("Y", ExrPixelType.HALF),
                new ExrHeader.Channel("Z", ExrPixelType.FLOAT), new ExrHeader.Channel("id", ExrPixelType.UINT));
        assertThat(img.channels()).containsExactly("Y", "Z", "id");
        assertThat(img.width()).isEqualTo(9);
        assertThat(img.height()).isEqualTo(37);
        for (int y = 0; y < 37; y++) {
            for (int x = 0; x < 9; x++) {
                String at = compression + " (" + x + ", " + y + ")";
                assertSame(img.get(x, y, 0), x * y / 16f, "Y " + at);
                float z = Math.scalb((float) (x + 1), y - 18);
                assertSame(img.get(x, y, 1), y % 2 == 1 ? -z : z, "Z " + at);
                long id = x == 0 && y == 0 ? 4294967295L : (x * 37L + y) * 65537;
                assertSame(img.get(x, y, 2), (float) id, "id " + at);
            }
        }
        assertCompressedChunks(file, compression);
    }

    @Test
    void pizOfAllTypesOddSizesAndAWindowIsReadExactly() throws IOException {
        ExrReader.ExrImage file = ExrReader.readFile(DIR.resolve("piz-mixed.exr"));
        ChannelImage img = file.pixels();
        assertThat(file.header().dataWindow()).isEqualTo(new ExrHeader.Box(10, -7, 70, 37));
        assertThat(file.header().lineOrder()).isEqualTo(1);
        assertThat(file.compressedChunks()).as("both chunks compressed").isEqualTo(2);
        assertThat(img.channels()).containsExactly("Y", "Z", "id");
        assertThat(img.width()).isEqualTo(61);
        assertThat(img.height()).isEqualTo(45);
        for (int y = 0; y < 45; y++) {
            for (int x = 0; x < 61; x++) {
                String at = "(" + x + ", " + y + ")";
                assertSame(img.get(x, y, 0), (x + 2 * y) / 64f, "Y " + at);
                assertSame(img.get(x, y, 1), Math.scalb((float) (x + 1), (y / 4) - 5), "Z " + at);
                assertSame(img.get(x, y, 2), x + 61 * y, "id " + at);
            }
        }
    }

    @Test
    void pizWithMoreThan16384DistinctValuesUsesTheWideWaveletAndReadsExactly() throws IOException {
        ExrReader.ExrImage file = ExrReader.readFile(DIR.resolve("piz-wide-range.exr"));
        ChannelImage img = file.pixels();
        assertThat(img.channels()).containsExactly("Y");
        assertThat(img.width()).isEqualTo(256);
        assertThat(img.height()).isEqualTo(124);
        assertThat(file.compressedChunks()).isEqualTo(4);
        for (int y = 0; y < 124; y++) {
            for (int x = 0; x < 256; x++) {
                assertSame(img.get(x, y, 0), Half.toFloat(y * 256 + x), "(" + x + ", " + y + ")");
            }
        }
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "refused-dwaa.exr | EXR compression DWAA is not supported (strahl reads NONE, RLE, ZIPS, ZIP, PIZ)",
        "refused-b44.exr | EXR compression B44 is not supported (strahl reads NONE, RLE, ZIPS, ZIP, PIZ)",
        "refused-pxr24.exr | EXR compression PXR24 is not supported (strahl reads NONE, RLE, ZIPS, ZIP, PIZ)",
        "refused-tiled.exr | tiled EXR files are not supported (strahl reads single-part scanline images)",
        "refused-two-parts.exr | multi-part EXR files are not supported (strahl reads single-part scanline images)"})
    void otherKindsAreRefusedByName(String name, String message) {
        Path file = DIR.resolve(name);
        assertThatThrownBy(() -> ExrReader.read(file)).isInstanceOf(ImageFormatException.class).hasMessage(file + ": " + message);
    }

    @Test
    void rgbConvenienceTakesTheColourChannels() throws IOException {
        ChannelImage rgb = ExrReader.readRgb(DIR.resolve("rgba-half-zip.exr"));
        assertThat(rgb.channels()).containsExactly("R", "G", "B");
        assertThat(rgb.get(2, 1, 0)).isEqualTo(10f);
        ChannelImage grey = ExrReader.readRgb(DIR.resolve("mixed-zip.exr"));
        assertThat(grey.channels()).containsExactly("R", "G", "B");
        assertThat(List.of(grey.get(4, 4, 0), grey.get(4, 4, 1), grey.get(4, 4, 2))).containsOnly(1f);
    }
}
