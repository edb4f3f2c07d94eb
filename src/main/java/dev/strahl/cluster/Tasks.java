package dev.strahl.cluster;

import com.hazelcast.core.HazelcastInstance;
import com.hazelcast.core.HazelcastInstanceAware;
import com.hazelcast.nio.ObjectDataInput;
import com.hazelcast.nio.ObjectDataOutput;
import com.hazelcast.nio.serialization.DataSerializableFactory;
import com.hazelcast.nio.serialization.IdentifiedDataSerializable;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.UUID;
import java.util.concurrent.Callable;

/**
 * The messages between members, each a task run on the member it is sent to. They are
 * {@link IdentifiedDataSerializable}: read field by field by strahl's own code, made by
 * {@link Factory} from a class id, never by Java serialisation (which the member's configuration
 * restricts to strahl's classes anyway). Every answer is a byte array whose first byte says
 * whether it holds the result (0) or a message why not (1), so that no exception object crosses
 * the network either.
 */
final class Tasks {
    static final int FACTORY_ID = 0x57a41;
    static final int RENDER_UNIT = 1;
    static final int FETCH = 2;
    static final int END_JOB = 3;

    private Tasks() {}

    /** Makes the tasks from their class ids, for Hazelcast's serialisation. */
    static final class Factory implements DataSerializableFactory {
        @Override
        public IdentifiedDataSerializable create(int typeId) {
            return switch (typeId) {
                case RENDER_UNIT -> new RenderUnit();
                case FETCH -> new Fetch();
                case END_JOB -> new EndJob();
                default -> null;
            };
        }
    }

    /**
     * What every task carries: the job, its coordinator, the sender's strahl version and what it is
     * about (a work unit, a content hash, nothing); and the member it runs on.
     */
    abstract static class Base implements Callable<byte[]>, IdentifiedDataSerializable, HazelcastInstanceAware {
        String job;
        UUID coordinator;
        String version;
        byte[] payload;
        transient HazelcastMember member;

        Base() {}

        Base(String job, UUID coordinator, String version, byte[] payload) {
            this.job = job;
            this.coordinator = coordinator;
            this.version = version;
            this.payload = payload;
        }

        @Override
        public void setHazelcastInstance(HazelcastInstance instance) {
            this.member = (HazelcastMember) instance.getUserContext().get(HazelcastMember.CONTEXT_KEY);
        }

        @Override
        public int getFactoryId() {
            return FACTORY_ID;
        }

        @Override
        public void writeData(ObjectDataOutput out) throws IOException {
            out.writeString(job);
            out.writeLong(coordinator.getMostSignificantBits());
            out.writeLong(coordinator.getLeastSignificantBits());
            out.writeString(version);
            out.writeByteArray(payload);
        }

        @Override
        public void readData(ObjectDataInput in) throws IOException {
            job = in.readString();
            coordinator = new UUID(in.readLong(), in.readLong());
            version = in.readString();
            payload = in.readByteArray();
        }

        @Override
        public final byte[] call() {
            if (member == null) {
                return Answers.failure("this member is shutting down");
            }
            if (!HazelcastMember.VERSION.equals(version)) {
                return Answers.failure("refused: the coordinator runs strahl " + version + ", this member strahl " + HazelcastMember.VERSION);
            }
            try {
                return run();
            } catch (RuntimeException | IOException e) {
                return Answers.failure(e.getMessage() != null ? e.getMessage() : e.toString());
            } catch (OutOfMemoryError e) {
                return Answers.failure("out of memory on this member");
            }
        }

        abstract byte[] run() throws IOException;
    }

    /** Render one work unit of a job (sent by its coordinator to any member, itself included); the payload is the unit. */
    static final class RenderUnit extends Base {
        RenderUnit() {}

        RenderUnit(String job, UUID coordinator, String version, byte[] unit) {
            super(job, coordinator, version, unit);
        }

        @Override
        byte[] run() throws IOException {
            return member.renderUnit(job, coordinator, payload);
        }

        @Override
        public int getClassId() {
            return RENDER_UNIT;
        }
    }

    /** Fetch a job's description (an empty hash) or one of its files by content hash, the payload (sent to the coordinator). */
    static final class Fetch extends Base {
        Fetch() {}

        Fetch(String job, UUID coordinator, String version, String hash) {
            super(job, coordinator, version, hash.getBytes(StandardCharsets.US_ASCII));
        }

        @Override
        byte[] run() throws IOException {
            return member.answerFetch(job, new String(payload, StandardCharsets.US_ASCII));
        }

        @Override
        public int getClassId() {
            return FETCH;
        }
    }

    /** A job has ended: drop it (sent by its coordinator to every member). */
    static final class EndJob extends Base {
        EndJob() {}

        EndJob(String job, UUID coordinator, String version) {
            super(job, coordinator, version, new byte[0]);
        }

        @Override
        byte[] run() {
            member.dropJob(job, "finished");
            return Answers.ok(new byte[0]);
        }

        @Override
        public int getClassId() {
            return END_JOB;
        }
    }

    /** The first byte of an answer: 0 and the result, or 1 and a UTF-8 message. */
    static final class Answers {
        private Answers() {}

        static byte[] ok(byte[] result) {
            byte[] a = new byte[result.length + 1];
            System.arraycopy(result, 0, a, 1, result.length);
            return a;
        }

        static byte[] failure(String message) {
            byte[] m = message.getBytes(java.nio.charset.StandardCharsets.UTF_8);
            byte[] a = new byte[m.length + 1];
            a[0] = 1;
            System.arraycopy(m, 0, a, 1, m.length);
            return a;
        }

        static boolean isOk(byte[] answer) {
            return answer.length > 0 && answer[0] == 0;
        }

        static String message(byte[] answer) {
            return answer.length == 0 ? "empty answer" : new String(answer, 1, answer.length - 1, java.nio.charset.StandardCharsets.UTF_8);
        }
    }
}
