package dev.strahl.render;

/**
 * Figures of a finished (or cancelled) render.
 *
 * @param seconds         wall-clock render time, excluding scene loading and BVH build
 * @param samples         camera samples taken
 * @param rays            rays traced (camera, continuation and shadow)
 * @param samplesPerPixel completed samples per pixel
 * @param threads         worker threads used
 * @param cancelled       whether the render was cancelled before reaching its sample count (a time limit is not a cancellation)
 * @param invalidSamples  samples whose radiance was NaN or infinite and so was dropped
 * @param threadIdleSeconds summed over the threads: how long each, having finished its part of a
 *                        pass, waited for the last thread to finish it (this session's passes only)
 */
public record RenderStats(double seconds, long samples, long rays, int samplesPerPixel, int threads,
                          boolean cancelled, long invalidSamples, double threadIdleSeconds) {

    /**
     * Camera samples per second of wall-clock time.
     *
     * @return samples / seconds, 0 if no time passed
     */
    public double samplesPerSecond() {
        return seconds > 0 ? samples / seconds : 0;
    }

    /**
     * Rays per second of wall-clock time.
     *
     * @return rays / seconds, 0 if no time passed
     */
    public double raysPerSecond() {
        return seconds > 0 ? rays / seconds : 0;
    }
}
