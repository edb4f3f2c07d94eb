package dev.strahl.cli;

import picocli.CommandLine.Option;

/** Where a cluster member listens and which cluster it is in: what {@code render --cluster} and {@code worker} share. */
class ClusterAddress {

    @Option(names = "--bind", paramLabel = "ADDR", defaultValue = "127.0.0.1", order = 3,
            description = "The address this member listens on and the others reach it at (default: ${DEFAULT-VALUE}; give this machine's"
                    + " LAN address for a cluster of machines).")
    String bind;

    @Option(names = "--cluster-name", paramLabel = "NAME", defaultValue = "strahl", order = 2,
            description = "The cluster's name: only members with the same name form a cluster (default: ${DEFAULT-VALUE}).")
    String clusterName;
}
