package dev.strahl.render;

import dev.strahl.film.Film;
import dev.strahl.image.Image;
import java.util.Set;

/**
 * The last completed pass of a {@link RenderJob}: its image ({@link RenderJob#snapshot()}), and
 * its variance and feature buffers ({@link RenderJob#snapshotBuffers()}), copied from the film
 * only when asked for and only while the film still holds exactly that pass. It does from the end
 * of a pass until the next one starts (while the job reports the pass to its listener), and for as
 * long as a pause that began then lasts. A pause that began in the middle of a pass does not
 * count: the film holds part of the next pass then. So no pass costs a copy nobody asked for, and
 * no copy is ever read from a film being written.
 *
 * <p>The job's coordinator thread calls {@link #ended} and {@link #starting}; {@link #pause} and
 * {@link #resume} hold and release the workers under the same lock, so that a pause begun while
 * the film is still keeps it still until the resume.
 */
final class PassBuffers {
    private final Film film;
    private final Set<Aov> aovs;
    /** The image at the end of the last completed pass, or null before the first. */
    private volatile Image image;
    /** The coordinator is between the end of a pass and the start of the next one (guarded by this). */
    private boolean reporting;
    /** Paused while {@link #reporting}: the film stays still until resumed (guarded by this). */
    private boolean heldAtPass;

    PassBuffers(Film film, Set<Aov> aovs) {
        this.film = film;
        this.aovs = aovs;
    }

    /** The image of the last completed pass; black before the first. */
    Image image() {
        Image i = image;
        return i != null ? i : new Image(film.width(), film.height(), new float[3 * film.width() * film.height()]);
    }

    /** A pass has ended with this image: until {@link #starting()} nothing writes into the film. */
    synchronized void ended(Image passImage) {
        image = passImage;
        reporting = true;
    }

    /** The next pass starts: the workers write into the film from now on (once released, if paused at the pass). */
    synchronized void starting() {
        reporting = false;
    }

    /** Holds the workers ({@code hold}); begun while the film is still, the pause keeps it still. */
    synchronized void pause(Runnable hold) {
        heldAtPass = reporting;
        hold.run();
    }

    /** Releases the workers ({@code release}); the film is no longer held at the pass. */
    synchronized void resume(Runnable release) {
        heldAtPass = false;
        release.run();
    }

    /** The buffers of the last completed pass, copied now, if the film still holds exactly that pass; else null. */
    synchronized RenderBuffers snapshot() {
        Image i = image;
        return (reporting || heldAtPass) && i != null ? of(i) : null;
    }

    /** The film's variance and feature buffers beside {@code color}: consistent only while nothing renders into the film. */
    RenderBuffers of(Image color) {
        return new RenderBuffers(color, film.varianceImage(),
                aovs.contains(Aov.ALBEDO) ? film.featureImage(0) : null,
                aovs.contains(Aov.NORMAL) ? film.featureImage(3) : null,
                aovs.contains(Aov.DEPTH) ? film.featureImage(6) : null, aovs.contains(Aov.SPP) ? sampleCounts() : null);
    }

    /** The film's sample count of every pixel, in r, g and b alike. */
    private Image sampleCounts() {
        float[] n = new float[3 * film.width() * film.height()];
        for (int y = 0, o = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++, o += 3) {
                n[o] = n[o + 1] = n[o + 2] = film.sampleCount(x, y);
            }
        }
        return new Image(film.width(), film.height(), n);
    }
}
