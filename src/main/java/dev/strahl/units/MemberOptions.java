package dev.strahl.units;

import java.time.Duration;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * How this process joins a cluster.
 *
 * @param join        members to join, "host" or "host:port"; empty to start a cluster of one
 * @param bind        the address to bind to and be reached at
 * @param port        the port; 0 for the first free one from 5701
 * @param clusterName the cluster's name: only members with the same name join
 * @param threads     threads this member renders units on
 * @param joinTimeout how long to look for the members to join
 * @param log         where the member reports what it does (one line each), or null for nothing
 */
public record MemberOptions(List<String> join, String bind, int port, String clusterName, int threads, Duration joinTimeout,
                            Consumer<String> log) {
    /** Default port of the first member on a machine. */
    public static final int DEFAULT_PORT = 5701;
    /** Default cluster name. */
    public static final String DEFAULT_NAME = "strahl";

    /**
     * Checks the options.
     *
     * @param join        members to join
     * @param bind        the address to bind to
     * @param port        the port
     * @param clusterName the cluster's name
     * @param threads     render threads, positive
     * @param joinTimeout how long to look for members
     * @param log         where to report, or null
     */
    public MemberOptions {
        join = List.copyOf(join);
        Objects.requireNonNull(bind, "bind");
        Objects.requireNonNull(clusterName, "clusterName");
        Objects.requireNonNull(joinTimeout, "joinTimeout");
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be in 0..65535, got " + port);
        }
        if (threads <= 0) {
            throw new IllegalArgumentException("threads must be positive, got " + threads);
        }
        if (clusterName.isBlank()) {
            throw new IllegalArgumentException("the cluster name must not be empty");
        }
    }
}
