package dev.strahl;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.scene.Scene;
import java.lang.module.ModuleDescriptor;
import org.junit.jupiter.api.Test;

/** The tests run on the module path, and the module exports the API packages and nothing else. */
class ModuleTest {
    private final Module module = Scene.class.getModule();

    @Test
    void theTestsRunInsideTheNamedModule() {
        assertThat(module.isNamed()).isTrue();
        assertThat(module.getName()).isEqualTo("dev.strahl");
        assertThat(ModuleTest.class.getModule()).isSameAs(module);
    }

    @Test
    void exactlyTheApiPackagesAreExported() {
        assertThat(module.getDescriptor().exports()).allMatch(e -> !e.isQualified())
                .extracting(ModuleDescriptor.Exports::source)
                .containsExactlyInAnyOrder("dev.strahl.scene", "dev.strahl.render", "dev.strahl.image", "dev.strahl.io");
        assertThat(module.getDescriptor().packages()).contains("dev.strahl.accel", "dev.strahl.light", "dev.strahl.world", "dev.strahl.cli",
                "dev.strahl.viewer", "dev.strahl.io.json");
    }

    @Test
    void onlyTheCliIsOpenAndOnlyToPicocli() {
        assertThat(module.getDescriptor().opens()).singleElement().satisfies(o -> {
            assertThat(o.source()).isEqualTo("dev.strahl.cli");
            assertThat(o.targets()).containsExactly("info.picocli");
        });
    }
}
