package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.integrator.IntegratorKind;
import dev.strahl.sampling.HemisphereSampling;
import dev.strahl.viewer.ViewerOptions;
import dev.strahl.viewer.ViewerOptions.Setting;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** {@code strahl view}'s options, without opening a window: which of them win over a scene file's settings. */
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
        assertThat(none.width()).isEqualTo(512);
        assertThat(none.integrator()).isEqualTo(IntegratorKind.PATH);

        ViewerOptions some = parse("view", "s.json", "--width", "300", "--integrator", "whitted", "--spp", "16", "--threads", "1");
        assertThat(some.given()).containsExactlyInAnyOrder(Setting.WIDTH, Setting.INTEGRATOR);
        assertThat(some.width()).isEqualTo(300);
        assertThat(some.integrator()).isEqualTo(IntegratorKind.WHITTED);
        assertThat(some.stopAt()).isEqualTo(16);

        ViewerOptions all = parse("view", "--width", "300", "--height", "200", "--max-depth", "4", "--hemisphere", "uniform",
                "--seed", "3", "--integrator", "direct", "--light-samples", "2");
        assertThat(all.given()).containsExactlyInAnyOrder(Setting.values());
        assertThat(all.hemisphere()).isEqualTo(HemisphereSampling.UNIFORM);
        assertThat(all.lightSamples()).isEqualTo(2);
        assertThat(all.scene()).isNull();

        assertThat(parse("view", "--max-depth", "-1").given()).as("given at its default value is still given")
                .containsExactly(Setting.MAX_DEPTH);
    }
}
