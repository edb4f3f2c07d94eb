package dev.strahl.io.text;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The kind of a JSON value as both JSON trees name it in their errors. */
class JsonTypesTest {

    @Test
    void everyKindOfValueHasItsName() {
        assertThat(JsonTypes.name(null)).isEqualTo("null");
        assertThat(JsonTypes.name(Map.of())).isEqualTo("an object");
        assertThat(JsonTypes.name(List.of())).isEqualTo("an array");
        assertThat(JsonTypes.name(2.5)).as("glTF's and the scene file's fractions").isEqualTo("a number");
        assertThat(JsonTypes.name(7L)).as("the scene file's whole numbers").isEqualTo("a number");
        assertThat(JsonTypes.name("x")).isEqualTo("a string");
        assertThat(JsonTypes.name(true)).isEqualTo("a boolean");
    }
}
