package dev.strahl.units;

import java.util.List;
import java.util.concurrent.CompletableFuture;

/** One job on the cluster, as its coordinator sees it. */
public interface JobChannel extends AutoCloseable {
    /**
     * Has the unit rendered by some member. A member that leaves or dies hands its units back,
     * and they are rendered elsewhere.
     *
     * @param unit the unit with its tile's state
     * @return the rendered unit; completes exceptionally only when the job cannot go on
     */
    CompletableFuture<WorkUnit> submit(WorkUnit unit);

    /** Members that take units of this job now (this one included). */
    int members();

    /** Threads of those members. */
    int threads();

    /**
     * What each member has done for this job so far (a unit lost is counted where it was rendered
     * in the end, not where it was lost).
     *
     * @param make makes the record of one member's figures
     * @param <M>  the record
     * @return one record per member that took part
     */
    <M> List<M> figures(MemberFigures<M> make);

    /** The job has ended: members drop it. */
    @Override
    void close();
}
