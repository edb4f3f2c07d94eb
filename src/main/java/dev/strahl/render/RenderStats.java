package dev.strahl.render;

import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * Figures of a render: after each pass (what {@link RenderListener#passFinished} hears) and when it
 * ended, completed or cancelled ({@link RenderJob#awaitStats()}).
 *
 * @param seconds           wall-clock render time, excluding scene loading and BVH build
 * @param samples           camera samples taken
 * @param rays              rays traced (camera, continuation and shadow)
 * @param samplesPerPixel   completed samples per pixel (with a noise threshold: of the pixels still rendering, or at the
 *                          end of those that rendered longest)
 * @param threads           worker threads used (of every member, on a cluster)
 * @param cancelled         whether the render was cancelled before reaching its sample count (a time limit is not a cancellation)
 * @param invalidSamples    samples whose radiance was NaN or infinite and so was dropped
 * @param threadIdleSeconds summed over the threads: how long each, having finished its part of a
 *                          pass, waited for the last thread to finish it (this session's passes only)
 * @param passes            passes completed
 * @param minSamplesPerPixel  the fewest samples a pixel holds (with a noise threshold, of the pixels that converged first)
 * @param meanSamplesPerPixel the mean samples per pixel: the samples the image holds over its pixels
 * @param maxSamplesPerPixel  the most samples a pixel holds
 * @param convergedFraction the share of pixels a noise threshold has found converged, from 0 to 1; 0 without one
 * @param members           on a cluster ({@link RenderCluster}), what each member did for this render; empty for a local one
 */
public record RenderStats(double seconds, long samples, long rays, int samplesPerPixel, int threads, boolean cancelled,
                          long invalidSamples, double threadIdleSeconds, int passes, int minSamplesPerPixel, double meanSamplesPerPixel,
                          int maxSamplesPerPixel, double convergedFraction, List<Member> members) {

    /**
     * Copies the list of members.
     *
     * @param seconds           render time
     * @param samples           camera samples
     * @param rays              rays traced
     * @param samplesPerPixel   completed samples per pixel (with a noise threshold: of the pixels still rendering, or at the
 *                          end of those that rendered longest)
     * @param threads           worker threads
     * @param cancelled         whether it was cancelled
     * @param invalidSamples    NaN or infinite samples
     * @param threadIdleSeconds time threads waited for each other
     * @param passes            passes completed
     * @param minSamplesPerPixel  the fewest samples of a pixel
     * @param meanSamplesPerPixel the mean samples of a pixel
     * @param maxSamplesPerPixel  the most samples of a pixel
     * @param convergedFraction the share of pixels converged
     * @param members           the cluster's members' figures, or none
     */
    public RenderStats {
        members = List.copyOf(members);
    }

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

    /**
     * What one member of a cluster did for a render, as its coordinator counted it. The units and
     * samples of a render's members add up to the units merged and the samples taken (a unit that
     * is lost is counted where it was rendered in the end, not where it was lost). docs/cluster.md
     * reads these figures.
     *
     * @param member        its address, host:port
     * @param coordinator   whether it is the render's coordinator (the member that started it)
     * @param threads       its render threads
     * @param units         units it rendered
     * @param samples       camera samples of those units
     * @param bytesSent     bytes of units sent to it
     * @param bytesReceived bytes of rendered units received from it
     * @param unitSeconds   summed over its units, the time from sending each to receiving it back
     * @param lost          units handed back because it left or failed
     */
    public record Member(String member, boolean coordinator, int threads, long units, long samples, long bytesSent,
                         long bytesReceived, double unitSeconds, long lost) {
        /**
         * Checks the figures: non-negative counts, at least one thread.
         *
         * @param member        its address
         * @param coordinator   whether it coordinates
         * @param threads       render threads, positive
         * @param units         units rendered
         * @param samples       samples of those units
         * @param bytesSent     bytes sent to it
         * @param bytesReceived bytes received from it
         * @param unitSeconds   time of its units, summed
         * @param lost          units it handed back
         */
        public Member {
            Objects.requireNonNull(member, "member");
            if (threads < 1 || units < 0 || samples < 0 || bytesSent < 0 || bytesReceived < 0 || lost < 0 || !(unitSeconds >= 0)) {
                throw new IllegalArgumentException("bad member figures " + member + " threads=" + threads + " units=" + units);
            }
        }

        /**
         * The mean time from sending a unit to receiving it back.
         *
         * @return seconds; 0 before the first unit
         */
        public double meanUnitSeconds() {
            return units > 0 ? unitSeconds / units : 0;
        }

        /**
         * One line for a person: the address, "(coordinator)" on the coordinator, then the figures as name=value.
         *
         * @return the line
         */
        public String line() {
            return String.format(Locale.ROOT, "%s%s threads=%d units=%d samples=%d sent=%d received=%d meanUnitSeconds=%.4f lost=%d",
                    member, coordinator ? " (coordinator)" : "", threads, units, samples, bytesSent, bytesReceived, meanUnitSeconds(), lost);
        }
    }
}
