package dev.strahl.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.scene.SceneException;
import dev.strahl.io.json.SceneSettings;
import dev.strahl.io.json.SceneSettings.Setting;
import java.awt.Dimension;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import javax.swing.JComboBox;
import javax.swing.JMenu;
import javax.swing.JRadioButtonMenuItem;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The small pure pieces of the viewer: letterboxing, status texts, file names, theme names, options, choices. */
class ViewerPartsTest {
    /** A scene file that sets every film and integrator key. */
    static final SceneSettings FILE = new SceneSettings(320, 160, 8, 3, 42L, IntegratorKind.DIRECT, 4, HemisphereSampling.UNIFORM, null, null);
    static final Path SCENE = Path.of("s.json");

    @TempDir
    Path dir;

    static ViewerOptions options(Set<Setting> given) {
        return new ViewerOptions(null, RenderSettings.defaults().withSize(200, 100).withMaxDepth(5).withThreads(2).withSeed(9).withIntegrator(IntegratorKind.WHITTED).withLightSamples(2),
                256, Theme.LIGHT, given, SceneOverrides.NONE);
    }

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
        assertThat(d.renderSettings().execution().samplesPerPass()).isEqualTo(1);
        assertThat(d.settings().transport().integrator()).isEqualTo(IntegratorKind.PATH);
        assertThat(d.renderSettings().transport().integrator()).isEqualTo(IntegratorKind.PATH);
        assertThatThrownBy(() -> new ViewerOptions(null, RenderSettings.defaults().withSize(0, 512),
                0, Theme.LIGHT, Set.of(), SceneOverrides.NONE))
                .hasMessageContaining("image size");
        assertThatThrownBy(() -> new ViewerOptions(null, RenderSettings.defaults().withSize(64, 64),
                -1, Theme.LIGHT, Set.of(), SceneOverrides.NONE))
                .hasMessageContaining("stop-at");
        assertThatThrownBy(() -> new ViewerOptions(null, RenderSettings.defaults().withSize(64, 64).withMaxDepth(0),
                0, Theme.LIGHT, Set.of(), SceneOverrides.NONE))
                .hasMessageContaining("max depth");
        assertThatThrownBy(() -> new ViewerOptions(null, RenderSettings.defaults().withSize(64, 64).withIntegrator(IntegratorKind.DIRECT).withLightSamples(0),
                0, Theme.LIGHT, Set.of(), SceneOverrides.NONE))
                .hasMessageContaining("light samples");
    }

    @Test
    void aSceneFilesSettingsReplaceTheOptionsNotGiven() throws Exception {
        RenderSettings s = options(Set.of()).settingsFor(FILE);
        assertThat(s.output().width()).isEqualTo(320);
        assertThat(s.output().height()).isEqualTo(160);
        assertThat(s.transport().integrator()).isEqualTo(IntegratorKind.DIRECT);
        assertThat(s.transport().maxDepth()).isEqualTo(3);
        assertThat(s.sampling().seed()).isEqualTo(42);
        assertThat(s.transport().lightSamples()).isEqualTo(4);
        assertThat(s.transport().hemisphere()).isEqualTo(HemisphereSampling.UNIFORM);
        assertThat(s.execution().threads()).as("not a scene-file key").isEqualTo(2);
        assertThat(s.execution().samplesPerPass()).isEqualTo(1);
        assertThat(s.sampling().samplesPerPixel()).as("the file's spp is not the viewer's stop-at count")
                .isEqualTo(options(Set.of()).renderSettings().sampling().samplesPerPixel());
        assertThat(options(Set.of()).settingsFor(SceneSettings.NONE)).as("a file that says nothing")
                .isEqualTo(options(Set.of()).renderSettings());
    }

    @Test
    void optionsGivenExplicitlyWinOverTheSceneFile() throws Exception {
        RenderSettings all = options(EnumSet.allOf(Setting.class)).settingsFor(FILE);
        assertThat(all).isEqualTo(options(Set.of()).renderSettings());

        RenderSettings widthOnly = options(Set.of(Setting.WIDTH)).settingsFor(FILE);
        assertThat(widthOnly.output().width()).isEqualTo(200);
        assertThat(widthOnly.output().height()).as("the file's height with the given width, as render does").isEqualTo(160);
        assertThat(widthOnly.transport().integrator()).isEqualTo(IntegratorKind.DIRECT);
        assertThat(options(Set.of(Setting.HEIGHT)).settingsFor(FILE).output().width()).isEqualTo(320);
        assertThat(options(Set.of(Setting.HEIGHT)).settingsFor(FILE).output().height()).isEqualTo(100);

        // Each one alone: that setting from the option, every other one from the file
        RenderSettings fromFile = options(Set.of()).settingsFor(FILE);
        RenderSettings fromOptions = options(Set.of()).renderSettings();
        assertThat(options(Set.of(Setting.MAX_DEPTH)).settingsFor(FILE)).isEqualTo(fromFile.withMaxDepth(fromOptions.transport().maxDepth()));
        assertThat(options(Set.of(Setting.HEMISPHERE)).settingsFor(FILE)).isEqualTo(fromFile.withHemisphere(fromOptions.transport().hemisphere()));
        assertThat(options(Set.of(Setting.SEED)).settingsFor(FILE)).isEqualTo(fromFile.withSeed(fromOptions.sampling().seed()));
        assertThat(options(Set.of(Setting.INTEGRATOR)).settingsFor(FILE)).isEqualTo(fromFile.withIntegrator(fromOptions.transport().integrator()));
        assertThat(options(Set.of(Setting.LIGHT_SAMPLES)).settingsFor(FILE))
                .isEqualTo(fromFile.withLightSamples(fromOptions.transport().lightSamples()));
    }

    @Test
    void openingASceneFileCombinesItsSettingsWithTheOptions() throws Exception {
        Files.copy(Path.of("scenes", "cornell-box.obj"), dir.resolve("cornell-box.obj"));
        Files.copy(Path.of("scenes", "cornell-box.mtl"), dir.resolve("cornell-box.mtl"));
        Path file = Files.writeString(dir.resolve("s.json"), """
                { "film": { "width": 96, "height": 48 },
                  "integrator": { "type": "direct", "maxDepth": 7, "spp": 3 },
                  "shapes": [ { "type": "mesh", "file": "cornell-box.obj" } ] }
                """);
        List<Dimension> checked = new ArrayList<>();
        SceneFiles.Opened opened = SceneFiles.open(file, ViewerOptions.defaults(), (w, h, features) -> checked.add(new Dimension(w, h)));
        assertThat(opened.file()).isEqualTo(file);
        assertThat(opened.settings().output().width()).isEqualTo(96);
        assertThat(opened.settings().output().height()).isEqualTo(48);
        assertThat(opened.settings().transport().integrator()).isEqualTo(IntegratorKind.DIRECT);
        assertThat(opened.settings().transport().maxDepth()).isEqualTo(7);
        assertThat(opened.settings().sampling().samplesPerPixel()).as("the viewer renders on: not the file's spp").isNotEqualTo(3);
        assertThat(checked).as("the film check sees the size the settings ask for").containsExactly(new Dimension(96, 48));
    }

    @Test
    void aFilmThatFailsTheCheckIsRefusedWithItsMessage() throws Exception {
        Files.copy(Path.of("scenes", "cornell-box.obj"), dir.resolve("cornell-box.obj"));
        Files.copy(Path.of("scenes", "cornell-box.mtl"), dir.resolve("cornell-box.mtl"));
        Path huge = Files.writeString(dir.resolve("huge.json"), """
                { "film": { "width": 30000, "height": 20000 }, "shapes": [ { "type": "mesh", "file": "cornell-box.obj" } ] }
                """);
        Viewer.FilmCheck atMost4k = (w, h, features) -> {
            if (w > 4096 || h > 4096) {
                throw new IllegalArgumentException("a " + w + "x" + h + " image is too large");
            }
        };
        assertThatThrownBy(() -> SceneFiles.open(huge, ViewerOptions.defaults(), atMost4k))
                .isInstanceOf(IllegalArgumentException.class).hasMessage("a 30000x20000 image is too large");
        assertThat(SceneFiles.open(huge, options(Set.of(Setting.WIDTH, Setting.HEIGHT)), atMost4k).settings().output().width())
                .as("--width and --height given win over the file's film, and pass").isEqualTo(200);
        assertThatThrownBy(() -> SceneFiles.open(huge, options(Set.of(Setting.WIDTH)), atMost4k))
                .as("--width alone keeps the file's height").hasMessage("a 200x20000 image is too large");
        ViewerOptions wide = new ViewerOptions(null, RenderSettings.defaults().withSize(8000, 100).withMaxDepth(5).withThreads(2).withSeed(9).withIntegrator(IntegratorKind.WHITTED).withLightSamples(2),
                256, Theme.LIGHT, Set.of(Setting.WIDTH, Setting.HEIGHT), SceneOverrides.NONE);
        assertThatThrownBy(() -> SceneFiles.open(huge, wide, atMost4k)).as("as --width 8000 --height 100")
                .hasMessage("a 8000x100 image is too large");
        assertThat(SceneFiles.open(huge, ViewerOptions.defaults(), Viewer.FilmCheck.NONE).settings().output().width()).isEqualTo(30000);
    }

    @Test
    void aChoiceShowsAValueSetElsewhereWithoutReportingIt() {
        List<Integer> reported = new ArrayList<>();
        Choice<Integer> depth = new Choice<>(ViewerActions.DEPTHS, 5, ViewerActions.DEPTH_ORDER, StatusBar::depthText, reported::add);
        JComboBox<Integer> box = depth.comboBox("depth ", "");
        JMenu menu = depth.menu("Max depth", 0);

        depth.show(7);
        assertThat(depth.value()).isEqualTo(7);
        assertThat(depth.values()).as("joins in order, unbounded first").containsExactly(-1, 1, 2, 3, 4, 5, 7, 8, 16);
        assertThat(box.getItemCount()).isEqualTo(9);
        assertThat(box.getSelectedItem()).isEqualTo(7);
        assertThat(menu.getItemCount()).isEqualTo(9);
        assertThat(((JRadioButtonMenuItem) menu.getItem(6)).isSelected()).isTrue();
        assertThat(((JRadioButtonMenuItem) menu.getItem(6)).getText()).isEqualTo("7");
        assertThat(reported).as("the controller already has it").isEmpty();

        depth.show(-1);
        assertThat(box.getSelectedItem()).isEqualTo(-1);
        assertThat(((JRadioButtonMenuItem) menu.getItem(0)).isSelected()).isTrue();
        assertThat(reported).isEmpty();

        box.setSelectedItem(3);                 // the user's choice is reported
        assertThat(reported).containsExactly(3);
        assertThat(((JRadioButtonMenuItem) menu.getItem(3)).isSelected()).isTrue();
        assertThatThrownBy(() -> depth.set(6)).as("only listed values can be chosen").isInstanceOf(IllegalArgumentException.class);

        Choice<Integer> stopAt = new Choice<>(ViewerActions.STOP_AT, 100, ViewerActions.STOP_AT_ORDER, n -> n + "", n -> { });
        assertThat(stopAt.values()).as("never (0) last").containsExactly(16, 64, 100, 256, 1024, 4096, RenderController.UNLIMITED);
        Choice<IntegratorKind> kinds = new Choice<>(List.of(IntegratorKind.PATH), IntegratorKind.PATH, null, IntegratorKind::id, k -> { });
        assertThatThrownBy(() -> kinds.show(IntegratorKind.DIRECT)).isInstanceOf(IllegalArgumentException.class);
    }

    /** The status bar's share never says all while a pixel is left; the heat map is blue to cyan where met, yellow to red where not. */
    @Test
    void noiseShareAndHeatMapColours() {
        assertThat(StatusBar.noiseText(0.6321)).isEqualTo("63.2 % converged");
        assertThat(StatusBar.noiseText(0.99999)).isEqualTo("99.9 % converged");
        assertThat(StatusBar.noiseText(1)).isEqualTo("100 % converged");
        assertThat(StatusBar.percent(0.05)).isEqualTo("5 %");
        assertThat(StatusBar.percent(0.005)).isEqualTo("0.5 %");
        assertThat(NoiseHeatMap.color(1)).isEqualTo(0x00ffff);
        assertThat(NoiseHeatMap.color(4)).isEqualTo(0xff0000);
        assertThat(NoiseHeatMap.color(100)).isEqualTo(0xff0000);
        assertThat(NoiseHeatMap.color(Double.NaN)).isEqualTo(0xff00ff);
        for (double v = 0; v <= 1; v += 0.125) {
            assertThat(NoiseHeatMap.color(v) >> 16).as("met: no red, %s", v).isZero();
        }
        for (double v = 1.01; v < 8; v *= 1.3) {
            assertThat(NoiseHeatMap.color(v) >> 16).as("not met: red, %s", v).isEqualTo(255);
        }
        var img = NoiseHeatMap.of(new dev.strahl.image.Image(2, 1, new float[] {0.01f, 0.01f, 0.01f, 0.5f, 0.5f, 0.5f}), 0.01);
        assertThat(img.getRGB(0, 0) & 0xffffff).isEqualTo(0x00ffff);
        assertThat(img.getRGB(1, 0) & 0xffffff).isEqualTo(0xff0000);
    }
}
