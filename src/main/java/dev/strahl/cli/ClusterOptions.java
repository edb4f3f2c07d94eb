package dev.strahl.cli;

import dev.strahl.render.IntegratorKind;
import dev.strahl.render.RenderCluster;
import dev.strahl.render.RenderSettings;
import java.io.IOException;
import java.io.PrintWriter;
import java.time.Duration;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.Option;

/** {@code render}'s "Cluster" section: render with the {@code strahl worker}s there (docs/cluster.md). */
final class ClusterOptions extends ClusterAddress {

    @Option(names = "--cluster", paramLabel = "HOST[:PORT],...", split = ",", order = 1,
            description = "Render on a cluster: join the 'strahl worker' members there and render with them (docs/cluster.md);"
                    + " the image is the same bits as without. --bind, --port and --cluster-name need it.")
    List<String> cluster;

    @Option(names = "--port", defaultValue = "0", order = 4,
            description = "The port this member listens on; 0 = 5701 or the next free one (default: ${DEFAULT-VALUE}).")
    int port;

    /** Checks the cluster options before anything is loaded: they need --cluster, and a port in range. */
    void check(CommandLine.ParseResult parsed) {
        if (cluster == null) {
            for (String option : List.of("--cluster-name", "--bind", "--port")) {
                if (parsed.hasMatchedOption(option)) {
                    throw new IllegalArgumentException(option + " needs --cluster");
                }
            }
            return;
        }
        if (cluster.isEmpty() || cluster.stream().anyMatch(String::isBlank)) {
            throw new IllegalArgumentException("--cluster: give the members to join as HOST[:PORT],...");
        }
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("--port must be in 0..65535, got " + port);
        }
        if (clusterName.isBlank()) {
            throw new IllegalArgumentException("--cluster-name must not be empty");
        }
    }

    /** Joins the cluster (a member that renders too); null without --cluster. */
    RenderCluster join(RenderSettings settings, boolean quiet, PrintWriter err) {
        if (cluster == null) {
            return null;
        }
        if (settings.transport().integrator() == IntegratorKind.PHOTON) {
            throw new IllegalArgumentException("--cluster: the photon mapper cannot render on a cluster (each sample needs the photon map of the whole scene)");
        }
        try {
            return RenderCluster.builder().join(cluster.toArray(String[]::new)).bind(bind).port(port).clusterName(clusterName)
                    .threads(settings.execution().threads()).joinTimeout(Duration.ofSeconds(10))
                    .log(quiet ? null : line -> {
                        synchronized (err) {
                            err.println("strahl: cluster: " + line);
                            err.flush();
                        }
                    }).start();
        } catch (IOException | IllegalStateException e) {
            throw new IllegalArgumentException("--cluster: " + e.getMessage(), e);
        }
    }
}
