package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import dev.strahl.render.IntegratorKind;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.io.json.SceneSettings.Setting;
import dev.strahl.viewer.SceneOverrides;
import dev.strahl.viewer.ViewerOptions;
import java.awt.GraphicsEnvironment;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * {@code strahl view}'s options, without opening a window: which of them win over a scene file's
 * settings, and a film too large for the heap refused before anything starts.
 */
class ViewCommandTest {

    static ViewerOptions parse(String... args) {
        CommandLine cl = Main.commandLine();
        cl.parseArgs(args);
        ViewCommand view = cl.getSubcommands().get("view").getCommand();
        return view.options();
    }

    @Test
    void onlyTheOptionsOnTheCommandLineAreGiven() {
        ViewerOptions none = parse("view", "s.json");
        assertThat(none.given()).isEmpty();
        assertThat(none.scene()).isEqualTo(Path.of("s.json"));
        assertThat(none.settings().output().width()).isEqualTo(512);
        assertThat(none.settings().transport().integrator()).isEqualTo(IntegratorKind.PATH);

        ViewerOptions some = parse("view", "s.json", "--width", "300", "--integrator", "whitted", "--spp", "16", "--threads", "1");
        assertThat(some.given()).containsExactlyInAnyOrder(Setting.WIDTH, Setting.INTEGRATOR);
        assertThat(some.settings().output().width()).isEqualTo(300);
        assertThat(some.settings().transport().integrator()).isEqualTo(IntegratorKind.WHITTED);
        assertThat(some.stopAt()).isEqualTo(16);

        ViewerOptions all = parse("view", "--width", "300", "--height", "200", "--max-depth", "4", "--hemisphere", "uniform",
                "--seed", "3", "--integrator", "direct", "--light-samples", "2", "--photons", "7000", "--photon-radius", "0.5",
                "--aov", "depth", "--noise-threshold", "0.02");
        assertThat(all.given()).as("every scene-file setting but spp: view's --spp is the stop-at count, not the file's spp")
                .isEqualTo(EnumSet.complementOf(EnumSet.of(Setting.SAMPLES_PER_PIXEL)));
        assertThat(all.settings().transport().hemisphere()).isEqualTo(HemisphereSampling.UNIFORM);
        assertThat(all.settings().transport().lightSamples()).isEqualTo(2);
        assertThat(all.settings().transport().photons().photonsPerIteration()).isEqualTo(7000);
        assertThat(all.settings().transport().photons().initialRadius()).isEqualTo(0.5);
        assertThat(all.settings().output().aovs()).containsExactly(dev.strahl.render.Aov.DEPTH);
        assertThat(all.settings().sampling().noiseThreshold()).isEqualTo(0.02);
        assertThat(all.scene()).isNull();

        assertThat(parse("view", "--max-depth", "-1").given()).as("given at its default value is still given")
                .containsExactly(Setting.MAX_DEPTH);
    }

    @Test
    void environmentMapAndLensReachTheViewer() {
        assertThat(parse("view", "s.json").overrides()).isEqualTo(SceneOverrides.NONE);
        SceneOverrides o = parse("view", "s.json", "--envmap", "sky.hdr", "--aperture", "0.1", "--focus-distance", "4").overrides();
        assertThat(o).isEqualTo(new SceneOverrides(Path.of("sky.hdr"), 0.1, 4.0));
        assertThat(parse("view", "--aperture", "0").overrides()).isEqualTo(new SceneOverrides(null, 0.0, null));
    }

    @Test
    void anImpossibleLensIsOneLineAndExitCode2() {
        assertRefusedHeadless(RenderCommandTest.strahl("view", "--aperture", "-1"), "--aperture: the lens radius must be finite and >= 0");
        assertRefusedHeadless(RenderCommandTest.strahl("view", "--focus-distance", "0"), "--focus-distance: the distance must be");
    }

    /** Refused before any window opens, so also without a display. */
    private static void assertRefusedHeadless(RenderCommandTest.Run run, String message) {
        assertThat(run.code()).as(run.err()).isEqualTo(2);
        assertThat(run.errLines()).hasSize(1);
        assertThat(run.err()).startsWith("strahl: " + message);
    }

    /**
     * The heap check of {@code render} refuses a film too large for the heap before the viewer
     * starts anything, as one line with exit code 2. Needs a display (without one, {@code view}
     * stops earlier with exit code 1).
     */
    @Test
    @Timeout(value = 60, unit = TimeUnit.SECONDS)                   // without the check, the viewer would open and wait
    void aFilmTooLargeForTheHeapIsOneLineAndExitCode2(@TempDir Path dir) throws Exception {
        assumeTrue(!GraphicsEnvironment.isHeadless(), "no display (headless): run under xvfb-run to include this test");
        assertRefused(RenderCommandTest.strahl("view", "--width", "30000", "--height", "30000"), "30000x30000");

        Files.copy(Path.of("scenes", "cornell-box.obj"), dir.resolve("cornell-box.obj"));
        Files.copy(Path.of("scenes", "cornell-box.mtl"), dir.resolve("cornell-box.mtl"));
        Path huge = Files.writeString(dir.resolve("huge.json"), """
                { "film": { "width": 30000, "height": 30000 }, "shapes": [ { "type": "mesh", "file": "cornell-box.obj" } ] }
                """);
        assertRefused(RenderCommandTest.strahl("view", huge.toString()), "30000x30000");
        assertRefused(RenderCommandTest.strahl("view", huge.toString(), "--height", "20000"), "30000x20000");
    }

    private static void assertRefused(RenderCommandTest.Run run, String size) {
        assertThat(run.code()).as(run.err()).isEqualTo(2);
        assertThat(run.errLines()).hasSize(1);
        assertThat(run.err()).startsWith("strahl: a " + size + " image needs ").contains("for its film and image buffers", "java -Xmx")
                .doesNotContain("Exception");
        assertThat(Thread.getAllStackTraces().keySet()).as("no render thread was started")
                .noneMatch(t -> t.isAlive() && t.getName().startsWith("strahl-render"));
    }
}
