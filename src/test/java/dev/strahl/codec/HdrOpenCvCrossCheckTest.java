package dev.strahl.codec;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Pictures written by strahl's HdrWriter, read by OpenCV (docs/anchors/hdr_dump.py via python3):
 * OpenCV must see the same values as HdrReader, flat and run-length encoded. Skipped, saying why,
 * where python3 with OpenCV is not installed.
 */
class HdrOpenCvCrossCheckTest {
    private static final Path DUMP = Path.of("docs", "anchors", "hdr_dump.py");
    private static String unavailable;

    @TempDir
    Path dir;

    @BeforeAll
    static void findOpenCv() {
        try {
            Process p = new ProcessBuilder("python3", "-c", "import cv2, numpy").redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            out = out.substring(out.lastIndexOf('\n') + 1);
            if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
                unavailable = "python3 cannot import cv2 (opencv-python-headless) and numpy: " + out;
            }
        } catch (IOException e) {
            unavailable = "no python3: " + e.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            unavailable = "interrupted";
        }
    }

    @Test
    void openCvReadsWhatStrahlWritesAsStrahlDoes() throws Exception {
        assumeTrue(unavailable == null, () -> unavailable);
        List<String> command = new ArrayList<>(List.of("python3", DUMP.toString()));
        List<Path> files = new ArrayList<>();
        for (int[] size : new int[][] {{1, 1}, {5, 3}, {64, 7}, {300, 2}}) {
            int w = size[0];
            int h = size[1];
            SplittableRandom r = new SplittableRandom(w + 7L * h);
            float[] rgb = new float[3 * w * h];
            for (int i = 0; i < rgb.length; i++) {
                rgb[i] = i % 5 == 0 ? 0.5f : (float) Math.exp(r.nextGaussian() * 4);
            }
            Path f = dir.resolve(w + "x" + h + ".hdr");
            HdrWriter.write(f, w, h, rgb);
            files.add(f);
            command.add(f.toString());
        }
        Process p = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(120, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).isZero();
        String[] lines = out.strip().split("\n");
        assertThat(lines).hasSize(files.size());
        for (int k = 0; k < files.size(); k++) {
            String[] t = lines[k].split(" ");
            assertThat(t[0]).as(lines[k]).isEqualTo("file");
            ChannelImage mine = HdrReader.read(files.get(k));
            assertThat(Integer.parseInt(t[2])).isEqualTo(mine.width());
            assertThat(Integer.parseInt(t[3])).isEqualTo(mine.height());
            float[] data = mine.data();
            for (int i = 0; i < data.length; i++) {
                float theirs = Float.intBitsToFloat(Integer.parseUnsignedInt(t[4 + i], 16));
                assertThat(theirs).as("%s value %d", files.get(k).getFileName(), i).isEqualTo(data[i]);
            }
        }
    }
}
