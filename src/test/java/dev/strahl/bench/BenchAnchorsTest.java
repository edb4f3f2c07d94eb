package dev.strahl.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The anchors file of {@code bench --anchors}: its figures are read by their paths, and a bad file is one clear message. */
class BenchAnchorsTest {
    @TempDir
    Path dir;

    private Path file(String text) throws IOException {
        Path f = dir.resolve("anchors.json");
        Files.writeString(f, text);
        return f;
    }

    static final String GOOD = """
            {"date": "2026-12-02T19:40:00Z",
             "machine": {"cores": 2, "load_average_at_start": 3.5},
             "mitsuba": {"llvm_ad_rgb": {"version": "3.9.1", "threads": 2, "image_mean": [0.18, 0.12, 0.03],
                                         "samples_per_second": {"median": 5.0e6, "min": 4.9e6, "max": 5.1e6, "runs": 3}},
                         "scalar_rgb": {"samples_per_second": {"median": 1460000, "min": 1, "max": 2, "runs": 3}}},
             "embree": {"binding": "embreex", "meshes": {
                "cornell-box": {"triangles": 36, "build_triangles_per_second": {"median": 2.0e5},
                                "incoherent": {"query": "closest-hit", "rays_per_second": {"median": 1.02e7, "min": 1e7}},
                                "binding_floor_ns_per_ray": {"median": 99.0}},
                "bun_zipper": {"primary": {"rays_per_second": {"median": 1.85e7}}}}}}
            """;

    @Test
    void readsTheFiguresByTheirPaths() throws IOException {
        BenchAnchors a = BenchAnchors.read(file(GOOD));
        assertThat(a.get(BenchAnchors.MITSUBA_LLVM)).isEqualTo(5.0e6);
        assertThat(a.get(BenchAnchors.MITSUBA_SCALAR)).isEqualTo(1.46e6);
        assertThat(a.get(BenchAnchors.embreeRays("cornell-box", "incoherent"))).isEqualTo(1.02e7);
        assertThat(a.get(BenchAnchors.embreeRays("bun_zipper", "primary"))).isEqualTo(1.85e7);
        assertThat(a.get(BenchAnchors.embreeBuild("cornell-box"))).isEqualTo(2.0e5);
        assertThat(a.get(BenchAnchors.embreeRays("cornell-box", "shadow"))).isNaN();      // not in the file: no anchor
        assertThat(a.size()).isEqualTo(5);                                                 // the floor and the min are not anchors
        assertThat(a.sideBySide()).isTrue();
        assertThat(a.source()).contains("anchors.json").contains("2026-12-02T19:40:00Z");
    }

    @Test
    void theConstantsAreTheFallback() {
        BenchAnchors a = BenchAnchors.fallback();
        assertThat(a.sideBySide()).isFalse();
        assertThat(a.get(BenchAnchors.MITSUBA_LLVM)).isEqualTo(4.0e6);
        assertThat(a.get(BenchAnchors.embreeRays("cornell-box", "incoherent"))).isEqualTo(7.5e6);
    }

    @Test
    void targetsTakeTheFilesFiguresAndLeaveOutTheMissingOnes() throws IOException {
        BenchResults r = new BenchResults();
        r.anchors = BenchAnchors.read(file(GOOD));
        BenchResults.Stat s = BenchResults.Stat.of(new double[] {6.0e6});
        r.cornell.add(new BenchResults.Render(2, BenchResults.Stat.of(new double[] {2.5e6}), s, 5.7));
        r.meshes.add(new BenchResults.Mesh("cornell-box", "x.obj", 36, 0, BenchResults.Stat.of(new double[] {1e-4}), 0,
                List.of(new BenchResults.Rays("incoherent", 1, BenchResults.Stat.of(new double[] {5.1e6}), 1, 1),
                        new BenchResults.Rays("shadow", 1, s, 1, 1)), "passed"));
        BenchReport.targets(r, 1, 2);
        assertThat(r.targets).extracting(BenchResults.Target::name).containsExactly("Cornell Box samples/s, 2 threads",
                "Cornell Box samples/s, 2 threads", "cornell-box incoherent closest-hit rays/s, 1 thread", "cornell-box BVH build triangles/s, 0 threads");
        assertThat(r.targets.get(0).ratio()).isEqualTo(0.5);
        assertThat(r.targets.get(0).anchorSource()).contains("side by side");
        assertThat(r.targets.get(2).ratio()).isCloseTo(0.5, org.assertj.core.api.Assertions.within(1e-12));
        assertThat(r.targets.get(2).reached()).isFalse();                    // goal: 1.0× Embree
    }

    @Test
    void aBadFileIsOneLineNamingTheFileAndThePlace() throws IOException {
        assertThatThrownBy(() -> BenchAnchors.read(dir.resolve("none.json"))).hasMessage(dir.resolve("none.json") + ": no such file");
        assertThatThrownBy(() -> BenchAnchors.read(file("{\"mitsuba\": {\"llvm_ad_rgb\": \n  {\"samples_per_second\": {\"median\": }}}}")))
                .hasMessageStartingWith(dir.resolve("anchors.json") + ": line 2, column").hasMessageContaining("not valid JSON")
                .satisfies(e -> assertThat(e.getMessage()).doesNotContain("\n"));
        assertThatThrownBy(() -> BenchAnchors.read(file("{\"mitsuba\": {\"llvm_ad_rgb\": {\"samples_per_second\": {\"median\": -5}}}}")))
                .hasMessageContaining("line 1, column").hasMessageContaining("mitsuba.llvm_ad_rgb.samples_per_second.median must be a positive number, got -5");
        assertThatThrownBy(() -> BenchAnchors.read(file("{\"embree\": {\"meshes\": {\"m\": {\"primary\": {\"rays_per_second\": {\"median\": \"fast\"}}}}}}")))
                .hasMessageContaining("embree.meshes.m.primary.rays_per_second.median must be a positive number, got fast");
        assertThatThrownBy(() -> BenchAnchors.read(file("{\"date\": \"today\", \"other\": {\"median\": 3}}")))
                .hasMessageContaining("no anchor figures").hasMessageContaining("anchors.py");
        assertThatThrownBy(() -> BenchAnchors.read(file("[1, 2]"))).hasMessageContaining("expected a JSON object");
        assertThatThrownBy(() -> BenchAnchors.read(file(""))).hasMessageContaining("anchors.json");
    }
}
