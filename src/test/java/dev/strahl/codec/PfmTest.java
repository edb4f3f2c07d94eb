package dev.strahl.codec;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.image.Image;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

class PfmTest {

    @TempDir
    Path dir;

    // IEEE 754 single precision: 1.0 = 3F800000, 2.0 = 40000000, 0.5 = 3F000000,
    // -1.0 = BF800000, 0.25 = 3E800000, 4.0 = 40800000; little-endian puts the low byte first.
    private static final byte[] ONE_LE = {0x00, 0x00, (byte) 0x80, 0x3F};
    private static final byte[] TWO_LE = {0x00, 0x00, 0x00, 0x40};
    private static final byte[] HALF_LE = {0x00, 0x00, 0x00, 0x3F};
    private static final byte[] MINUS_ONE_LE = {0x00, 0x00, (byte) 0x80, (byte) 0xBF};
    private static final byte[] QUARTER_LE = {0x00, 0x00, (byte) 0x80, 0x3E};
    private static final byte[] FOUR_LE = {0x00, 0x00, (byte) 0x80, 0x40};

    private static byte[] concat(Object... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (Object p : parts) {
            byte[] b = p instanceof String s ? s.getBytes(StandardCharsets.US_ASCII) : (byte[]) p;
            out.writeBytes(b);
        }
        return out.toByteArray();
    }

    private static byte[] reversed(byte[] b) {
        byte[] r = new byte[b.length];
        for (int i = 0; i < b.length; i++) {
            r[i] = b[b.length - 1 - i];
        }
        return r;
    }

