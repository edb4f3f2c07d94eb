package dev.strahl.render;

import dev.strahl.scene.Scene;
import dev.strahl.units.ClusterBackend;
import dev.strahl.units.JobChannel;
import dev.strahl.units.JobSpec;
import dev.strahl.units.MemberOptions;
import dev.strahl.units.UnitService;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * This process as a member of a render cluster (on Hazelcast, embedded): it renders work units of
 * the cluster's renders, and {@link #render} spreads a render of its own over every member. The
 * image is bit-identical to {@link RenderJob#start} at the same seed and settings, whatever the
 * number of members and whoever renders which part; the returned {@link RenderJob} has the same
 * listener, snapshot, pause, checkpoint and cancel as a local one. docs/cluster.md tells how to run
 * one, and that a cluster belongs on a trusted network (no authentication, no encryption).
 *
 * <pre>{@code
 * try (RenderCluster cluster = RenderCluster.builder().join("192.168.1.20").bind("192.168.1.10").start();
 *      RenderJob job = cluster.render(scene, sceneFile, settings, listener)) {
 *     Image image = job.awaitCompletion();
 * }
 * }</pre>
 *
 * <p>Needs {@code com.hazelcast:hazelcast} on the class or module path (an optional dependency of
 * strahl); without a cluster, no Hazelcast class is ever loaded.
 */
public final class RenderCluster implements AutoCloseable {
    private static final String BACKEND = "dev.strahl.cluster.HazelcastMember";

    private final ClusterBackend backend;

    private RenderCluster(ClusterBackend backend) {
        this.backend = backend;
    }

    /**
     * A builder of a member, with the defaults: join nobody (a cluster of one that others may
     * join), bind to 127.0.0.1, port 5701 (or the next free one), cluster name "strahl", one
     * render thread per processor.
     *
     * @return the builder
     */
    public static Builder builder() {
        return new Builder();
    }

    /**
     * Renders {@code scene} on the cluster: sends every member the scene file and each file it
     * references (they cache them by content), and renders a part here too.
     *
     * @param scene     the scene, loaded from {@code sceneFile} (its camera may have been replaced)
     * @param sceneFile the file it was loaded from, which the members load
     * @param settings  how to render; the thread count is this member's (each member has its own)
     * @param listener  hears about every pass and the end
     * @return the running job
     * @throws IOException if a file of the scene cannot be read
     * @throws IllegalArgumentException if the integrator cannot render on a cluster (the photon mapper)
     */
    public RenderJob render(Scene scene, Path sceneFile, RenderSettings settings, RenderListener listener) throws IOException {
        try {
            return start(scene, sceneFile, settings, listener, null);
        } catch (CheckpointException e) {
            throw new IllegalStateException(e);          // no checkpoint is read
        }
    }

    /**
     * Continues on the cluster a render saved in a checkpoint (by a local or a cluster render):
     * as {@link RenderJob#resumeFrom}, bit-identical to a render never interrupted.
     *
     * @param checkpoint the checkpoint file
     * @param scene      the scene of the saved render, loaded from {@code sceneFile}
     * @param sceneFile  the file it was loaded from
     * @param settings   the settings of the saved render; the sample count may be higher
     * @param listener   hears about every pass and the end
     * @return the running job
     * @throws CheckpointException if the checkpoint is unreadable or of another render
     * @throws IOException         if it or a file of the scene cannot be read
     */
    public RenderJob resume(Path checkpoint, Scene scene, Path sceneFile, RenderSettings settings, RenderListener listener)
            throws CheckpointException, IOException {
        return start(scene, sceneFile, settings, listener, Objects.requireNonNull(checkpoint, "checkpoint"));
    }

    private RenderJob start(Scene scene, Path sceneFile, RenderSettings settings, RenderListener listener, Path checkpoint)
            throws CheckpointException, IOException {
        Objects.requireNonNull(scene, "scene");
        Objects.requireNonNull(sceneFile, "sceneFile");
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(listener, "listener");
        if (settings.transport().integrator() == IntegratorKind.PHOTON) {
            throw new IllegalArgumentException("the photon mapper cannot render on a cluster (each sample needs the photon map of the whole scene)");
        }
        byte[] digest = Checkpoint.of(scene, settings).sceneDigestBytes();
        JobChannel channel = backend.open(new JobSpec(sceneFile, scene.camera(),
                UnitRenderers.encode(settings, SampleLoop.stratifiedSampler()), digest, scene));
        try {
            return RenderJob.launch(scene, settings, listener, checkpoint, film -> new ClusterPasses(film, channel));
        } catch (CheckpointException | IOException | RuntimeException e) {
            channel.close();
            throw e;
        }
    }

    /**
     * Members of the cluster that run this strahl version, this one included.
     *
     * @return the count
     */
    public int memberCount() {
        return backend.memberCount();
    }

    /** Leaves the cluster: the renders it coordinates end, the members drop them. */
    @Override
    public void close() {
        backend.close();
    }

    /** How this process joins a cluster; {@link #start()} joins. */
    public static final class Builder {
        private final List<String> join = new ArrayList<>();
        private String bind = "127.0.0.1";
        private int port;
        private String name = MemberOptions.DEFAULT_NAME;
        private int threads;
        private Duration joinTimeout = Duration.ofSeconds(10);
        private Consumer<String> log;

        private Builder() {}

        /**
         * Members to join.
         *
         * @param members "host" or "host:port" of each (the port defaults to 5701)
         * @return this builder
         */
        public Builder join(String... members) {
            join.addAll(List.of(members));
            return this;
        }

        /**
         * The network address to bind to; the other members reach this one there.
         *
         * @param address an IP address of this machine
         * @return this builder
         */
        public Builder bind(String address) {
            this.bind = Objects.requireNonNull(address, "address");
            return this;
        }

        /**
         * The port to listen on.
         *
         * @param port 1..65535; 0 for 5701 or the next free one
         * @return this builder
         */
        public Builder port(int port) {
            this.port = port;
            return this;
        }

        /**
         * The cluster's name: only members with the same name form a cluster.
         *
         * @param name the name
         * @return this builder
         */
        public Builder clusterName(String name) {
            this.name = Objects.requireNonNull(name, "name");
            return this;
        }

        /**
         * Threads this member renders units on.
         *
         * @param threads positive; 0 for one per processor
         * @return this builder
         */
        public Builder threads(int threads) {
            this.threads = threads;
            return this;
        }

        /**
         * How long {@link #start()} looks for the members to join.
         *
         * @param timeout the time
         * @return this builder
         */
        public Builder joinTimeout(Duration timeout) {
            this.joinTimeout = Objects.requireNonNull(timeout, "timeout");
            return this;
        }

        /**
         * Where the member reports, one line each, the jobs it works on and the members that
         * come and go (by default nowhere).
         *
         * @param log receives the lines, on the cluster's threads
         * @return this builder
         */
        public Builder log(Consumer<String> log) {
            this.log = log;
            return this;
        }

        /**
         * Starts the member and joins the cluster.
         *
         * @return the member
         * @throws IOException if members to join were given and none of them answered within the
         *                     join timeout, or the address cannot be bound
         * @throws IllegalStateException if Hazelcast is not on the class or module path
         */
        public RenderCluster start() throws IOException {
            int t = threads > 0 ? threads : Runtime.getRuntime().availableProcessors();
            var options = new MemberOptions(join, bind, port, name, t, joinTimeout, log);
            ClusterBackend backend;
            try {
                backend = (ClusterBackend) Class.forName(BACKEND).getMethod("start", MemberOptions.class, UnitService.class)
                        .invoke(null, options, new UnitRenderers());
            } catch (ClassNotFoundException | NoClassDefFoundError e) {
                throw new IllegalStateException("a cluster needs Hazelcast: add com.hazelcast:hazelcast 5.7.0 to the class or module path", e);
            } catch (InvocationTargetException e) {
                if (e.getCause() instanceof IOException io) {
                    throw io;
                }
                if (e.getCause() instanceof RuntimeException r) {
                    throw r;
                }
                if (e.getCause() instanceof NoClassDefFoundError n) {
                    throw new IllegalStateException("a cluster needs Hazelcast: add com.hazelcast:hazelcast 5.7.0 to the class or module path", n);
                }
                throw new IllegalStateException(e.getCause());
            } catch (ReflectiveOperationException e) {
                throw new IllegalStateException(e);
            }
            if (!join.isEmpty() && backend.memberCount() < 2) {
                backend.close();
                throw new IOException("no strahl member answered at " + String.join(", ", join) + " within "
                        + joinTimeout.toSeconds() + " s (is a 'strahl worker' running there, with the same --cluster-name, reachable through the firewall?)");
            }
            return new RenderCluster(backend);
        }
    }
}
