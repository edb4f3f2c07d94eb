package dev.strahl.codec.exr;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Files written by strahl's ExrWriter, read by the OpenEXR library (docs/anchors/exr_dump.py via
 * python3): OpenEXR must see the same channels and the same bits, and numpy's float-to-half
 * conversion of the FLOAT channels must agree with {@link Half#fromFloat}. Skipped, saying why,
 * where python3 with the OpenEXR package is not installed (CI may not have it).
 */
class ExrOpenExrCrossCheckTest {
    private static final Path DUMP = Path.of("docs", "anchors", "exr_dump.py");
    private static String unavailable;

    @TempDir
    Path dir;

    @BeforeAll
    static void findOpenExr() {
        try {
            Process p = new ProcessBuilder("python3", "-c", "import OpenEXR, numpy").redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            out = out.substring(out.lastIndexOf('\n') + 1);        // the error's last line, as "ModuleNotFoundError: ..."
            if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
                unavailable = "python3 cannot import OpenEXR and numpy: " + out;
            }
        } catch (IOException e) {
            unavailable = "no python3: " + e.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            unavailable = "interrupted";
        }
    }

    private record Dumped(int width, int height, int compression, Map<String, String> types, Map<String, int[]> bits,
            Map<String, int[]> asHalf) {}

    private static Map<Path, Dumped> dump(List<Path> files) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of("python3", DUMP.toString()));
        files.forEach(f -> command.add(f.toString()));
        Process p = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(120, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as("exr_dump.py exit code (OpenEXR could not read a file strahl wrote?)").isZero();
        Map<Path, Dumped> result = new HashMap<>();
        Dumped current = null;
        for (String line : out.split("\n")) {
            String[] t = line.split(" ");
            switch (t[0]) {
                case "file" -> {
                    current = new Dumped(Integer.parseInt(t[2]), Integer.parseInt(t[3]), Integer.parseInt(t[4]), new HashMap<>(),
                            new HashMap<>(), new HashMap<>());
                    result.put(Path.of(t[1]), current);
                }
                case "channel" -> {
                    current.types().put(t[1], t[2]);
                    current.bits().put(t[1], hex(t, 3));
                }
                case "as-half" -> current.asHalf().put(t[1], hex(t, 2));
                default -> { }
            }
        }
        return result;
    }

    private static int[] hex(String[] t, int from) {
        int[] v = new int[t.length - from];
        for (int i = 0; i < v.length; i++) {
            v[i] = Integer.parseUnsignedInt(t[from + i], 16);
        }
        return v;
    }

    @Test
    void openExrReadsWhatStrahlWritesBitForBit() throws Exception {
        assumeTrue(unavailable == null, () -> unavailable);
        List<Path> files = new ArrayList<>();
        Map<Path, List<ExrWriter.Channel>> written = new HashMap<>();
        Map<Path, ExrWriter.Options> options = new HashMap<>();
        int[][] sizes = {{1, 1}, {1000, 1}, {37, 19}, {64, 40}};
        int k = 0;
        for (ExrPixelType type : List.of(ExrPixelType.HALF, ExrPixelType.FLOAT)) {
            for (ExrCompression c : List.of(ExrCompression.ZIP, ExrCompression.NONE, ExrCompression.ZIPS, ExrCompression.RLE)) {
                for (int[] s : sizes) {
                    int n = s[0] * s[1];
                    List<ExrWriter.Channel> channels = List.of(new ExrWriter.Channel("R", ExrRoundTripTest.values(n, k, 0)),
                            new ExrWriter.Channel("G", ExrRoundTripTest.values(n, k + 1, 1)),
                            new ExrWriter.Channel("B", ExrRoundTripTest.values(n, k + 2, 2)),
                            new ExrWriter.Channel("depth.Z", ExrRoundTripTest.values(n, k + 3, 1), ExrPixelType.FLOAT),
                            new ExrWriter.Channel("albedo.R", ExrRoundTripTest.values(n, k + 4, 0)));
                    Path f = dir.resolve(type + "-" + c + "-" + s[0] + "x" + s[1] + ".exr");
                    ExrWriter.Options o = new ExrWriter.Options(type, c);
                    ExrWriter.write(f, s[0], s[1], channels, o);
                    files.add(f);
                    written.put(f, channels);
                    options.put(f, o);
                    k += 5;
                }
            }
        }
        Map<Path, Dumped> seen = dump(files);
        for (Path f : files) {
            Dumped d = seen.get(f);
            assertThat(d).as("OpenEXR's view of %s", f).isNotNull();
            ExrWriter.Options o = options.get(f);
            assertThat(d.compression()).isEqualTo(o.compression().code());
            List<ExrWriter.Channel> channels = written.get(f);
            assertThat(d.types().keySet()).containsExactlyInAnyOrder("R", "G", "B", "depth.Z", "albedo.R");
            for (ExrWriter.Channel c : channels) {
                ExrPixelType type = c.type() != null ? c.type() : o.type();
                assertThat(d.types().get(c.name())).as("%s %s", f, c.name()).isEqualTo(type.name());
                int[] bits = d.bits().get(c.name());
                assertThat(bits).hasSize(d.width() * d.height()).hasSize(c.values().length);
                for (int i = 0; i < bits.length; i++) {
                    float v = c.values()[i];
                    int expected = type == ExrPixelType.HALF ? Half.fromFloat(v) : Float.floatToRawIntBits(v);
                    assertThat(Integer.toHexString(bits[i])).as("%s %s sample %d (%s)", f.getFileName(), c.name(), i, v)
                            .isEqualTo(Integer.toHexString(expected));
                }
                if (type == ExrPixelType.FLOAT) {
                    int[] numpyHalf = d.asHalf().get(c.name());
                    for (int i = 0; i < numpyHalf.length; i++) {
                        float v = c.values()[i];
                        int mine = Half.fromFloat(v);
                        if (Float.isNaN(v)) {
                            assertThat(Float.isNaN(Half.toFloat(numpyHalf[i]))).isTrue();
                        } else {
                            assertThat(Integer.toHexString(mine)).as("half of %s: strahl vs numpy", v)
                                    .isEqualTo(Integer.toHexString(numpyHalf[i]));
                        }
                    }
                }
            }
        }
    }
}
