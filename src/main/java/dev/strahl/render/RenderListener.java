package dev.strahl.render;

import dev.strahl.image.Image;

/**
 * Hears about a render's progress. Called from a render thread: implementations must return
 * quickly and hand work to their own thread (a Swing viewer uses {@code invokeLater}).
 */
public interface RenderListener {

    /**
     * Where a render stands at the end of a pass.
     *
     * @param number          passes completed, from 1
     * @param samplesPerPixel samples per pixel of all completed passes
     * @param samples         camera samples taken so far
     * @param seconds         time since the render started
     */
    record Pass(int number, int samplesPerPixel, long samples, double seconds) {
        /**
         * The mean sampling rate so far.
         *
         * @return camera samples per second
         */
        public double samplesPerSecond() {
            return seconds > 0 ? samples / seconds : 0;
        }
    }

    /**
     * A pass over the whole image finished. By default hands on to {@link #passCompleted}.
     *
     * @param pass  the figures of the render so far
     * @param image the mean of all samples so far
     */
    default void passFinished(Pass pass, Image image) {
        passCompleted(pass.samplesPerPixel(), image);
    }

    /**
     * A pass over the whole image finished.
     *
     * @param samplesPerPixel samples per pixel of all completed passes
     * @param image           the mean of all samples so far
     */
    default void passCompleted(int samplesPerPixel, Image image) {}

    /**
     * The render ended, completed or cancelled.
     *
     * @param stats its figures
     */
    default void finished(RenderStats stats) {}
}