    private static byte[] encode(Image img) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PfmWriter.write(img, out);
        return out.toByteArray();
    }

    private Path file(String name, byte[] content) throws IOException {
        return Files.write(dir.resolve(name), content);
    }

    private static void assertBitIdentical(Image actual, Image expected) {
        assertThat(actual.width()).isEqualTo(expected.width());
        assertThat(actual.height()).isEqualTo(expected.height());
        float[] a = actual.rgb();
        float[] e = expected.rgb();
        for (int i = 0; i < e.length; i++) {
            assertThat(Float.floatToRawIntBits(a[i])).as("float %d", i).isEqualTo(Float.floatToRawIntBits(e[i]));
        }
    }

    @Test
    void roundTripIsBitExactIncludingRowOrderAndSpecialValues() throws IOException {
        int w = 7;
        int h = 5;
        float[] rgb = new float[3 * w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                for (int c = 0; c < 3; c++) {
                    rgb[3 * (y * w + x) + c] = 100 * y + x + c / 10f;   // top and bottom rows differ
                }
            }
        }
        float[] special = {Float.intBitsToFloat(0x7fc0_1234), -0.0f, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY,
            Float.MIN_VALUE, Float.MAX_VALUE, -1e-30f, 0.1f};
        System.arraycopy(special, 0, rgb, 3 * 2 * w, special.length);   // middle row
        Image img = new Image(w, h, rgb);

        Image back = PfmReader.read(file("gradient.pfm", encode(img)));

        assertBitIdentical(back, img);
        assertThat(back.get(2, 0, 0)).isEqualTo(2f);       // top row stays on top
        assertThat(back.get(2, h - 1, 0)).isEqualTo(402f);
    }

    @Test
    void roundTripOfAFileLargerThanOneWriteChunk() throws IOException {
        int w = 301;
        int h = 307;                                          // 1.1 MB: several chunks, odd row length
        float[] rgb = new float[3 * w * h];
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = i * 0.37f - 5;
        }
        Image img = new Image(w, h, rgb);
        assertBitIdentical(PfmReader.read(file("big.pfm", encode(img))), img);
    }

    @Test
    void writes2x1AsHeaderThenLittleEndianPixelsLeftToRight() throws IOException {
        Image img = new Image(2, 1, new float[] {1, 2, 0.5f, -1, 0.25f, 4});
        byte[] expected = concat("PF\n2 1\n-1.0\n", ONE_LE, TWO_LE, HALF_LE, MINUS_ONE_LE, QUARTER_LE, FOUR_LE);
        assertThat(encode(img)).isEqualTo(expected);
    }

    @Test
    void writes1x2WithTheBottomRowFirst() throws IOException {
        Image img = new Image(1, 2, new float[] {1, 2, 0.5f, /* bottom: */ -1, 0.25f, 4});
        byte[] expected = concat("PF\n1 2\n-1.0\n", MINUS_ONE_LE, QUARTER_LE, FOUR_LE, ONE_LE, TWO_LE, HALF_LE);
        assertThat(encode(img)).isEqualTo(expected);
    }

    @Test
    void readsBigEndianFilesWithTheBottomRowFirst() throws IOException {
        byte[] content = concat("PF\n1 2\n1.0\n", reversed(MINUS_ONE_LE), reversed(QUARTER_LE), reversed(FOUR_LE),
                reversed(ONE_LE), reversed(TWO_LE), reversed(HALF_LE));
        Image img = PfmReader.read(file("be.pfm", content));
        assertThat(img.rgb()).containsExactly(1, 2, 0.5f, -1, 0.25f, 4);
    }

    @Test
    void readsOneChannelFilesAsGray() throws IOException {
        byte[] content = concat("Pf\n2 1\n-1.0\n", HALF_LE, FOUR_LE);
        Image img = PfmReader.read(file("gray.pfm", content));
        assertThat(img.rgb()).containsExactly(0.5f, 0.5f, 0.5f, 4, 4, 4);
    }

    @Test
    void readsOneChannelFilesBottomRowFirst() throws IOException {
        byte[] content = concat("Pf\n1 2\n-1\n", HALF_LE, FOUR_LE);
        Image img = PfmReader.read(file("gray2.pfm", content));
        assertThat(img.rgb()).containsExactly(4, 4, 4, 0.5f, 0.5f, 0.5f);
    }

    @ParameterizedTest
    @ValueSource(strings = {"PF\n2 1\n-1.0\n", "PF 2 1 -1 ", "PF\r\n2 1\r\n-1.0\r\n", "PF\n 2\t1\n\n-1.000000\n",
        "PF\n2 1\n-1\t", "PF\n+2 1\n-1e0\n", "PF\n2 1\n-.5\n"})
    void acceptsHeaderWhitespaceVariants(String header) throws IOException {
        byte[] content = concat(header, ONE_LE, TWO_LE, HALF_LE, MINUS_ONE_LE, QUARTER_LE, FOUR_LE);
        Image img = PfmReader.read(file("ws.pfm", content));
        assertThat(img.rgb()).containsExactly(1, 2, 0.5f, -1, 0.25f, 4);
    }

    @Test
    void aCarriageReturnAfterTheScaleFollowedByALineFeedByteOfPixelDataIsNotACrLf() throws IOException {
        // The float with bits 3F80000A starts with the byte '\n' in little-endian order; the file
        // length shows it is pixel data, not the second half of a CR LF.
        byte[] pixel = {0x0A, 0x00, (byte) 0x80, 0x3F};
        byte[] content = concat("Pf\n1 1\n-1\r", pixel);
        Image img = PfmReader.read(file("cr.pfm", content));
        assertThat(Float.floatToRawIntBits(img.get(0, 0, 0))).isEqualTo(0x3F80000A);
    }

    @Test
    void ignoresBytesAfterThePixelData() throws IOException {
        byte[] content = concat("Pf\n1 1\n-1\n", FOUR_LE, "trailing");
        assertThat(PfmReader.read(file("trail.pfm", content)).rgb()).containsExactly(4, 4, 4);
    }

    static Stream<Arguments> malformed() {
        byte[] twelve = new byte[12];
        return Stream.of(
                Arguments.of("empty file", new byte[0], "truncated PFM header"),
                Arguments.of("other format", concat("P6\n2 1\n255\n", twelve), "not a PFM file"),
                Arguments.of("binary garbage", "x".repeat(5000).getBytes(StandardCharsets.US_ASCII), "not a PFM file"),
                Arguments.of("header ends after tag", concat("PF\n"), "truncated PFM header"),
                Arguments.of("header ends after size", concat("PF\n2 1"), "truncated PFM header"),
                Arguments.of("no whitespace after scale", concat("PF\n2 1\n-1.0"), "truncated PFM header"),
                Arguments.of("header only", concat("PF\n2 1\n-1.0\n"), "truncated PFM data"),
                Arguments.of("truncated data", concat("PF\n2 1\n-1.0\n", new byte[23]), "truncated PFM data"),
                Arguments.of("negative width", concat("PF\n-2 1\n-1.0\n", new byte[24]), "invalid PFM width '-2'"),
                Arguments.of("negative height", concat("PF\n2 -1\n-1.0\n", new byte[24]), "invalid PFM height '-1'"),
                Arguments.of("zero width", concat("PF\n0 1\n-1.0\n", twelve), "invalid PFM width '0'"),
                Arguments.of("width not a number", concat("PF\nabc 1\n-1.0\n", twelve), "invalid PFM width 'abc'"),
                Arguments.of("width beyond int", concat("PF\n99999999999 1\n-1.0\n", twelve), "invalid PFM width"),
                Arguments.of("zero scale", concat("PF\n1 1\n0\n", twelve), "invalid PFM scale '0'"),
                Arguments.of("NaN scale", concat("PF\n1 1\nNaN\n", twelve), "invalid PFM scale 'NaN'"),
                Arguments.of("huge size, short file", concat("PF\n100000 100000\n-1.0\n", twelve), "truncated PFM data"),
                Arguments.of("largest size, short file", concat("PF\n2147483647 2147483647\n-1\n", twelve), "truncated PFM data"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("malformed")
    void malformedInputIsAnImageFormatExceptionNamingTheFile(String what, byte[] content, String message) throws IOException {
        Path f = file("bad.pfm", content);
        assertThatThrownBy(() -> PfmReader.read(f))
                .isExactlyInstanceOf(ImageFormatException.class)
                .hasMessageStartingWith(f + ": ")
                .hasMessageContaining(message);
    }

    @Test
    void aLargeButTooShortFileIsRefusedBeforeAllocating() throws IOException {
        // 20000² pixels would need 4.8 GB of floats, more than the test JVM has: only the
        // size check against the 12-byte file can make this the reader's error instead of an OOM.
        Path f = file("lying.pfm", concat("PF\n20000 20000\n-1\n", new byte[12]));
        assertThatThrownBy(() -> PfmReader.read(f)).isExactlyInstanceOf(ImageFormatException.class).hasMessageContaining("needs 4800000000 bytes");
    }

    @Test
    void missingFilesAndDirectoriesAreIOExceptionsNamingThePath() throws IOException {
        Path missing = dir.resolve("missing.pfm");
        assertThatThrownBy(() -> PfmReader.read(missing)).isInstanceOf(NoSuchFileException.class).hasMessageContaining(missing.toString());
        Path sub = Files.createDirectory(dir.resolve("sub.pfm"));
        assertThatThrownBy(() -> PfmReader.read(sub)).isInstanceOf(IOException.class).hasMessageStartingWith(sub.toString());
    }
}
