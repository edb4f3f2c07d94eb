package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import dev.strahl.cli.RenderCommandTest.Run;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code render --stats} and {@code strahl bench}: the figures are written, complete and checked. */
class BenchCommandTest {

    @TempDir
    Path dir;

    /** The scalar fields of a flat JSON object (and the first level of nested ones, as "outer.inner"). */
    private static Map<String, String> fields(Path file) throws IOException {
        Map<String, String> out = new HashMap<>();
        try (JsonParser p = new JsonFactory().createParser(file.toFile())) {
            String prefix = "";
            int depth = 0;
            String name = null;
            for (JsonToken t = p.nextToken(); t != null; t = p.nextToken()) {
                switch (t) {
                    case START_OBJECT, START_ARRAY -> {
                        depth++;
                        if (depth == 2 && name != null) {
                            prefix = name + ".";
                        }
                    }
                    case END_OBJECT, END_ARRAY -> {
                        depth--;
                        if (depth <= 1) {
                            prefix = "";
                        }
                    }
                    case FIELD_NAME -> name = p.currentName();
                    default -> {
                        if (name != null && !out.containsKey(prefix + name)) {
                            out.put(prefix + name, p.getText());
                        }
                    }
                }
            }
        }
        return out;
    }

    @Test
    void renderStatsWritesEveryFigure() throws Exception {
        Path stats = dir.resolve("stats.json");
        Run r = RenderCommandTest.render(RenderCommandTest.CORNELL, dir.resolve("img.png"), "--stats", stats.toString(), "--threads", "2", "-q");
        assertThat(r.code()).as(r.err()).isZero();
        Map<String, String> f = fields(stats);
        assertThat(f.keySet()).contains("seconds", "samples", "samples_per_second", "rays", "rays_per_second", "threads", "width", "height",
                "spp", "bvh_build_seconds", "load_seconds");
        assertThat(Long.parseLong(f.get("samples"))).isEqualTo(16 * 16 * 4);
        assertThat(Long.parseLong(f.get("rays"))).isGreaterThan(16 * 16 * 4);
        assertThat(f.get("threads")).isEqualTo("2");
        assertThat(f.get("width")).isEqualTo("16");
        assertThat(f.get("spp")).isEqualTo("4");
        double seconds = Double.parseDouble(f.get("seconds"));
        assertThat(seconds).isPositive();
        assertThat(Double.parseDouble(f.get("samples_per_second"))).isCloseTo(16 * 16 * 4 / seconds, org.assertj.core.api.Assertions.within(1e-6 * 1024 / seconds));
        assertThat(Double.parseDouble(f.get("bvh_build_seconds"))).isNotNegative();
        assertThat(Double.parseDouble(f.get("load_seconds"))).isNotNegative();
    }

