package dev.strahl.cluster;

import com.hazelcast.cluster.Member;
import com.hazelcast.core.ExecutionCallback;
import dev.strahl.units.JobChannel;
import dev.strahl.units.MemberFigures;
import dev.strahl.units.WorkUnit;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;

/**
 * A job this member coordinates: a queue of units and, per member, the units out to it. A member
 * gets units while it has fewer out than its threads plus one (one waiting in its queue while the
 * others render), so a fast member gets more and a member that joins late gets some at once. A
 * unit out to a member that leaves or dies comes back with a failure from Hazelcast and goes to
 * the front of the queue; a member that answers with an error (it cannot load the scene, say) is
 * not sent this job's units again, and a unit that failed on three members fails the job.
 */
final class CoordinatedJob implements JobChannel {
    private static final int MAX_ATTEMPTS = 3;

    private final HazelcastMember node;
    private final String id;
    private final byte[] description;
    private final Map<String, Path> files;
    private final ArrayDeque<Pending> queue = new ArrayDeque<>();
    private final Map<UUID, Slot> slots = new LinkedHashMap<>();
    private boolean closed;
    private String lastError;
    private int turn;

    CoordinatedJob(HazelcastMember node, String id, byte[] description, Map<String, Path> files) {
        this.node = node;
        this.id = id;
        this.description = description;
        this.files = files;
    }

    String id() {
        return id;
    }

    byte[] description() {
        return description;
    }

    Path file(String hash) {
        return files.get(hash);
    }

    @Override
    public CompletableFuture<WorkUnit> submit(WorkUnit unit) {
        var p = new Pending(unit, unit.samples());
        synchronized (this) {
            if (closed) {
                p.result.completeExceptionally(new CancellationException("job " + id + " has ended"));
                return p.result;
            }
            queue.add(p);
        }
        dispatch();
        return p.result;
    }

    /** Sends queued units to members with room for them, one at a time round the members. */
    void dispatch() {
        List<Pending> failed = new ArrayList<>();
        synchronized (this) {
            if (closed) {
                return;
            }
            List<Slot> open = new ArrayList<>();
            for (Member m : node.compatibleMembers()) {
                Slot s = slots.computeIfAbsent(m.getUuid(), u -> new Slot(m));
                s.member = m;
                if (!s.excluded) {
                    open.add(s);
                }
            }
            if (open.isEmpty()) {
                failed.addAll(queue);
                queue.clear();
            }
            while (!queue.isEmpty()) {
                Slot s = leastLoaded(open);
                if (s == null) {
                    break;
                }
                send(queue.poll(), s);
            }
        }
        for (Pending p : failed) {
            p.result.completeExceptionally(new IOException("no member can render job " + id + (lastError != null ? ": " + lastError : "")));
        }
    }

    /**
     * The member with room (fewer units out than its threads plus one) that has the fewest out per
     * thread; among equals the one whose turn it is, so that units spread over all members even
     * when there are fewer than they have room for.
     */
    private Slot leastLoaded(List<Slot> open) {
        Slot best = null;
        double bestLoad = Double.MAX_VALUE;
        int n = open.size();
        for (int i = 0; i < n; i++) {
            Slot s = open.get((turn + i) % n);
            double load = (double) s.out / s.threads;
            if (s.out < s.threads + 1 && load < bestLoad) {
                best = s;
                bestLoad = load;
            }
        }
        if (best != null) {
            turn = (open.indexOf(best) + 1) % n;
        }
        return best;
    }

    private void send(Pending p, Slot s) {
        byte[] bytes = p.unit.encode(0);
        s.out++;
        s.sent += bytes.length;
        long start = System.nanoTime();
        var task = new Tasks.RenderUnit(id, node.localUuid(), HazelcastMember.VERSION, bytes);
        try {
            node.units().submitToMember(task, s.member, new ExecutionCallback<byte[]>() {
                @Override
                public void onResponse(byte[] answer) {
                    done(p, s, answer, null, start);
                }

                @Override
                public void onFailure(Throwable t) {
                    done(p, s, null, t, start);
                }
            });
        } catch (RuntimeException e) {
            s.out--;
            s.lost++;
            queue.addFirst(p);
        }
    }

    private void done(Pending p, Slot s, byte[] answer, Throwable failure, long start) {
        WorkUnit result = null;
        Throwable fatal = null;
        synchronized (this) {
            s.out--;
            if (closed) {
                return;
            }
            if (answer != null && Tasks.Answers.isOk(answer)) {
                try {
                    result = WorkUnit.decode(answer, 1);
                    s.units++;
                    s.samples += p.samples;
                    s.received += answer.length;
                    s.seconds += (System.nanoTime() - start) * 1e-9;
                } catch (IOException e) {
                    answer = Tasks.Answers.failure("a damaged unit came back: " + e.getMessage());
                }
            }
            if (result == null) {
                if (answer != null) {
                    // the member answered, but could not render: it gets no more units of this job
                    String message = Tasks.Answers.message(answer);
                    lastError = HazelcastMember.name(s.member) + ": " + message;
                    if (!s.excluded) {
                        s.excluded = true;
                        node.log("job " + id + ": member " + HazelcastMember.name(s.member) + " cannot render it: " + message);
                    }
                    p.attempts++;
                } else {
                    s.lost++;                      // it left or died: the unit goes elsewhere, not counted as an attempt
                }
                if (p.attempts >= MAX_ATTEMPTS) {
                    fatal = new IOException("a unit of job " + id + " failed on " + MAX_ATTEMPTS + " members; the last said: " + lastError);
                } else {
                    queue.addFirst(p);
                }
            }
        }
        if (result != null) {
            p.result.complete(result);
        } else if (fatal != null) {
            p.result.completeExceptionally(fatal);
        }
        dispatch();
    }

    @Override
    public synchronized int members() {
        int n = 0;
        for (Member m : node.compatibleMembers()) {
            Slot s = slots.get(m.getUuid());
            n += s == null || !s.excluded ? 1 : 0;
        }
        return n;
    }

    @Override
    public synchronized int threads() {
        int n = 0;
        for (Member m : node.compatibleMembers()) {
            Slot s = slots.get(m.getUuid());
            n += s == null || !s.excluded ? HazelcastMember.threadsOf(m) : 0;
        }
        return n;
    }

    @Override
    public synchronized <M> List<M> figures(MemberFigures<M> make) {
        List<M> list = new ArrayList<>();
        for (Slot s : slots.values()) {
            list.add(make.of(HazelcastMember.name(s.member), s.member.localMember(), s.threads,
                    s.units, s.samples, s.sent, s.received, s.seconds, s.lost));
        }
        return list;
    }

    @Override
    public void close() {
        List<Pending> left;
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
            left = new ArrayList<>(queue);
            queue.clear();
        }
        for (Pending p : left) {
            p.result.completeExceptionally(new CancellationException("job " + id + " has ended"));
        }
        node.ended(this);
    }

    /** A unit waiting or out, with its result to complete. */
    private static final class Pending {
        final WorkUnit unit;
        final long samples;
        final CompletableFuture<WorkUnit> result = new CompletableFuture<>();
        int attempts;

        Pending(WorkUnit unit, long samples) {
            this.unit = unit;
            this.samples = samples;
        }
    }

    /** What this job has out to one member, and what the member did. */
    private static final class Slot {
        Member member;
        final int threads;
        int out;
        boolean excluded;
        long units;
        long samples;
        long sent;
        long received;
        long lost;
        double seconds;

        Slot(Member m) {
            this.member = m;
            this.threads = HazelcastMember.threadsOf(m);
        }
    }
}
