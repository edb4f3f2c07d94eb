package dev.strahl.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;

class DurationsTest {
    private final Durations durations = new Durations();

    @ParameterizedTest(name = "{0}")
    @CsvSource({"90, 90000", "90s, 90000", "5m, 300000", "1h30m, 5400000", "500ms, 500", "1.5s, 1500", "PT20S, 20000", "2m30s, 150000"})
    void parsesWhatPeopleWrite(String text, long millis) {
        assertThat(durations.convert(text)).isEqualTo(Duration.ofMillis(millis));
    }

    @ParameterizedTest(name = "[{0}]")
    @ValueSource(strings = {"", "abc", "5x", "m5", "-3s", "0", "1h-2m", "PT-5S"})
    void refusesTheRest(String text) {
        assertThatThrownBy(() -> durations.convert(text)).isInstanceOf(CommandLine.TypeConversionException.class);
    }
}
