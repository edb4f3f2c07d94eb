package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;
import picocli.CommandLine.Model.ArgGroupSpec;

/** --simd is an option of every command that traces rays, in its "Execution" section, and is parsed there. */
class ExecutionOptionsTest {

    @ParameterizedTest
    @ValueSource(strings = {"render", "view", "worker", "bench"})
    void simdIsInTheExecutionSection(String command) {
        CommandLine sub = Main.commandLine().getSubcommands().get(command);
        List<ArgGroupSpec> execution = sub.getCommandSpec().argGroups().stream()
                .filter(g -> g.heading() != null && g.heading().contains("Execution"))
                .collect(Collectors.toList());
        assertThat(execution).hasSize(1);
        assertThat(execution.get(0).options()).anySatisfy(o -> assertThat(o.longestName()).isEqualTo("--simd"));
    }

    @ParameterizedTest
    @ValueSource(strings = {"render", "view", "worker", "bench"})
    void simdOffIsParsed(String command) {
        CommandLine cl = Main.commandLine();
        String[] args = command.equals("render") ? new String[] {command, "scene.json", "-o", "out.png", "--simd", "off"}
                : command.equals("view") ? new String[] {command, "scene.json", "--simd", "off"} : new String[] {command, "--simd", "off"};
        CommandLine.ParseResult parsed = cl.parseArgs(args);
        assertThat(parsed.subcommand().matchedOptionValue("--simd", SimdOption.Mode.on)).isEqualTo(SimdOption.Mode.off);
    }

    /** --wavefront on sets the property the render jobs read while the command runs, and puts back what was there. */
    @ParameterizedTest
    @ValueSource(strings = {"render", "view", "worker"})
    void wavefrontIsInTheExecutionSectionAndHoldsWhileTheCommandRuns(String command) {
        CommandLine sub = Main.commandLine().getSubcommands().get(command);
        assertThat(sub.getCommandSpec().argGroups()).anySatisfy(g -> {
            assertThat(g.heading()).contains("Execution");
            assertThat(g.options()).anySatisfy(o -> assertThat(o.longestName()).isEqualTo("--wavefront"));
        });
        ExecutionOptions options = new ExecutionOptions();
        new CommandLine(options).parseArgs("--wavefront", "on");
        String before = System.getProperty(dev.strahl.integrator.PathWavefront.PROPERTY);
        try (SimdOption.Scope scope = options.apply()) {
            assertThat(System.getProperty(dev.strahl.integrator.PathWavefront.PROPERTY)).isEqualTo("on");
        }
        assertThat(System.getProperty(dev.strahl.integrator.PathWavefront.PROPERTY)).isEqualTo(before);
        ExecutionOptions none = new ExecutionOptions();
        new CommandLine(none).parseArgs();
        try (SimdOption.Scope scope = none.apply()) {
            assertThat(System.getProperty(dev.strahl.integrator.PathWavefront.PROPERTY)).isEqualTo(before);
        }
    }
}
