package dev.strahl.cli;

import static dev.strahl.cli.RenderCommandTest.CORNELL;
import static org.assertj.core.api.Assertions.assertThat;

import dev.strahl.image.Image;
import dev.strahl.codec.PfmReader;
import dev.strahl.viewer.ViewerOptions;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The teaching option {@code --shadows on|off}, one definition for {@code render} and {@code view}
 * ({@link TransportOptions}): off renders without shadows (a lighter image), on is the default
 * image, the value is case-insensitive, {@code --stats} reports it, and a wrong value is one line
 * naming the option, with exit code 2 and nothing written.
 */
class ShadowsOptionTest {
    @TempDir
    Path out;

    private Image render(String name, String... options) throws IOException {
        Path pfm = out.resolve(name);
        RenderCommandTest.Run r = RenderCommandTest.render(CORNELL, pfm, options);
        assertThat(r.code()).as("exit code; stderr: %s", r.err()).isZero();
        return PfmReader.read(pfm);
    }

    private static double luminance(Image img) {
        double[] m = img.mean();
        return 0.2126 * m[0] + 0.7152 * m[1] + 0.0722 * m[2];
    }

    @Test
    void offRendersALighterImageWithoutShadowsAndStatsReportIt() throws IOException {
        Path json = out.resolve("off.json");
        Image on = render("on.pfm", "--integrator", "whitted", "--seed", "5");
        Image explicit = render("on2.pfm", "--integrator", "whitted", "--seed", "5", "--shadows", "ON");
        Image off = render("off.pfm", "--integrator", "whitted", "--seed", "5", "--shadows", "off", "--stats", json.toString());
        assertThat(explicit.rgb()).as("--shadows on is the default").isEqualTo(on.rgb());
        assertThat(luminance(off)).as("without shadows no light is blocked").isGreaterThan(1.015 * luminance(on));
        assertThat(Files.readString(json)).contains("\"shadows\" : \"off\"");
    }

    @Test
    void aWrongValueIsOneLineNamingTheOptionForRenderAndView() {
        Path png = out.resolve("a.png");
        RenderCommandTest.Run render = RenderCommandTest.render(CORNELL, png, "--shadows", "maybe");
        RenderCommandTest.Run view = RenderCommandTest.strahl("view", "--shadows", "maybe");
        for (RenderCommandTest.Run r : new RenderCommandTest.Run[] {render, view}) {
            assertThat(r.code()).as(r.err()).isEqualTo(2);
            assertThat(r.errLines()).hasSize(1);
            assertThat(r.errLines().get(0)).startsWith("strahl: ").contains("--shadows").contains("'maybe'").doesNotContain("Exception");
        }
        assertThat(png).doesNotExist();
    }

    @Test
    void helpListsItAsATeachingOption() {
        for (String command : new String[] {"render", "view"}) {
            RenderCommandTest.Run r = RenderCommandTest.strahl(command, "--help");
            assertThat(r.code()).isZero();
            assertThat(r.out()).contains("--shadows").contains("on|off").contains("Teaching option");
        }
    }

    @Test
    void viewCarriesItIntoTheViewerOptions() {
        assertThat(ViewCommandTest.parse("view", "s.json").settings().transport().shadows()).isTrue();
        ViewerOptions off = ViewCommandTest.parse("view", "s.json", "--shadows", "off");
        assertThat(off.settings().transport().shadows()).isFalse();
        assertThat(off.given()).as("not a scene file's setting").isEmpty();
    }
}
