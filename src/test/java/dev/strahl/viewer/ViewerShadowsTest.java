package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.render.PhotonParameters;
import dev.strahl.render.RenderSettings;
import dev.strahl.io.json.SceneSettings;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.render.IntegratorKind;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The teaching option without shadows reaches the viewer's renders, also of a scene file that chooses its own integrator. */
class ViewerShadowsTest {
    private static ViewerOptions options(boolean shadows) {
        return new ViewerOptions(null, RenderSettings.defaults().withSize(64, 64).withPhotons(new PhotonParameters(1000, 0)).withShadows(shadows),
                0, Theme.SYSTEM, Set.of(), SceneOverrides.NONE);
    }

    @Test
    void shadowsAreOnUnlessTurnedOff() {
        assertThat(ViewerOptions.defaults().settings().transport().shadows()).isTrue();
        assertThat(ViewerOptions.defaults().renderSettings().transport().shadows()).isTrue();
        assertThat(options(true).renderSettings().transport().shadows()).isTrue();
        assertThat(options(false).renderSettings().transport().shadows()).isFalse();
        SceneSettings file = new SceneSettings(32, 32, 8, 3, 1L, IntegratorKind.WHITTED, 2, null, null, null);
        assertThat(options(false).settingsFor(file)).extracting(s -> s.transport().integrator(), s -> s.transport().shadows())
                .containsExactly(IntegratorKind.WHITTED, false);
    }
}
