package dev.strahl.units;

import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.function.Function;

/**
 * What one member did for a job, as its coordinator counted it. The units and samples of a job's
 * members add up to the units merged and the samples taken (a unit that is lost is counted where
 * it was rendered in the end, not where it was lost).
 *
 * @param member        its address, host:port
 * @param coordinator   whether it is the job's coordinator (the member that renders it)
 * @param threads       its render threads
 * @param units         units it rendered
 * @param samples       camera samples of those units
 * @param bytesSent     bytes of units sent to it
 * @param bytesReceived bytes of rendered units received from it
 * @param unitSeconds   summed over its units, the time from sending each to receiving it back
 * @param lost          units handed back because it left or failed
 */
public record MemberFigures(String member, boolean coordinator, int threads, long units, long samples, long bytesSent,
                            long bytesReceived, double unitSeconds, long lost) {
    private static volatile Function<Object, List<MemberFigures>> clusterAccess;

    /** Checks the figures: non-negative counts, at least one thread. */
    public MemberFigures {
        Objects.requireNonNull(member, "member");
        if (threads < 1 || units < 0 || samples < 0 || bytesSent < 0 || bytesReceived < 0 || lost < 0 || !(unitSeconds >= 0)) {
            throw new IllegalArgumentException("bad member figures " + member + " threads=" + threads + " units=" + units);
        }
    }

    /** The mean time from sending a unit to receiving it back; 0 before the first unit. */
    public double meanUnitSeconds() {
        return units > 0 ? unitSeconds / units : 0;
    }

    /** One line for a person: the address, "(coordinator)" on the coordinator, then the figures as name=value. */
    public String line() {
        return String.format(Locale.ROOT, "%s%s threads=%d units=%d samples=%d sent=%d received=%d meanUnitSeconds=%.4f lost=%d",
                member, coordinator ? " (coordinator)" : "", threads, units, samples, bytesSent, bytesReceived, meanUnitSeconds(), lost);
    }

    /**
     * The figures per member of every render a {@code RenderCluster} coordinated, for strahl's own
     * packages (the API returns them as lines only): the accessor that {@code RenderCluster}
     * installs when it is loaded, the pattern of {@code World.of(scene)}.
     *
     * @param cluster a {@code dev.strahl.render.RenderCluster}
     */
    public static List<MemberFigures> of(Object cluster) {
        Function<Object, List<MemberFigures>> access = clusterAccess;
        if (access == null) {
            throw new IllegalStateException("RenderCluster has not been loaded");
        }
        return access.apply(Objects.requireNonNull(cluster, "cluster"));
    }

    /** Called once by {@code RenderCluster}'s static initialiser. */
    public static void installClusterAccess(Function<Object, List<MemberFigures>> access) {
        if (clusterAccess != null) {
            throw new IllegalStateException("cluster access installed twice");
        }
        clusterAccess = Objects.requireNonNull(access, "access");
    }
}