    @Test
    void renderStatsIntoAMissingDirectoryIsRefusedBeforeRendering() {
        Run r = RenderCommandTest.render(RenderCommandTest.CORNELL, dir.resolve("img.png"), "--stats", dir.resolve("no/such/stats.json").toString());
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.errLines()).hasSize(1);
        assertThat(r.err()).contains("--stats").contains("does not exist");
        assertThat(Files.exists(dir.resolve("img.png"))).isFalse();
    }

    @Test
    void benchMeasuresAndChecksAMesh() throws Exception {
        Path json = dir.resolve("bench.json");
        Run r = RenderCommandTest.strahl("bench", "--quick", "--no-cornell", "--mesh", "scenes/cornell-box.obj",
                "--mesh", dir.resolve("missing.ply").toString(), "--rays", "4096", "--threads", "1,2", "--json", json.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("Meshes").contains("cornell-box").contains("primary").contains("incoherent").contains("shadow")
                .contains("skipped: missing").contains("Targets");
        Map<String, String> f = fields(json);
        assertThat(f.get("machine.cores")).isEqualTo(String.valueOf(Runtime.getRuntime().availableProcessors()));
        assertThat(f).containsKeys("machine.cpu", "machine.jvm", "date");
        String text = Files.readString(json);
        assertThat(text).contains("\"check\" : \"passed\"").contains("\"threads\" : 1").contains("\"threads\" : 2")
                .contains("\"set\" : \"shadow\"").contains("\"query\" : \"any-hit\"").contains("bytes_per_triangle");
    }

    @Test
    void benchRendersAndChecksTheCornellBox() throws Exception {
        Run r = RenderCommandTest.strahl("bench", "--quick", "--mesh", dir.resolve("none.ply").toString(), "--threads", "2");
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("Cornell Box").contains("samples/s").contains("check: image mean").contains(": passed")
                .contains("viewer preview").contains("Mitsuba 3 LLVM");
    }

    @Test
    void benchComparesWithTheAnchorsFileAndExportsItsRays() throws Exception {
        Path anchors = dir.resolve("anchors.json");
        Files.writeString(anchors, "{\"date\": \"d1\", \"embree\": {\"meshes\": {\"cornell-box\": "
                + "{\"incoherent\": {\"rays_per_second\": {\"median\": 1234567.0}}}}}}");
        Run r = RenderCommandTest.strahl("bench", "--quick", "--no-cornell", "--mesh", "scenes/cornell-box.obj", "--rays", "4096",
                "--threads", "1", "--anchors", anchors.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(r.out()).contains("Anchors: " + anchors + " (d1)").contains("1.23 M").contains("Embree 4, per core, side by side")
                .doesNotContain("Mitsuba");                                   // not in the file: no target

        Path rays = Files.createDirectory(dir.resolve("rays"));
        r = RenderCommandTest.strahl("bench", "--mesh", "scenes/cornell-box.obj", "--rays", "1000", "--export-rays", rays.toString());
        assertThat(r.code()).as(r.err()).isZero();
        assertThat(Files.size(rays.resolve("cornell-box.triangles.f32"))).isEqualTo(36 * 36);
        assertThat(Files.size(rays.resolve("cornell-box.incoherent.f32"))).isEqualTo(1000 * 28);
        assertThat(Files.size(rays.resolve("cornell-box.shadow.f32"))).isEqualTo(1000 * 28);
        assertThat(Files.size(rays.resolve("cornell-box.primary.f32"))).isEqualTo(15 * 15 * 4 * 28);
        assertThat(Files.readString(rays.resolve("cornell-box.json"))).contains("\"any_hit\" : true").contains("\"triangles\" : 36");
    }

    @Test
    void aBadAnchorsFileIsOneLineAndExitCode2() throws Exception {
        Path bad = dir.resolve("bad.json");
        Files.writeString(bad, "{\"mitsuba\": {\"llvm_ad_rgb\": {\"samples_per_second\": {\"median\": 0}}}}");
        Run r = RenderCommandTest.strahl("bench", "--quick", "--no-cornell", "--mesh", "scenes/cornell-box.obj", "--anchors", bad.toString());
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.errLines()).hasSize(1);
        assertThat(r.err()).contains("--anchors " + bad + ": line 1").contains("must be a positive number, got 0");
        r = RenderCommandTest.strahl("bench", "--anchors", dir.resolve("missing.json").toString());
        assertThat(r.code()).isEqualTo(2);
        assertThat(r.errLines()).containsExactly("strahl: --anchors " + dir.resolve("missing.json") + ": no such file");
        assertThat(RenderCommandTest.strahl("bench", "--export-rays", dir.resolve("nowhere").toString()).code()).isEqualTo(2);
    }

    @Test
    void benchRefusesBadOptions() {
        assertThat(RenderCommandTest.strahl("bench", "--runs", "0").code()).isEqualTo(2);
        assertThat(RenderCommandTest.strahl("bench", "--threads", "0").code()).isEqualTo(2);
        assertThat(RenderCommandTest.strahl("bench", "--rays", "-3").code()).isEqualTo(2);
    }
}
