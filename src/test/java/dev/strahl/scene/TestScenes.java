package dev.strahl.scene;

import dev.strahl.geometry.Aabb;
import dev.strahl.image.Rgb;
import dev.strahl.material.Bsdf;

/** Test access to what the scene API keeps to strahl's own packages. */
public final class TestScenes {
    private TestScenes() {}

    /** A material with any scattering function, e.g. one a test defines. */
    public static Material material(String name, Bsdf bsdf, Rgb emission) {
        return Material.of(name, bsdf, emission);
    }

    /** The scattering function behind a material. */
    public static Bsdf bsdf(Material m) {
        return m.bsdf();
    }

    /** One step of a transform, as a scene file writes it: kind "translate", "rotate" or "scale". */
    public record Step(String kind, double x, double y, double z, double degrees) {}

    /** The steps a transform was made of, first applied first. */
    public static java.util.List<Step> steps(Transform t) {
        return t.steps().stream()
                .map(s -> new Step(s.kind().name().toLowerCase(java.util.Locale.ROOT), s.x(), s.y(), s.z(), s.degrees())).toList();
    }

    /** The camera a scene without one gets. */
    public static Camera framing(Aabb box, double fovDegrees) {
        return Camera.framing(box, fovDegrees);
    }
}
