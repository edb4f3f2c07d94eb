package dev.strahl.units;

import java.io.IOException;

/**
 * This process as a member of a render cluster: it renders units of other members' jobs (with the
 * {@link UnitService} it was started with) and may coordinate jobs of its own. The implementation
 * (on Hazelcast) lives in a package above this one and is loaded only when a cluster is used.
 */
public interface ClusterBackend extends AutoCloseable {
    /**
     * Makes a job known to the cluster; members fetch its spec and files when they get its first unit.
     *
     * @param spec the job
     * @return the channel to send its units through
     * @throws IOException if the scene's files cannot be read
     */
    JobChannel open(JobSpec spec) throws IOException;

    /** Members of the cluster that run this strahl version (this one included). */
    int memberCount();

    /** Leaves the cluster. */
    @Override
    void close();
}
