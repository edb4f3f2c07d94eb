package dev.strahl.testing;

import dev.strahl.image.Image;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.Scene;

/** Renders for tests. */
public final class Renders {
    private Renders() {}

    /** Renders to completion and returns the mean image. */
    public static Image render(Scene scene, RenderSettings settings) {
        try (RenderJob job = RenderJob.start(scene, settings)) {
            return job.awaitCompletion();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError("interrupted", e);
        }
    }
}
