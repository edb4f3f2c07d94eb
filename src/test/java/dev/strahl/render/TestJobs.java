package dev.strahl.render;

import dev.strahl.film.Film;
import dev.strahl.integrator.Integrator;
import dev.strahl.scene.Scene;

/** Test access to what the render API keeps to strahl's own packages. */
public final class TestJobs {
    private TestJobs() {}

    /** Starts a job with a given integrator made for the scene; the settings' integrator choice is ignored. */
    public static RenderJob start(Scene scene, RenderSettings settings, Integrator integrator, RenderListener listener) {
        return RenderJob.start(scene, settings, integrator, listener);
    }

    /** The film a job fills. */
    public static Film film(RenderJob job) {
        return job.film();
    }

    /** Waits for the job and returns its film. */
    public static Film awaitFilm(RenderJob job) throws InterruptedException {
        job.awaitStats();
        return job.film();
    }

    /** Continues the render whose state {@code film} holds (saved as a checkpoint and resumed from it). */
    public static RenderJob resume(Scene scene, RenderSettings settings, Film film, RenderListener listener)
            throws java.io.IOException, CheckpointException {
        java.nio.file.Path file = java.nio.file.Files.createTempFile("strahl-test", ".ck");
        try {
            Checkpoint.of(scene, settings).save(file, film, null, 0, 0);
            return RenderJob.resumeFrom(file, scene, settings, listener);
        } finally {
            java.nio.file.Files.deleteIfExists(file);
        }
    }
}
