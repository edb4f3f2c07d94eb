package dev.strahl.denoise.net;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.testing.Fuzzer;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.Example;

/**
 * Fuzzing of the .tza reader and of building the U-Net from what it read: archives written here
 * (a tiny complete U-Net, a single tensor), mutated — hostile integers over counts, offsets,
 * dimensions and lengths, bytes scrambled, cut short or spliced — may be accepted or refused with
 * a {@link TensorArchiveException}, never end in another exception, a hang or running out of
 * memory. A jqwik example, as {@code ParserFuzzTest}'s, and like its parsers a target of the
 * campaign of docs/reliability/fuzz.sh (named {@code tza}: {@code -Dstrahl.fuzz.only=tza}).
 */
class TensorArchiveFuzzTest {

    static Fuzzer.Target target() {
        return file -> {
            TensorArchive archive = TensorArchive.read(file.getFileName().toString(), Files.readAllBytes(file));
            if (archive.tensors().containsKey("enc_conv0.weight")) {
                new UNet(archive, "fuzz.tza", 9);
            }
        };
    }

    static Arbitrary<byte[]> inputs() {
        List<byte[]> seeds = List.of(TzaFiles.write(TzaFiles.tinyUNet(7)), TensorArchiveTest.one(),
                TzaFiles.write(List.of(new TzaFiles.Entry("b", new int[] {3}, 'h', new float[] {1, 2, 3}))));
        return Combinators.combine(Arbitraries.of(seeds), Arbitraries.longs(), Arbitraries.of(1, 1, 1, 2, 2, 3, 5))
                .as((seed, choice, edits) -> {
                    SplittableRandom r = new SplittableRandom(choice);
                    byte[] b = seed;
                    for (int e = 0; e < edits; e++) {
                        b = edit(b, r);
                    }
                    return b;
                });
    }

    static byte[] edit(byte[] seed, SplittableRandom r) {
        if (seed.length < 9) {
            return seed;
        }
        byte[] b = seed.clone();
        ByteBuffer buf = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
        int at = r.nextInt(b.length - 8);
        switch (r.nextInt(8)) {
            case 0 -> buf.putInt(at, hostile(r));
            case 1 -> buf.putLong(at, r.nextBoolean() ? hostile(r) : r.nextLong(b.length + 16L));
            case 2 -> buf.putShort(at, (short) hostile(r));
            case 3 -> b[at] = (byte) r.nextInt(256);
            case 4 -> {
                return Arrays.copyOf(b, r.nextInt(b.length));              // cut short
            }
            case 5 -> {                                                     // a piece repeated
                int n = 1 + r.nextInt(Math.min(64, b.length - at));
                byte[] longer = Arrays.copyOf(b, b.length + n);
                System.arraycopy(b, at, longer, at + n, b.length - at);
                return longer;
            }
            case 6 -> {                                                     // a word of the format
                byte[] word = List.of("oihw", "x", "f", "h", "enc_conv0.weight", "\u00d7A\u0002").get(r.nextInt(6))
                        .getBytes(StandardCharsets.ISO_8859_1);
                System.arraycopy(word, 0, b, at, Math.min(word.length, b.length - at));
            }
            default -> {
                int n = Math.min(b.length - at, 1 + r.nextInt(16));
                for (int i = 0; i < n; i++) {
                    b[at + i] = (byte) r.nextInt(256);
                }
            }
        }
        return b;
    }

    static int hostile(SplittableRandom r) {
        int[] values = {0, 1, -1, 2, 3, 9, 255, 256, 65535, 65536, Integer.MAX_VALUE, Integer.MIN_VALUE, 0x41D7, 1 << 20};
        return r.nextBoolean() ? values[r.nextInt(values.length)] : r.nextInt();
    }

    @Example
    void tensorArchiveReaderOnlyEverThrowsItsOwnException() throws IOException {
        String only = System.getProperty("strahl.fuzz.only", "");
        if (!only.isEmpty() && !List.of(only.split(",")).contains("tza")) {
            return;                                 // a campaign runs the parsers one by one
        }
        Path dir = Files.createTempDirectory("strahl-fuzz-tza");
        try {
            Fuzzer.Report report = new Fuzzer("tza", target(), TensorArchiveException.class, dir.resolve("fuzz.tza"))
                    .run(inputs(), Fuzzer.budget(), Fuzzer.inputs(), Fuzzer.seed());
            System.out.println(report);
            Path reports = Fuzzer.output().resolve("fuzz-reports");
            Files.createDirectories(reports);
            Files.writeString(reports.resolve("tza.txt"), report + "\n", StandardCharsets.UTF_8);
            assertThat(report.findings()).as(report.toString()).isEmpty();
            assertThat(report.inputs()).as("inputs run").isGreaterThan(100);
            assertThat(report.rejected()).as("some inputs are rejected").isPositive();
            assertThat(report.accepted()).as("some inputs are accepted").isPositive();
        } finally {
            try (var files = Files.list(dir)) {
                for (Path f : files.toList()) {
                    Files.deleteIfExists(f);
                }
            }
            Files.deleteIfExists(dir);
        }
    }
}
