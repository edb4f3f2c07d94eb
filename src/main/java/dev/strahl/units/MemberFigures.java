package dev.strahl.units;

/**
 * What one member did for a job.
 *
 * @param member        its address
 * @param threads       its render threads
 * @param units         units it rendered
 * @param samples       camera samples of those units
 * @param bytesSent     bytes of units sent to it
 * @param bytesReceived bytes of rendered units received from it
 * @param seconds       sum over its units of the time from sending to receiving
 * @param lost          units handed back because it left or failed
 */
public record MemberFigures(String member, int threads, long units, long samples, long bytesSent, long bytesReceived,
                            double seconds, long lost) {
}
