package dev.strahl.render;

import dev.strahl.image.Image;

/**
 * Hears about a render's progress. Called from a render thread: implementations must return
 * quickly and hand work to their own thread (a Swing viewer uses {@code invokeLater}).
 */
public interface RenderListener {

    /**
     * A pass over the whole image finished. By default hands on to {@link #passCompleted}.
     *
     * @param soFar the figures of the render so far (its passes, samples per pixel, samples and rays per second)
     * @param image the mean of all samples so far
     */
    default void passFinished(RenderStats soFar, Image image) {
        passCompleted(soFar.samplesPerPixel(), image);
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
