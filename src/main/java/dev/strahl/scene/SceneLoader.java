package dev.strahl.scene;

import dev.strahl.material.Lambert;
import dev.strahl.material.Material;
import dev.strahl.math.Rgb;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Loads a scene from a file: a strahl scene file ({@code .json}) or a Wavefront OBJ with its MTL
 * materials ({@code .obj}; the camera then frames the scene from +Z).
 */
public final class SceneLoader {
    private SceneLoader() {}

    /** Loads and builds the scene in {@code file}. */
    public static Scene load(Path file) throws SceneException {
        String name = file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (Files.isDirectory(file)) {
            throw new SceneException(file, "is a directory, not a scene file");
        }
        if (!Files.exists(file)) {
            throw new SceneException(file, "file not found");
        }
        if (name.endsWith(".json")) {
            return JsonSceneReader.read(file);
        }
        if (name.endsWith(".obj")) {
            Scene.Builder builder = Scene.builder();
            addObj(file, builder);
            return builder.build();
        }
        throw new SceneException(file, "unknown scene format (expected .json or .obj)");
    }

    /** Adds the triangles of an OBJ file, with their MTL materials, to a scene under construction. */
    static void addObj(Path obj, Scene.Builder builder) throws SceneException {
        ObjModel model = ObjReader.read(obj);
        List<Material> palette = new ArrayList<>(model.materials().size());
        for (MtlMaterial m : model.materials()) {
            palette.add(toMaterial(m, builder));
        }
        for (String w : model.warnings()) {
            builder.note(w);
        }
        builder.addMesh(model.mesh(), model.triangleMaterial(), palette);
    }

    /**
     * Maps MTL parameters to a material following the conventions table: Ke > 0 emits,
     * illum ≤ 2 with Ks = 0 is Lambertian with albedo Kd.
     */
    static Material toMaterial(MtlMaterial m, Scene.Builder builder) {
        Rgb kd = m.kd();
        if (kd.max() > 1) {
            builder.note("material '" + m.name() + "': Kd " + kd + " reflects more than it receives; clamped to 1");
            kd = new Rgb(Math.min(kd.r(), 1), Math.min(kd.g(), 1), Math.min(kd.b(), 1));
        }
        boolean plainDiffuse = m.illum() <= 2 && m.ks().isBlack();
        if (!plainDiffuse) {
            builder.note("material '" + m.name() + "' (illum " + m.illum() + ", Ks " + m.ks() + "): only diffuse materials are supported yet; rendering it as diffuse");
        }
        return new Material(m.name(), new Lambert(kd), m.ke());
    }

    /** The one-line error for a file that cannot be read. */
    static SceneException cannotRead(Path file, IOException e) {
        if (e instanceof NoSuchFileException) {
            return new SceneException(file, "file not found");
        }
        if (e instanceof AccessDeniedException) {
            return new SceneException(file, "permission denied");
        }
        return new SceneException(file, "cannot read: " + e.getMessage(), e);
    }
}
