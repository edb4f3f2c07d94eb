package dev.strahl.render;

import dev.strahl.film.Image;

/**
 * Hears about a render's progress. Called from a render thread: implementations must return
 * quickly and hand work to their own thread (a Swing viewer uses {@code invokeLater}).
 */
public interface RenderListener {

    /** A pass over the whole image finished; {@code image} is the mean of all samples so far. */
    default void passCompleted(int samplesPerPixel, Image image) {}

    /** The render ended, completed or cancelled. */
    default void finished(RenderStats stats) {}
}
