package dev.strahl.io.json;

import dev.strahl.io.json.SceneDescription.TextureRef;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Texture;
import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;

/**
 * Turns a scene file's texture references into textures: paths relative to the scene file's
 * folder; a missing file is a warning (the parameter keeps its plain value, as a missing MTL file
 * does), an unreadable or corrupt one an error naming it.
 */
final class TextureLoader {
    private final Path sceneFile;
    private final Path folder;
    private final List<String> notes;

    TextureLoader(Path sceneFile, Path folder, List<String> notes) {
        this.sceneFile = sceneFile;
        this.folder = folder;
        this.notes = notes;
    }

    /** The texture, or null (with a warning) if its file does not exist. */
    Texture load(TextureRef ref, String key) throws SceneException {
        Path file;
        try {
            file = folder.resolve(ref.file());
        } catch (InvalidPathException e) {
            throw new SceneException(sceneFile, "'" + key + ".texture' is not a valid path: " + ref.file());
        }
        Texture t;
        try {
            t = Texture.image(file);
        } catch (NoSuchFileException e) {
            notes.add("warning: texture file not found: " + file + " ('" + key + "' keeps its plain value)");
            return null;
        } catch (IOException e) {
            String m = e.getMessage();
            throw new SceneException(file, "cannot read texture image ('" + key + "' of " + sceneFile.getFileName() + "): "
                    + (m == null ? e.getClass().getSimpleName() : m.replace(file + ": ", "")), e);
        }
        if (ref.linear()) {
            t = t.linear();
        }
        return ref.scaleU() == 1 && ref.scaleV() == 1 ? t : t.withUvScale(ref.scaleU(), ref.scaleV());
    }
}
