package dev.strahl.codec.exr;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.codec.ChannelImage;
import dev.strahl.codec.ImageFormatException;
import dev.strahl.testing.Bytes;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** ExrWriter → ExrReader: every value comes back (FLOAT bit for bit, HALF as its nearest half). */
class ExrRoundTripTest {
    @TempDir
    Path dir;

    static Stream<Arguments> kinds() {
        List<Arguments> out = new ArrayList<>();
        for (ExrPixelType type : List.of(ExrPixelType.HALF, ExrPixelType.FLOAT)) {
            for (ExrCompression c : List.of(ExrCompression.ZIP, ExrCompression.NONE, ExrCompression.ZIPS, ExrCompression.RLE)) {
                for (int[] size : new int[][] {{1, 1}, {1000, 1}, {1, 40}, {37, 19}, {64, 33}}) {
                    out.add(Arguments.of(type, c, size[0], size[1]));
                }
            }
        }
        return out.stream();
    }

    /** Smooth ramps (which compress), noise (which does not), and the special values. */
    static float[] values(int n, long seed, int style) {
        SplittableRandom r = new SplittableRandom(seed);
        float[] v = new float[n];
        float[] special = {0f, -0f, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NaN, 65504f, 65520f, 1e-8f, -3e38f,
            Float.MIN_VALUE, 0x1p-24f, 1f / 3};
        for (int i = 0; i < n; i++) {
            v[i] = switch (style) {
                case 0 -> i * 0.01f;
                case 1 -> (float) r.nextGaussian() * 100;
                default -> i % 7 == 0 ? special[r.nextInt(special.length)] : Float.intBitsToFloat(r.nextInt());
            };
        }
        return v;
    }

    static float expected(float v, ExrPixelType type) {
        return type == ExrPixelType.HALF ? Half.toFloat(Half.fromFloat(v)) : v;
    }

    @ParameterizedTest(name = "{0} {1} {2}x{3}")
    @MethodSource("kinds")
    void everyValueComesBack(ExrPixelType type, ExrCompression compression, int w, int h) throws IOException {
        List<ExrWriter.Channel> channels = List.of(new ExrWriter.Channel("R", values(w * h, 1, 0)),
                new ExrWriter.Channel("G", values(w * h, 2, 1)), new ExrWriter.Channel("B", values(w * h, 3, 2)));
        Path file = dir.resolve("t.exr");
        ExrWriter.write(file, w, h, channels, new ExrWriter.Options(type, compression));
        ExrReader.ExrImage read = ExrReader.readFile(file);
        assertThat(read.header().compression()).isEqualTo(compression);
        assertThat(read.header().dataWindow()).isEqualTo(new ExrHeader.Box(0, 0, w - 1, h - 1));
        assertThat(read.header().channels()).extracting(ExrHeader.Channel::type).containsOnly(type);
        ChannelImage img = read.pixels();
        assertThat(img.channels()).containsExactly("B", "G", "R");
        assertThat(img.width()).isEqualTo(w);
        assertThat(img.height()).isEqualTo(h);
        for (int c = 0; c < 3; c++) {
            float[] in = channels.get(2 - c).values();       // B G R in the file, R G B given
            for (int p = 0; p < w * h; p++) {
                float e = expected(in[p], type);
                float a = img.data()[p * 3 + c];
                assertThat(Float.floatToIntBits(a)).as("channel %d pixel %d: %s, expected %s", c, p, a, e)
                        .isEqualTo(Float.floatToIntBits(e));
            }
        }
    }

