package dev.strahl.cli;

import dev.strahl.render.RenderCluster;
import java.io.IOException;
import java.io.PrintWriter;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Callable;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code strahl worker}: a member of a render cluster that renders the units of the renders
 * started with {@code strahl render --cluster}, until Ctrl-C (or SIGTERM), which leaves the
 * cluster cleanly. Exit codes: 130/143 after a signal, 2 bad usage, an address that cannot be
 * bound, members to join of which none answers, or a cluster of another strahl version.
 */
@Command(name = "worker",
        mixinStandardHelpOptions = true,
        abbreviateSynopsis = true,
        versionProvider = Main.Version.class,
        description = {"Joins (or starts) a render cluster and renders parts of the renders started with 'strahl render --cluster',",
            "until Ctrl-C. Hazelcast's community edition has no authentication or encryption: run it on a trusted network only",
            "(docs/cluster.md)."},
        sortOptions = false)
final class WorkerCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = {"-q", "--quiet"}, description = "Print nothing but errors.")
    boolean quiet;

    @ArgGroup(validate = false, heading = "%nCluster:%n")
    Membership cluster = new Membership();

    @ArgGroup(validate = false, heading = "%nExecution:%n")
    ExecutionOptions execution = new ExecutionOptions();

    /** The members to join and the port, beside the address and cluster name that render --cluster shares. */
    static final class Membership extends ClusterAddress {
        @Option(names = "--join", paramLabel = "HOST[:PORT],...", split = ",", order = 1,
                description = "Members to join (none answering within 10 s is an error); without it this worker starts a cluster of its own that others join.")
        List<String> join = new ArrayList<>();

        @Option(names = "--port", defaultValue = "5701", order = 4, description = "The port to listen on (default: ${DEFAULT-VALUE}).")
        int port;
    }

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        int threads = execution.threads;
        if (threads < 0) {
            return usage(err, "--threads must be >= 0, got " + threads);
        }
        if (cluster.port < 1 || cluster.port > 65535) {
            return usage(err, "--port must be in 1..65535, got " + cluster.port);
        }
        if (cluster.clusterName.isBlank()) {
            return usage(err, "--cluster-name must not be empty");
        }
        try (SimdOption.Scope kernel = execution.apply(); Interrupts irq = Interrupts.install(err)) {
            var stop = new CountDownLatch(1);
            irq.onFirstSignal(stop::countDown, "leaving the cluster");
            RenderCluster member;
            try {
                member = RenderCluster.builder().join(cluster.join.toArray(String[]::new)).bind(cluster.bind).port(cluster.port)
                        .clusterName(cluster.clusterName)
                        .threads(threads).joinTimeout(Duration.ofSeconds(10)).log(line -> report(err, line)).start();
            } catch (IOException | IllegalStateException | IllegalArgumentException e) {
                err.println("strahl: " + e.getMessage());
                err.flush();
                return 2;
            }
            try (member) {
                stop.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            irq.written();
            return irq.interrupted() ? irq.exitCode() : 0;
        }
    }

    private void report(PrintWriter err, String line) {
        if (!quiet) {
            synchronized (err) {
                err.println("strahl worker: " + line);
                err.flush();
            }
        }
    }

    private static int usage(PrintWriter err, String message) {
        err.println("strahl: " + message + " (see 'strahl worker --help')");
        err.flush();
        return 2;
    }
}
