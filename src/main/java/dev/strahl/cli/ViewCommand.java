package dev.strahl.cli;

import dev.strahl.io.json.SceneSettings;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.SceneException;
import dev.strahl.viewer.SceneOverrides;
import dev.strahl.viewer.Theme;
import dev.strahl.viewer.Viewer;
import dev.strahl.viewer.ViewerOptions;
import java.awt.AWTError;
import java.awt.HeadlessException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Set;
import java.util.concurrent.Callable;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code strahl view}: opens the interactive viewer. */
@Command(name = "view",
        mixinStandardHelpOptions = true,
        abbreviateSynopsis = true,
        versionProvider = Main.Version.class,
        description = {"Opens a window that renders a scene progressively, one sample per pixel at a time.",
            "Drag to orbit (left) or pan (right/middle), wheel to dolly; F1 in the window lists all controls.",
            "Drop a scene file onto the window to open it; File > Open Recent lists the last 8.",
            "Without SCENE, shows the Cornell Box (scenes/cornell-box.json)."},
        sortOptions = false)
final class ViewCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENE", description = "Scene file: .json (strahl scene), .obj (with its .mtl), .ply, or glTF 2.0 (.gltf, .glb).")
    Path scene;

    @Option(names = "--theme", defaultValue = "system", paramLabel = "system|light|dark",
            description = "Light or dark look; system follows the desktop where it can (default: ${DEFAULT-VALUE}).")
    String theme;

    @Mixin
    DebugOption debug;

    @ArgGroup(validate = false, heading = "%nFilm (its size at start; resizing the window keeps the aspect):%n")
    FilmOptions film = new FilmOptions();

    @ArgGroup(validate = false, heading = "%nSampling:%n")
    Sampling sampling = new Sampling();

    @ArgGroup(validate = false, heading = "%nLight transport:%n")
    TransportOptions transport = new TransportOptions();

    @ArgGroup(validate = false, heading = "%nLens:%n")
    LensOptions lens = new LensOptions();

    @ArgGroup(validate = false, heading = "%nEnvironment:%n")
    EnvironmentOptions environment = new EnvironmentOptions();

    @ArgGroup(validate = false, heading = "%nExecution:%n")
    ExecutionOptions execution = new ExecutionOptions();

    @ArgGroup(validate = false, heading = "%nTeaching option (docs/experiments.md):%n")
    ShadowsOption teaching = new ShadowsOption();

    /** view's --spp, the stop-at count, beside the shared --seed. */
    static final class Sampling extends SamplingOptions {
        @Option(names = "--spp", defaultValue = "1024", order = 1,
                description = "Stop at this many samples per pixel; 0 = never stop (default: ${DEFAULT-VALUE}).")
        int stopAt;
    }

    /** What the options say; those given on the command line win over the scene file's settings. */
    ViewerOptions options() {
        RenderSettings s = transport.applyTo(sampling.applyTo(film.applyTo(RenderSettings.defaults())));
        s = teaching.applyTo(execution.applyTo(s));
        lens.check();
        return new ViewerOptions(scene, s, sampling.stopAt, Theme.parse(theme), given(),
                new SceneOverrides(environment.envmap, lens.aperture, lens.focusDistance));
    }

    /**
     * The options given on the command line that name a scene file's settings. {@code --spp} is not
     * one of them here: view's {@code --spp} is its stop-at count, not the file's {@code spp}
     * (which the viewer does not use, see {@link ViewerOptions}).
     */
    private Set<SceneSettings.Setting> given() {
        Set<SceneSettings.Setting> given = SceneFileOptions.given(spec.commandLine().getParseResult());
        given.remove(SceneSettings.Setting.SAMPLES_PER_PIXEL);
        return given;
    }

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        try (SimdOption.Scope kernel = execution.apply()) {
            // refuses a film too large for the heap, as render does; a viewer that keeps feature buffers denoises them
            Viewer.open(options(), (w, h, features) -> HeapCheck.checkRender(w, h, features, features)).awaitClosed();
            return 0;
        } catch (SceneException | IllegalArgumentException e) {
            err.println("strahl: " + dev.strahl.codec.Printable.line(e.getMessage()));
            if (debug.enabled) {
                e.printStackTrace(err);
            }
            return 2;
        } catch (HeadlessException e) {
            err.println("strahl: view needs a display: DISPLAY is not set, or java.awt.headless is true");
            return 1;
        } catch (AWTError e) {
            err.println("strahl: cannot open a window: " + e.getMessage());
            return 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 1;
        }
    }
}