    @Test
    void manyChannelsWithLongNamesAndTheirOwnTypes() throws IOException {
        int w = 13;
        int h = 21;
        List<ExrWriter.Channel> channels = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            String name = i % 5 == 0 ? "a.rather.long.layer.name.for.channel." + i : "c" + (char) ('A' + i % 26) + i;
            channels.add(new ExrWriter.Channel(name, values(w * h, i, i % 3), i % 2 == 0 ? ExrPixelType.FLOAT : null));
        }
        Path file = dir.resolve("many.exr");
        ExrWriter.write(file, w, h, channels, ExrWriter.Options.DEFAULT);
        ChannelImage img = ExrReader.read(file);
        List<String> sorted = channels.stream().map(ExrWriter.Channel::name).sorted().toList();
        assertThat(img.channels()).containsExactlyElementsOf(sorted);
        for (ExrWriter.Channel c : channels) {
            int k = img.channel(c.name());
            ExrPixelType type = c.type() != null ? c.type() : ExrPixelType.HALF;
            for (int p = 0; p < w * h; p++) {
                assertThat(Float.floatToIntBits(img.data()[p * 40 + k])).isEqualTo(Float.floatToIntBits(expected(c.values()[p], type)));
            }
        }
        assertThat(ByteBuffer.wrap(Files.readAllBytes(file), 4, 4).order(ByteOrder.LITTLE_ENDIAN).getInt())
                .as("version 2 with the long-names flag").isEqualTo(0x402);
    }

    @Test
    void aChannelImageRoundTripsWithItsNames() throws IOException {
        float[] data = values(5 * 3 * 4, 9, 0);
        ChannelImage img = new ChannelImage(5, 3, List.of("R", "G", "B", "A"), data);
        Path file = dir.resolve("img.exr");
        ExrWriter.write(file, img, new ExrWriter.Options(ExrPixelType.FLOAT, ExrCompression.ZIP));
        ChannelImage back = ExrReader.read(file).select("R", "G", "B", "A");
        assertThat(back.data()).containsExactly(data);
        assertThat(ExrReader.read(file).rgba().data()).containsExactly(data);
    }

    @Test
    void smoothImagesAreCompressedAndNoiseIsStoredRaw() throws IOException {
        int w = 64;
        int h = 64;
        Path smooth = dir.resolve("smooth.exr");
        ExrWriter.write(smooth, w, h, List.of(new ExrWriter.Channel("Y", values(w * h, 1, 0))), ExrWriter.Options.DEFAULT);
        assertThat(ExrReader.readFile(smooth).compressedChunks()).isEqualTo(4);
        assertThat(Files.size(smooth)).isLessThan(w * h * 2 / 2);
        Path noise = dir.resolve("noise.exr");
        float[] random = new float[w * h];
        SplittableRandom r = new SplittableRandom(3);
        for (int i = 0; i < random.length; i++) {
            random[i] = Float.intBitsToFloat(r.nextInt());
        }
        ExrWriter.write(noise, w, h, List.of(new ExrWriter.Channel("Y", random)), new ExrWriter.Options(ExrPixelType.FLOAT,
                ExrCompression.ZIP));
        assertThat(ExrReader.readFile(noise).compressedChunks()).as("random bits do not compress: stored raw").isZero();
    }

    @Test
    void badArgumentsAreRefused() {
        float[] four = new float[4];
        assertThatThrownBy(() -> ExrWriter.write(dir.resolve("x.exr"), 2, 3, List.of(new ExrWriter.Channel("R", four)),
                ExrWriter.Options.DEFAULT)).isInstanceOf(IllegalArgumentException.class).hasMessageContaining("has 4 values");
        assertThatThrownBy(() -> ExrWriter.write(dir.resolve("x.exr"), 2, 2, List.of(new ExrWriter.Channel("R", four),
                new ExrWriter.Channel("R", four)), ExrWriter.Options.DEFAULT)).hasMessageContaining("twice");
        assertThatThrownBy(() -> new ExrWriter.Channel("", four)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new ExrWriter.Channel("x".repeat(256), four)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new ExrWriter.Options(ExrPixelType.HALF, ExrCompression.PIZ))
                .hasMessage("strahl writes EXR compression NONE, RLE, ZIPS or ZIP, not PIZ");
        assertThat(dir.resolve("x.exr")).doesNotExist();
    }

    // ---- broken files ------------------------------------------------------------------------

    private Path written(ExrCompression compression) throws IOException {
        Path file = dir.resolve("ok.exr");
        ExrWriter.write(file, 30, 40, List.of(new ExrWriter.Channel("Y", values(1200, 4, 0))),
                new ExrWriter.Options(ExrPixelType.HALF, compression));
        return file;
    }

    private Path withBytes(byte[] b) throws IOException {
        return Files.write(dir.resolve("bad.exr"), b);
    }

    @Test
    void truncatedFilesAreRefusedNamingTheFileAndPlace() throws IOException {
        for (ExrCompression c : List.of(ExrCompression.NONE, ExrCompression.ZIP, ExrCompression.RLE)) {
            byte[] ok = Files.readAllBytes(written(c));
            for (int cut : new int[] {0, 3, 7, 20, 300, ok.length / 2, ok.length - 1}) {
                Path bad = withBytes(Arrays.copyOf(ok, cut));
                assertThatThrownBy(() -> ExrReader.read(bad)).as("%s cut at %d", c, cut).isInstanceOf(ImageFormatException.class)
                        .hasMessageStartingWith(bad + ": ").hasMessageNotContaining("\n");
            }
        }
        Path cut = withBytes(Arrays.copyOf(Files.readAllBytes(written(ExrCompression.NONE)), 600));
        assertThatThrownBy(() -> ExrReader.read(cut)).hasMessageContaining("truncated");
    }

    @Test
    void corruptHeadersAndChunksGiveClearErrors() throws IOException {
        byte[] ok = Files.readAllBytes(written(ExrCompression.ZIP));
        byte[] notExr = ok.clone();
        notExr[0] = 'P';
        assertThatThrownBy(() -> ExrReader.read(withBytes(notExr))).hasMessageEndingWith(
                "not an OpenEXR file (it does not start with the magic number 76 2f 31 01)");
        byte[] tiled = ok.clone();
        tiled[5] |= 0x02;
        assertThatThrownBy(() -> ExrReader.read(withBytes(tiled))).hasMessageContaining("tiled EXR files are not supported");
        byte[] deep = ok.clone();
        deep[5] |= 0x08;
        assertThatThrownBy(() -> ExrReader.read(withBytes(deep))).hasMessageContaining("deep EXR files are not supported");

        // corrupt zlib data in the last chunk
        byte[] corrupt = ok.clone();
        for (int i = corrupt.length - 20; i < corrupt.length; i++) {
            corrupt[i] ^= 0x5a;
        }
        assertThatThrownBy(() -> ExrReader.read(withBytes(corrupt))).isInstanceOf(ImageFormatException.class)
                .hasMessageContaining("chunk 2 (y = 32, ZIP): zlib data");
    }

    @Test
    void anAbsurdDataWindowIsRefusedBeforeAllocating() throws IOException {
        byte[] ok = Files.readAllBytes(written(ExrCompression.ZIP));
        byte[] huge = ok.clone();
        int at = Bytes.indexOf(huge, "dataWindow\0box2i\0".getBytes(java.nio.charset.StandardCharsets.US_ASCII)) + 17 + 4;
        ByteBuffer.wrap(huge).order(ByteOrder.LITTLE_ENDIAN).putInt(at + 8, 2_000_000_000).putInt(at + 12, 1);
        assertThatThrownBy(() -> ExrReader.read(withBytes(huge))).isInstanceOf(ImageFormatException.class)
                .hasMessageContaining("more than this " + huge.length + "-byte file can hold with ZIP compression");
        ByteBuffer.wrap(huge).order(ByteOrder.LITTLE_ENDIAN).putInt(at + 8, 29).putInt(at + 12, 2_000_000_000);
        assertThatThrownBy(() -> ExrReader.read(withBytes(huge))).isInstanceOf(ImageFormatException.class)
                .hasMessageContaining("the file is truncated: the data window (0, 0) - (29, 2000000000) needs 125000001 chunks");
        ByteBuffer.wrap(huge).order(ByteOrder.LITTLE_ENDIAN).putInt(at + 8, -5);
        assertThatThrownBy(() -> ExrReader.read(withBytes(huge))).hasMessageContaining("is empty");
    }
}
