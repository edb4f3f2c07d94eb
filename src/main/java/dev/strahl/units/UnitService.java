package dev.strahl.units;

import dev.strahl.scene.Scene;

/** What a member does with a job it takes part in: the render package's side of the cluster. */
public interface UnitService {
    /**
     * A renderer for units of a job.
     *
     * @param scene    the job's scene, loaded from the files the coordinator shipped, with its camera
     * @param settings the job's settings as {@link JobSpec#settings()} holds them
     * @param digest   the fingerprint of the coordinator's scene, to check the loaded one against
     * @param threads  the threads this member renders units on
     * @return the renderer
     * @throws IllegalArgumentException if the settings cannot be read or the scene is not the coordinator's
     */
    UnitRenderer open(Scene scene, String settings, byte[] digest, int threads);
}
