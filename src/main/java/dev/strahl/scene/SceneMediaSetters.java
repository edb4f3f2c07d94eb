package dev.strahl.scene;

import dev.strahl.image.Rgb;
import java.nio.file.Path;
import org.joml.Vector3dc;

/**
 * The participating media of a {@link Scene.Builder} (its package-private base, above
 * {@link SceneLighting}): media by name, the boundary that shapes added from now on get, the
 * camera's medium; one method each, returning the builder. What they record is {@link SceneMedia}'s.
 */
abstract class SceneMediaSetters extends SceneLighting {
    final SceneMedia media = new SceneMedia();

    private Scene.Builder self() {
        return (Scene.Builder) this;
    }

    /**
     * Defines a homogeneous medium (Mitsuba 3's {@code homogeneous} with an {@code hg} phase function).
     *
     * @param name   the medium's name, new
     * @param sigmaT extinction per scene unit in each channel, ≥ 0
     * @param albedo single-scattering albedo σs/σt in each channel, in [0, 1] (0: it only absorbs)
     * @param g      Henyey–Greenstein asymmetry in (−1, 1): positive scatters forwards
     * @return this builder
     * @throws IllegalArgumentException for a value out of range or a name defined before
     */
    public Scene.Builder homogeneousMedium(String name, Rgb sigmaT, Rgb albedo, double g) {
        media.homogeneous(name, sigmaT, albedo, g);
        return self();
    }

    /**
     * Defines a medium of extinction {@code scale} × the density grid of a Mitsuba {@code .vol}
     * file (version 3, float32, one channel) filling a box, as Mitsuba 3's {@code gridvolume}:
     * voxel (i, j, k) at ((i + ½)/X, (j + ½)/Y, (k + ½)/Z) of the box, trilinear, clamped at the border.
     *
     * @param name   the medium's name, new
     * @param file   the {@code .vol} file
     * @param min    the box's lower corner, or null (with {@code max}) for the box in the file's header
     * @param max    the box's upper corner
     * @param scale  extinction per unit of density and scene unit, ≥ 0
     * @param albedo single-scattering albedo in each channel, in [0, 1]
     * @param g      Henyey–Greenstein asymmetry in (−1, 1)
     * @return this builder
     * @throws SceneException if the file holds no valid grid (one line naming it)
     */
    public Scene.Builder gridMedium(String name, Path file, Vector3dc min, Vector3dc max, double scale, Rgb albedo, double g)
            throws SceneException {
        media.grid(name, file, min, max, scale, albedo, g);
        return self();
    }

    /**
     * Makes the shapes added from now on boundaries between media: a ray that crosses into one
     * (against its geometric normal) travels on in {@code interior}, one that leaves it in
     * {@code exterior}. {@code (null, null)} ends it: later shapes leave a ray in its medium.
     *
     * @param interior a medium defined before, or null for vacuum
     * @param exterior a medium defined before, or null for vacuum
     * @return this builder
     */
    public Scene.Builder mediumBoundary(String interior, String exterior) {
        media.boundary(interior, exterior);
        return self();
    }

    /**
     * The medium the camera is in (default: vacuum).
     *
     * @param name a medium defined before, or null for vacuum
     * @return this builder
     */
    public Scene.Builder cameraMedium(String name) {
        media.camera(name);
        return self();
    }
}
