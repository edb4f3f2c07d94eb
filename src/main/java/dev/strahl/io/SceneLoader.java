package dev.strahl.io;

import dev.strahl.image.Image;
import dev.strahl.io.json.EnvironmentMaps;
import dev.strahl.io.json.SceneFile;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import java.nio.file.Path;

/**
 * Loads a scene from a file: a strahl scene file ({@code .json}, see docs/scene-format.md), a
 * Wavefront OBJ with its MTL materials ({@code .obj}), a PLY mesh ({@code .ply}, ASCII or
 * binary, grey diffuse) or a glTF 2.0 asset ({@code .gltf} with its {@code .bin} and images, or
 * {@code .glb}; its camera is used when it has one). An OBJ or PLY has no camera: the scene is framed from a raised
 * three-quarter view; without lights it is lit by strahl's studio sky ({@link Scene#notes()} says so).
 *
 * <pre>{@code
 * Path file = Path.of("scenes/cornell-box.json");
 * Scene scene = SceneLoader.load(file);
 * RenderSettings settings = SceneLoader.settings(file, RenderSettings.defaults());  // the file's film and integrator keys
 * }</pre>
 */
public final class SceneLoader {
    private SceneLoader() {}

    /**
     * Loads and builds the scene in {@code file}; the format follows the file's extension, in any case.
     *
     * @param file a {@code .json}, {@code .obj}, {@code .ply}, {@code .gltf} or {@code .glb} file
     * @return the scene
     * @throws SceneException if the file is missing, unreadable or malformed: the message names
     *                        the file and, where known, the line
     */
    public static Scene load(Path file) throws SceneException {
        return SceneFile.load(file).scene();
    }

    /**
     * Reads a linear HDR image, e.g. an environment map for {@code Scene.Builder.environmentMap}:
     * Radiance {@code .hdr}/{@code .pic} (RGBE, flat or run-length encoded), OpenEXR {@code .exr}
     * (scanline; NONE, RLE, ZIPS, ZIP or PIZ; half or float; R, G, B or Y channels) or {@code .pfm}.
     *
     * @param file the image file
     * @return its colour, linear, rows from the top
     * @throws SceneException if the file is missing, unreadable, corrupt, truncated, of an
     *                        unsupported kind (an EXR compression is named) or too large for the
     *                        heap: one line naming the file
     */
    public static Image readImage(Path file) throws SceneException {
        return EnvironmentMaps.read(file);
    }

    /**
     * Render settings with what a scene file says about rendering (its {@code film} and
     * {@code integrator} keys) on top of {@code base}; a mesh file says nothing and gives
     * {@code base}; a glTF camera's {@code aspectRatio} sets the size to 512 pixels across and
     * as many down as the ratio asks. Reads the file again: load the scene first.
     *
     * @param file a {@code .json}, {@code .obj}, {@code .ply}, {@code .gltf} or {@code .glb} file
     * @param base the settings to start from, e.g. {@link RenderSettings#defaults()}
     * @return the combined settings
     * @throws SceneException if the file is missing, unreadable or malformed
     */
    public static RenderSettings settings(Path file, RenderSettings base) throws SceneException {
        return SceneFile.load(file).settings().applyTo(base);
    }
}
