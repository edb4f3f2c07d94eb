package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.integrator.IntegratorKind;
import dev.strahl.sampling.HemisphereSampling;
import java.awt.Dimension;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The small pure pieces of the viewer: letterboxing, status texts, file names, theme names, options. */
class ViewerPartsTest {

    @Test
    void letterboxKeepsTheAspectAndFillsOneSide() {
        assertThat(ImagePanel.fit(724, 512, 1.0)).isEqualTo(new Dimension(512, 512));
        assertThat(ImagePanel.fit(512, 700, 1.0)).isEqualTo(new Dimension(512, 512));
        assertThat(ImagePanel.fit(1000, 1000, 2.0)).isEqualTo(new Dimension(1000, 500));
        assertThat(ImagePanel.fit(1, 1000, 16 / 9.0)).isEqualTo(new Dimension(1, 1));
        assertThat(ImagePanel.fit(1920, 1080, 16 / 9.0)).isEqualTo(new Dimension(1920, 1080));
    }

    @Test
    void statusTexts() {
        assertThat(StatusBar.sppText(12, 64)).isEqualTo("12 / 64 spp");
        assertThat(StatusBar.sppText(12, RenderController.UNLIMITED)).isEqualTo("12 spp");
        assertThat(StatusBar.timeText(0)).isEqualTo("0:00.0");
        assertThat(StatusBar.timeText(75.46)).isEqualTo("1:15.4");
        assertThat(StatusBar.rateText(1_234_567)).isEqualTo("1.23 M samples/s");
        assertThat(StatusBar.rateText(45_600)).isEqualTo("46 k samples/s");
        assertThat(StatusBar.integratorText(IntegratorKind.PATH, -1, HemisphereSampling.UNIFORM)).isEqualTo("path · depth ∞ · uniform");
        assertThat(StatusBar.exposureText(1.5)).isEqualTo("EV +1.5");
        assertThat(StatusBar.exposureText(-0.5)).isEqualTo("EV -0.5");
    }

    @Test
    void saveNamesGetTheFormatsExtension() {
        assertThat(FileActions.defaultName(Path.of("scenes/cornell-box.json"), 64)).isEqualTo("cornell-box-64spp.png");
        assertThat(FileActions.withExtension(Path.of("/tmp/a"), "pfm")).isEqualTo(Path.of("/tmp/a.pfm"));
        assertThat(FileActions.withExtension(Path.of("/tmp/a.PNG"), "pfm")).isEqualTo(Path.of("/tmp/a.PNG"));
        assertThat(FileActions.withExtension(Path.of("/tmp/a.b"), "png")).isEqualTo(Path.of("/tmp/a.b.png"));
    }

    @Test
    void darkThemeNames() {
        assertThat(Theme.isDarkName("Adwaita:dark")).isTrue();
        assertThat(Theme.isDarkName("'Yaru-dark'")).isTrue();
        assertThat(Theme.isDarkName("Breeze-Dark")).isTrue();
        assertThat(Theme.isDarkName("Adwaita")).isFalse();
        assertThat(Theme.isDarkName("Darkling")).isFalse();
        assertThat(Theme.parse("Dark")).isEqualTo(Theme.DARK);
        assertThatThrownBy(() -> Theme.parse("sepia")).hasMessageContaining("system, light or dark");
    }

    @Test
    void optionsAreCheckedWhenMade() {
        ViewerOptions d = ViewerOptions.defaults();
        assertThat(d.renderSettings().samplesPerPass()).isEqualTo(1);
        assertThat(d.integrator()).isEqualTo(IntegratorKind.PATH);
        assertThat(d.renderSettings().integrator()).isEqualTo(IntegratorKind.PATH);
        assertThatThrownBy(() -> new ViewerOptions(null, 0, 512, 0, -1, HemisphereSampling.COSINE, 0, 0, IntegratorKind.PATH, 1, Theme.LIGHT))
                .hasMessageContaining("image size");
        assertThatThrownBy(() -> new ViewerOptions(null, 64, 64, -1, -1, HemisphereSampling.COSINE, 0, 0, IntegratorKind.PATH, 1, Theme.LIGHT))
                .hasMessageContaining("stop-at");
        assertThatThrownBy(() -> new ViewerOptions(null, 64, 64, 0, 0, HemisphereSampling.COSINE, 0, 0, IntegratorKind.PATH, 1, Theme.LIGHT))
                .hasMessageContaining("max depth");
        assertThatThrownBy(() -> new ViewerOptions(null, 64, 64, 0, -1, HemisphereSampling.COSINE, 0, 0, IntegratorKind.DIRECT, 0, Theme.LIGHT))
                .hasMessageContaining("light samples");
    }
}
