package dev.strahl.units;

/**
 * Makes the record of what one member did for a job, as its coordinator counted it: the render
 * package passes its API record's constructor ({@code RenderStats.Member::new}), so the cluster
 * reports typed figures that this package, below the API, need not name.
 *
 * @param <M> the record made
 */
@FunctionalInterface
public interface MemberFigures<M> {
    /**
     * The figures of one member.
     *
     * @param member        its address, host:port
     * @param coordinator   whether it is the job's coordinator
     * @param threads       its render threads
     * @param units         units it rendered
     * @param samples       camera samples of those units
     * @param bytesSent     bytes of units sent to it
     * @param bytesReceived bytes of rendered units received from it
     * @param unitSeconds   summed over its units, the time from sending each to receiving it back
     * @param lost          units handed back because it left or failed
     * @return the record
     */
    M of(String member, boolean coordinator, int threads, long units, long samples, long bytesSent, long bytesReceived,
         double unitSeconds, long lost);
}
