package dev.strahl.cli;

import dev.strahl.scene.SceneException;
import dev.strahl.io.json.SceneSettings;
import dev.strahl.viewer.Theme;
import dev.strahl.viewer.Viewer;
import dev.strahl.viewer.ViewerOptions;
import java.awt.AWTError;
import java.awt.HeadlessException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code strahl view}: opens the interactive viewer. */
@Command(name = "view",
        mixinStandardHelpOptions = true,
        versionProvider = Main.Version.class,
        description = {"Opens a window that renders a scene progressively, one sample per pixel at a time.",
            "Drag to orbit (left) or pan (right/middle), wheel to dolly; F1 in the window lists all controls.",
            "Drop a scene file onto the window to open it; File > Open Recent lists the last 8.",
            "Without SCENE, shows the Cornell Box (scenes/cornell-box.json)."},
        sortOptions = false)
final class ViewCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Mixin
    TransportOptions transport;

    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENE", description = "Scene file: .json (strahl scene), .obj (with its .mtl), .ply, or glTF 2.0 (.gltf, .glb).")
    Path scene;

    @Option(names = "--width", defaultValue = "512", description = "Film width in pixels at start; resizing the window keeps the aspect (default: ${DEFAULT-VALUE}).")
    int width;

    @Option(names = "--height", defaultValue = "512", description = "Film height in pixels at start (default: ${DEFAULT-VALUE}).")
    int height;

    @Option(names = "--spp", defaultValue = "1024", description = "Stop at this many samples per pixel; 0 = never stop (default: ${DEFAULT-VALUE}).")
    int spp;

    @Option(names = "--threads", defaultValue = "0", description = "Worker threads; 0 = all processors (default: ${DEFAULT-VALUE}).")
    int threads;

    @Option(names = "--seed", defaultValue = "0", description = "Random seed (default: ${DEFAULT-VALUE}).")
    long seed;

    @Mixin
    EnvironmentLensOptions lens;

    @Option(names = "--theme", defaultValue = "system", paramLabel = "system|light|dark",
            description = "Light or dark look; system follows the desktop where it can (default: ${DEFAULT-VALUE}).")
    String theme;

    @Option(names = "--aov", split = ",", paramLabel = "LIST",
            description = "Feature buffers the render keeps beside the image: albedo, normal, depth (comma-separated), as the scene"
                    + " file's film.aovs; the denoiser's guides.")
    List<String> aovNames;

    @Mixin
    DebugOption debug;

    /** What the options say; those given on the command line win over the scene file's settings. */
    ViewerOptions options() {
        return new ViewerOptions(scene, width, height, spp, transport.maxDepth, transport.hemisphere, threads, seed,
                transport.integrator, transport.lightSamples, Theme.parse(theme), given(), transport.photons, transport.photonRadius,
                SceneFileOptions.aovs(aovNames), lens.overrides(), transport.shadows());
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
        try {
            Viewer.open(options(), HeapCheck::checkFilm).awaitClosed();   // refuses a film too large for the heap, as render does
            return 0;
        } catch (SceneException | IllegalArgumentException e) {
            err.println("strahl: " + dev.strahl.io.image.Printable.line(e.getMessage()));
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
