package dev.strahl.viewer;

import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;
import dev.strahl.world.World;

/**
 * Which integrators can render a scene: every one, except that a scene with participating media
 * or null surfaces is rendered by {@code path} and {@code direct} only (docs/media.md). The
 * viewer asks before it starts a job, so that choosing {@code whitted} or {@code photon} for such
 * a scene (or opening one whose file asks for them) renders with {@code path} and the toolbar
 * shows it, where the command line refuses with a message.
 */
final class SceneIntegrators {
    private SceneIntegrators() {}

    /** {@code settings}, with {@code path} instead of an integrator that does not render {@code scene}. */
    static RenderSettings supported(Scene scene, RenderSettings settings) {
        IntegratorKind kind = settings.transport().integrator();
        boolean refuses = kind == IntegratorKind.WHITTED || kind == IntegratorKind.PHOTON;
        return refuses && World.of(scene).media().any() ? settings.withIntegrator(IntegratorKind.PATH) : settings;
    }
}
