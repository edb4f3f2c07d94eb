package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.io.json.SceneSettings.Setting;
import dev.strahl.render.Aov;
import java.util.EnumSet;
import java.util.HashSet;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** The options that name a scene file's settings: one for every setting, and both commands have each of them. */
class SceneFileOptionsTest {

    @Test
    void everySceneFileSettingHasOneOptionOnBothCommands() {
        assertThat(new HashSet<>(SceneFileOptions.OPTIONS.values())).isEqualTo(EnumSet.allOf(Setting.class));
        assertThat(SceneFileOptions.OPTIONS.values()).doesNotHaveDuplicates();
        CommandLine main = Main.commandLine();
        for (String command : new String[] {"render", "view"}) {
            CommandLine.Model.CommandSpec spec = main.getSubcommands().get(command).getCommandSpec();
            for (String option : SceneFileOptions.OPTIONS.keySet()) {
                assertThat(spec.findOption(option)).as("%s %s", command, option).isNotNull();
            }
        }
    }

    /** view's --aov becomes the viewer's feature buffers, given (so it wins over a file's film.aovs), and a bad name is refused naming the option. */
    @Test
    void viewTakesAovsAsRenderDoes() {
        CommandLine cl = Main.commandLine();
        cl.parseArgs("view", "s.json", "--aov", "albedo,normal");
        ViewCommand view = cl.getSubcommands().get("view").getCommand();
        assertThat(view.options().settings().output().aovs()).containsExactlyInAnyOrder(Aov.ALBEDO, Aov.NORMAL);
        assertThat(view.options().given()).contains(Setting.AOVS);
        cl.parseArgs("view", "s.json", "--aov", "albedo,variance");
        ViewCommand bad = cl.getSubcommands().get("view").getCommand();
        assertThatThrownBy(bad::options).hasMessage("--aov: unknown feature buffer 'variance': use albedo, normal, depth or spp");
    }

    /** --envmap, --aperture and --focus-distance: on both commands, from the one shared definition. */
    @Test
    void environmentAndLensOptionsAreOneDefinitionOnBothCommands() {
        CommandLine main = Main.commandLine();
        for (String command : new String[] {"render", "view"}) {
            CommandLine.Model.CommandSpec spec = main.getSubcommands().get(command).getCommandSpec();
            for (String option : new String[] {"--envmap", "--aperture", "--focus-distance"}) {
                assertThat(spec.findOption(option)).as("%s %s", command, option).isNotNull();
                assertThat(spec.findOption(option).group().typeInfo().getType()).as("%s %s comes from the shared group", command, option)
                        .isIn(EnvironmentOptions.class, LensOptions.class);
            }
        }
    }

    @Test
    void exactlyTheOptionsOnTheCommandLineAreGiven() {
        CommandLine cl = Main.commandLine();
        cl.parseArgs("render", "s.json", "-o", "x.png", "--spp", "64", "--hemisphere", "uniform", "--threads", "2");
        assertThat(SceneFileOptions.given(cl.getSubcommands().get("render").getParseResult()))
                .as("--spp at its default value still counts; --threads names no scene-file setting")
                .containsExactlyInAnyOrder(Setting.SAMPLES_PER_PIXEL, Setting.HEMISPHERE);
    }
}
