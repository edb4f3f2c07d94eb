package dev.strahl.codec;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.testing.Bytes;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class HdrTest {
    private static final Path FIXTURES = Path.of("src", "test", "resources", "hdr");

    @TempDir
    Path dir;

    /** The formula of docs/anchors/hdr_fixtures.py: mantissas r, g, b and exponent e of pixel (x, y). */
    static int[] fixturePixel(int x, int y) {
        if ((x + y) % 11 == 5) {
            return new int[] {0, 0, 0, 0};
        }
        if (y % 2 == 1) {
            return new int[] {200, 100, 50, 130};
        }
        return new int[] {128 + (x * 37 + y * 11) % 128, (x * 13 + y * 7) % 256, (x * 5 + y * 3) % 128, 118 + (x + 3 * y) % 20};
    }

    private static float decoded(int m, int e) {
        return e == 0 ? 0 : m * (float) Math.pow(2, e - 136);
    }

    @ParameterizedTest
    @CsvSource({"opencv-rle.hdr, 37, 6", "opencv-flat.hdr, 37, 6", "opencv-narrow.hdr, 5, 4"})
    void picturesWrittenByOpenCvAreReadValueByValue(String name, int w, int h) throws IOException {
        ChannelImage img = HdrReader.read(FIXTURES.resolve(name));
        assertThat(img.channels()).containsExactly("R", "G", "B");
        assertThat(img.width()).isEqualTo(w);
        assertThat(img.height()).isEqualTo(h);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int[] p = fixturePixel(x, y);
                for (int c = 0; c < 3; c++) {
                    assertThat(img.get(x, y, c)).as("%s (%d, %d) channel %d", name, x, y, c).isEqualTo(decoded(p[c], p[3]));
                }
            }
        }
    }

    @Test
    void theRunLengthFixtureIsRunLengthEncoded() throws IOException {
        byte[] b = Files.readAllBytes(FIXTURES.resolve("opencv-rle.hdr"));
        int data = indexOf(b, "+X 37\n") + 6;
        assertThat(Arrays.copyOfRange(b, data, data + 4)).containsExactly(2, 2, 0, 37);
        assertThat(b.length).isLessThan(Files.readAllBytes(FIXTURES.resolve("opencv-flat.hdr")).length);
    }

    // ---- files built byte by byte from the format description --------------------------------

    private static byte[] concat(Object... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (Object p : parts) {
            if (p instanceof String s) {
                out.writeBytes(s.getBytes(StandardCharsets.ISO_8859_1));
            } else if (p instanceof int[] ints) {
                for (int i : ints) {
                    out.write(i);
                }
            } else {
                out.writeBytes((byte[]) p);
            }
        }
        return out.toByteArray();
    }

    private Path file(byte[] content) throws IOException {
        return Files.write(dir.resolve("t.hdr"), content);
    }

    @Test
    void aFlatPictureDecodesAsMantissaTimesTwoToTheExponentMinus136() throws IOException {
        Path f = file(concat("#?RGBE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=2.0\n# a comment\n\n-Y 2 +X 2\n",
                new int[] {128, 64, 0, 129, 255, 1, 0, 136, 0, 0, 0, 0, 7, 9, 11, 0, 1, 1, 1, 1}, new int[0]));
        // 1 x 2 is fine too: only the first 16 bytes are the 4 pixels; the rest is ignored
        ChannelImage img = HdrReader.read(f);
        assertThat(img.data()).containsExactly(1f, 0.5f, 0f, 255f, 1f, 0f, 0f, 0f, 0f, 0f, 0f, 0f);
    }

    /** Pixel k of a 3x2 picture in reading order (top-left first): (k + 1) · 2 in red, 2k in green. */
    private static final float[] EXPECTED = {2, 0, 0, 4, 2, 0, 6, 4, 0, 8, 6, 0, 10, 8, 0, 12, 10, 0};

    private static int[] pixel(int k) {
        return new int[] {k + 1, k, 0, 137};
    }

    @ParameterizedTest
    @ValueSource(strings = {"-Y 2 +X 3", "+Y 2 +X 3", "-Y 2 -X 3", "+Y 2 -X 3", "+X 3 -Y 2", "-X 3 -Y 2", "+X 3 +Y 2", "-X 3 +Y 2"})
    void allEightOrientationsGiveTheSameTopRowFirstImage(String resolution) throws IOException {
        // the scanlines in file order: for each scanline the pixel index k (row-major, top-left first) it holds
        String[] t = resolution.split(" ");
        boolean rows = t[0].endsWith("Y");
        ByteArrayOutputStream body = new ByteArrayOutputStream();
        int n1 = Integer.parseInt(t[1]);
        int n2 = Integer.parseInt(t[3]);
        for (int s = 0; s < n1; s++) {
            for (int i = 0; i < n2; i++) {
                int along = i;
                int across = s;
                int x;
                int y;
                if (rows) {
                    x = t[2].startsWith("+") ? along : 2 - along;
                    y = t[0].startsWith("-") ? across : 1 - across;
                } else {
                    x = t[0].startsWith("+") ? across : 2 - across;
                    y = t[2].startsWith("-") ? along : 1 - along;
                }
                for (int v : pixel(y * 3 + x)) {
                    body.write(v);
                }
            }
        }
        ChannelImage img = HdrReader.read(file(concat("#?RADIANCE\n\n" + resolution + "\n", body.toByteArray())));
        assertThat(img.width()).isEqualTo(3);
        assertThat(img.height()).isEqualTo(2);
        assertThat(img.data()).containsExactly(EXPECTED);
    }

    @Test
    void aRunLengthEncodedScanlineWithRunsAndLiteralsDecodes() throws IOException {
        // 10 pixels: r = 100 x4, then 1..6; g all 50; b literals 0..9; e = 137 x10
        byte[] line = concat(new int[] {2, 2, 0, 10},
                new int[] {128 + 4, 100, 6, 1, 2, 3, 4, 5, 6},
                new int[] {128 + 10, 50},
                new int[] {10, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9},
                new int[] {128 + 10, 137});
        ChannelImage img = HdrReader.read(file(concat("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 10\n", line, line)));
        int[] r = {100, 100, 100, 100, 1, 2, 3, 4, 5, 6};
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 10; x++) {
                assertThat(img.get(x, y, 0)).isEqualTo(2f * r[x]);
                assertThat(img.get(x, y, 1)).isEqualTo(100f);
                assertThat(img.get(x, y, 2)).isEqualTo(2f * x);
            }
        }
    }

    @Test
    void flatScanlinesOfAWideImageAreRecognisedByTheirFirstPixel() throws IOException {
        ByteArrayOutputStream body = new ByteArrayOutputStream();
        for (int i = 0; i < 9; i++) {
            body.writeBytes(new byte[] {(byte) (128 + i), 0, 0, (byte) 136});
        }
        ChannelImage img = HdrReader.read(file(concat("#?RADIANCE\n\n-Y 1 +X 9\n", body.toByteArray())));
        assertThat(img.get(8, 0, 0)).isEqualTo(136f);
    }

    // ---- writer ------------------------------------------------------------------------------

    @ParameterizedTest
    @CsvSource({"1, 1", "7, 3", "8, 2", "100, 9", "32767, 1", "32768, 1", "40000, 2"})
    void writtenPicturesReadBackWithinHalfAStepOfTheLargestComponentsExponent(int w, int h) throws IOException {
        SplittableRandom r = new SplittableRandom(w * 31L + h);
        float[] rgb = new float[3 * w * h];
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = switch (i % 97) {
                case 0 -> 0f;
                case 1 -> 1e-40f;
                case 2 -> 1e30f;
                default -> (float) Math.exp(r.nextGaussian() * 5);
            };
        }
        for (int i = 3 * (w / 2); i < 3 * w; i++) {
            rgb[i] = 0.75f;                                       // a run for the RLE
        }
        Path f = dir.resolve("w.hdr");
        HdrWriter.write(f, w, h, rgb);
        ChannelImage img = HdrReader.read(f);
        assertThat(img.width()).isEqualTo(w);
        assertThat(img.height()).isEqualTo(h);
        for (int p = 0; p < w * h; p++) {
            float max = Math.max(rgb[3 * p], Math.max(rgb[3 * p + 1], rgb[3 * p + 2]));
            for (int c = 0; c < 3; c++) {
                assertThat((double) img.data()[3 * p + c]).as("pixel %d channel %d", p, c)
                        .isCloseTo(rgb[3 * p + c], org.assertj.core.data.Offset.offset(max * 0x1p-8 + 0x1p-137));
            }
        }
        byte[] b = Files.readAllBytes(f);
        int data = Bytes.indexOf(b, ("+X " + w + "\n").getBytes(StandardCharsets.US_ASCII)) + ("+X " + w + "\n").length();
        boolean rle = b[data] == 2 && b[data + 1] == 2;
        assertThat(rle).as("run-length encoded iff 8 <= width <= 32767").isEqualTo(w >= 8 && w <= 32767);
    }

    @Test
    void exactlyRepresentableValuesRoundTripExactly() throws IOException {
        float[] rgb = {1f, 0.5f, 0.25f, 1.5f, 3f, 0x1p-6f, 0f, 0f, 0f, 0x1p-130f, 0f, 0x1p-135f};
        Path f = dir.resolve("x.hdr");
        HdrWriter.write(f, 2, 2, rgb);
        assertThat(HdrReader.read(f).data()).containsExactly(rgb);
        assertThat(Files.readString(f, StandardCharsets.ISO_8859_1)).startsWith("#?RADIANCE\n# written by strahl\n"
                + "FORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n");
    }

    @Test
    void valuesRgbeCannotHoldAreRefusedNamingThePixel() {
        for (float bad : new float[] {-1f, Float.NaN, Float.POSITIVE_INFINITY, 3e38f}) {
            float[] rgb = new float[12];
            rgb[7] = bad;
            assertThatThrownBy(() -> HdrWriter.write(dir.resolve("bad.hdr"), 2, 2, rgb)).as("%s", bad)
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("pixel (0, 1)");
        }
        assertThat(dir.resolve("bad.hdr")).doesNotExist();
    }

    // ---- bad files ---------------------------------------------------------------------------

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "P6\\n1 1\\n255\\n | :1: not a Radiance HDR file (expected a first line such as '#?RADIANCE', found 'P6')",
        "#?RADIANCE\\nFORMAT=32-bit_rle_xyze\\n\\n-Y 1 +X 1\\nabcd | :2: XYZE pictures are not supported (strahl reads FORMAT=32-bit_rle_rgbe)",
        "#?RADIANCE\\nFORMAT=bitmap\\n\\n | :2: unknown pixel format 'bitmap' (strahl reads 32-bit_rle_rgbe)",
        "#?RADIANCE\\n\\n-Y 1 -Y 2\\nabcd | :3: bad resolution line '-Y 1 -Y 2' (expected e.g. '-Y 512 +X 1024')",
        "#?RADIANCE\\n\\n-Y 0 +X 2\\n | :3: bad image size in '-Y 0 +X 2' (each must be from 1 to 2147483647)",
        "#?RADIANCE\\nFORMAT=32-bit_rle_rgbe\\n | :3: the file ends inside the header: it is truncated, or not a Radiance HDR file",
        "#?RADIANCE\\n\\n-Y 30000 +X 30000\\nabcd | :3: the file is truncated: 30000 scanlines of 30000 pixels need at least 56520000 bytes, but 4 follow the header",
        "#?RADIANCE\\n\\n-Y 2 +X 2\\nabcdabcdabc | :3: the file is truncated: 2 scanlines of 2 pixels need at least 16 bytes, but 11 follow the header",
        "#?RADIANCE\\n\\n-Y 2 +X 9\\nabcdabcdabcdabcdabcdabcdabcdabcdabcdabcdabcdabcdabcdabcd | : scanline 1 (byte 58): the file ends inside the scanline: it is truncated"})
    void badFilesGiveOneLineNamingTheFileAndPlace(String content, String message) throws IOException {
        Path f = file(content.replace("\\n", "\n").getBytes(StandardCharsets.ISO_8859_1));
        assertThatThrownBy(() -> HdrReader.read(f)).isInstanceOf(ImageFormatException.class).hasMessage(f + message);
    }

    @Test
    void corruptRunLengthCodeIsRefused() throws IOException {
        String head = "#?RADIANCE\n\n-Y 1 +X 10\n";
        int[] padding = new int[20];
        assertThatThrownBy(() -> HdrReader.read(file(concat(head, new int[] {2, 2, 0, 11}, padding))))
                .hasMessageEndingWith("scanline 0 (byte 23): run-length encoded scanline of 11 pixels, the image's are 10");
        assertThatThrownBy(() -> HdrReader.read(file(concat(head, new int[] {2, 2, 0, 10, 128 + 11, 5}, padding))))
                .hasMessageEndingWith("scanline 0 (byte 23): a run of 11 goes past the end of the 10-pixel scanline");
        assertThatThrownBy(() -> HdrReader.read(file(concat(head, new int[] {2, 2, 0, 10, 0}, padding))))
                .hasMessageEndingWith("scanline 0 (byte 23): a count of 0 in the run-length code");
        assertThatThrownBy(() -> HdrReader.read(file(concat(head, new int[] {2, 2, 0, 10, 11}, new int[8]))))
                .hasMessageEndingWith("scanline 0 (byte 23): 11 literal bytes go past the end of the 10-pixel scanline");
    }

    @Test
    void oldStyleRunLengthEncodingIsNotDecodedAndTheTruncationSaysItMayBeThat() throws IOException {
        // a 2x1 picture whose second pixel repeats the first (old style, 1 1 1 n): 8 bytes expected, 8 there: read literally
        ChannelImage literal = HdrReader.read(file(concat("#?RADIANCE\n\n-Y 1 +X 2\n", new int[] {128, 0, 0, 129, 1, 1, 1, 1})));
        assertThat(literal.get(1, 0, 0)).isEqualTo(0x1p-135f);
        // a 4x3 picture coded with repeats (1 1 1 3 repeats the pixel before three times): too short when read flat
        Path f = file(concat("#?RADIANCE\n\n-Y 3 +X 4\n", new int[] {128, 0, 0, 129, 1, 1, 1, 3, 128, 0, 0, 129, 1, 1, 1, 3,
            128, 0, 0, 129, 1, 1, 1, 3}));
        assertThatThrownBy(() -> HdrReader.read(f)).isInstanceOf(ImageFormatException.class)
                .hasMessage(f + ":3: the file is truncated: 3 scanlines of 4 pixels need at least 48 bytes, but 24 follow the header"
                        + " (or it uses old-style run-length encoding, pixels 1 1 1 n, which strahl does not read)");
    }

    private static int indexOf(byte[] hay, String needle) {
        return Bytes.indexOf(hay, needle.getBytes(StandardCharsets.US_ASCII));
    }
}
