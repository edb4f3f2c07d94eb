package dev.strahl.viewer;

import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.io.json.SceneFile;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * Finds and loads the scene to show, with the render settings it asks for. Without a file named
 * by the user, the default is the Cornell Box: {@code scenes/cornell-box.json} in the working
 * directory when it exists (a checkout of strahl), else the copy packed into the jar under
 * {@code /scenes/}, unpacked to a temporary directory because the loader reads files.
 */
final class SceneFiles {
    static final Path DEFAULT = Path.of("scenes", "cornell-box.json");
    private static final String[] BUNDLED = {"cornell-box.json", "cornell-box.obj", "cornell-box.mtl"};

    private SceneFiles() {
    }

    /**
     * A loaded scene and the settings to render it with.
     *
     * @param settings the viewer's options combined with the scene file's settings; the film size
     *                 is the one asked for, before the window fits it
     */
    record Opened(Path file, Scene scene, RenderSettings settings) {}

    /**
     * Loads {@code file} (the default scene when it is null) through the scene loader (the format
     * follows the extension), applies the command line's environment map and lens
     * ({@link ViewerOptions#overrides}), combines its settings with {@code options} and checks the
     * film size they ask for with {@code filmCheck}.
     *
     * @throws IllegalArgumentException if the film size fails {@code filmCheck}
     */
    static Opened open(Path file, ViewerOptions options, Viewer.FilmCheck filmCheck) throws SceneException {
        Path f = file != null ? file : defaultScene();
        SceneFile loaded = SceneFile.load(f);
        RenderSettings settings = options.settingsFor(loaded.settings());
        filmCheck.check(settings.output().width(), settings.output().height(), settings.output().keepsFeatures());
        return new Opened(f, options.overrides().applyTo(loaded.scene()), settings);
    }

    /** The file of the default scene. */
    static Path defaultScene() throws SceneException {
        if (Files.isRegularFile(DEFAULT)) {
            return DEFAULT;
        }
        if (SceneFiles.class.getResource("/scenes/" + BUNDLED[0]) == null) {
            throw new SceneException(DEFAULT, "file not found (and no Cornell Box packed in this build): name a scene file");
        }
        try {
            Path dir = Files.createTempDirectory("strahl-scenes");
            dir.toFile().deleteOnExit();
            for (String name : BUNDLED) {
                try (InputStream in = SceneFiles.class.getResourceAsStream("/scenes/" + name)) {
                    if (in == null) {
                        throw new SceneException(DEFAULT, "the packed Cornell Box lacks " + name);
                    }
                    Path out = dir.resolve(name);
                    Files.copy(in, out, StandardCopyOption.REPLACE_EXISTING);
                    out.toFile().deleteOnExit();
                }
            }
            return dir.resolve(BUNDLED[0]);
        } catch (IOException e) {
            throw new SceneException(DEFAULT, "cannot unpack the packed Cornell Box: " + e.getMessage(), e);
        }
    }
}
