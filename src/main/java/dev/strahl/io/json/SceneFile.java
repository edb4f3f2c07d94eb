package dev.strahl.io.json;

import dev.strahl.io.gltf.GltfReader;
import dev.strahl.io.mesh.MeshFiles;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Transform;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A scene loaded from a file, with what the file says about rendering: a strahl scene file
 * ({@code .json}), a mesh file (OBJ with its MTL materials, PLY), which says nothing about
 * rendering and has no camera (the scene is framed), or a glTF asset ({@code .gltf}, {@code .glb}),
 * whose camera is used when it has one, its {@code aspectRatio} setting the film's shape.
 *
 * @param scene    the scene
 * @param settings the file's film and integrator keys; {@link SceneSettings#NONE} for a mesh file
 */
public record SceneFile(Scene scene, SceneSettings settings) {

    /**
     * Loads {@code file}; the format follows its extension, in any case.
     *
     * @throws SceneException if the file is missing, unreadable or malformed: the message names
     *                        the file and, where known, the line
     */
    public static SceneFile load(Path file) throws SceneException {
        if (Files.isDirectory(file)) {
            throw new SceneException(file, "is a directory, not a scene file");
        }
        if (!Files.exists(file)) {
            throw new SceneException(file, "file not found");
        }
        if (MeshFiles.lowerCaseName(file).endsWith(".json")) {
            return JsonSceneReader.read(file);
        }
        if (MeshFiles.isMeshFile(file)) {
            Scene.Builder builder = Scene.builder();
            MeshFiles.add(file, null, Transform.IDENTITY, builder);
            return new SceneFile(build(file, builder), SceneSettings.NONE);
        }
        if (GltfReader.isGltfFile(file)) {
            Scene.Builder builder = Scene.builder();
            GltfReader.Asset asset = GltfReader.add(file, Transform.IDENTITY, builder);
            if (asset.camera() != null) {
                builder.camera(asset.camera());
            }
            GltfReader.addLights(asset, builder);
            SceneSettings settings = SceneSettings.NONE;
            if (asset.aspectRatio() > 0) {
                int width = RenderSettings.defaults().output().width();
                settings = new SceneSettings(width, SceneSettings.filmSide(width / asset.aspectRatio()), null, null, null, null,
                        null, null, null, null, null, asset.aspectRatio());
            }
            return new SceneFile(build(file, builder), settings);
        }
        throw new SceneException(file, "unknown scene format (expected .json, .obj, .ply, .gltf or .glb)");
    }

    /** The scene of {@code file}: what the builder refuses only when it has it all (an instance's extent) names the file. */
    static Scene build(Path file, Scene.Builder builder) throws SceneException {
        try {
            return builder.build();
        } catch (IllegalArgumentException e) {
            throw new SceneException(file, e.getMessage());
        }
    }
}
