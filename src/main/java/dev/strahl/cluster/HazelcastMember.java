package dev.strahl.cluster;

import com.hazelcast.cluster.Member;
import com.hazelcast.cluster.MembershipEvent;
import com.hazelcast.cluster.MembershipListener;
import com.hazelcast.config.Config;
import com.hazelcast.config.JavaSerializationFilterConfig;
import com.hazelcast.config.JoinConfig;
import com.hazelcast.config.NetworkConfig;
import com.hazelcast.core.Hazelcast;
import com.hazelcast.core.HazelcastInstance;
import com.hazelcast.core.IExecutorService;
import dev.strahl.units.ClusterBackend;
import dev.strahl.units.JobChannel;
import dev.strahl.units.JobSpec;
import dev.strahl.units.MemberOptions;
import dev.strahl.units.UnitRenderer;
import dev.strahl.units.UnitService;
import dev.strahl.units.WorkUnit;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

/**
 * This process as a Hazelcast member of a render cluster. Configured for a trusted network and
 * nothing more: TCP/IP join to the given members only (multicast, auto-detection and the cloud
 * discoveries off), bound to one address, no phone-home, Hazelcast's own logging off, and Java
 * deserialisation allowed for strahl's classes only (the messages, {@link Tasks}, do not use it).
 *
 * <p>Every member serves the jobs of others: a unit of an unknown job makes it fetch the job's
 * description and any file it does not have yet from the coordinator, load the scene and open a
 * renderer ({@link UnitService}); a job is dropped when its coordinator ends it or leaves. A
 * member coordinates its own jobs with a {@link CoordinatedJob} each.
 */
public final class HazelcastMember implements ClusterBackend, MembershipListener {
    static final String CONTEXT_KEY = "strahl.member";
    static final String UNITS = "strahl-units";
    static final String FETCHES = "strahl-fetches";
    static final String VERSION_ATTRIBUTE = "strahl.version";
    static final String THREADS_ATTRIBUTE = "strahl.threads";
    /** strahl's version and the cluster protocol's; {@code -Dstrahl.cluster.version} overrides it (the tests use that to play an old member). */
    static final String VERSION = System.getProperty("strahl.cluster.version", implementationVersion() + "/protocol-1");
    private static final AtomicLong JOBS = new AtomicLong();

    private final HazelcastInstance hz;
    private final UnitService service;
    private final MemberOptions options;
    private final Consumer<String> log;
    private final Path cache;
    private final Map<String, ServedJob> served = new ConcurrentHashMap<>();
    private final Map<String, CoordinatedJob> coordinated = new ConcurrentHashMap<>();
    private final Set<String> ended = ConcurrentHashMap.newKeySet();
    private final Set<UUID> refused = ConcurrentHashMap.newKeySet();
    private volatile boolean closed;

    static {
        // before the first Hazelcast class logs (it warns about JPMS access at once): its logging is off
        if (System.getProperty("hazelcast.logging.type") == null) {
            System.setProperty("hazelcast.logging.type", "none");
        }
    }

    private HazelcastMember(MemberOptions options, UnitService service) {
        this.options = options;
        this.service = service;
        this.log = options.log() != null ? options.log() : s -> { };
        this.cache = Path.of(System.getProperty("java.io.tmpdir"), "strahl-cluster-" + System.getProperty("user.name", "user"));
        Config config = config(options);
        config.getUserContext().put(CONTEXT_KEY, this);
        this.hz = Hazelcast.newHazelcastInstance(config);
    }

    /**
     * Starts a member and joins the cluster (looking for the given members up to the join timeout).
     *
     * @param options how to join
     * @param service renders the units of jobs
     * @return the member
     * @throws IOException if the address cannot be bound
     */
    public static ClusterBackend start(MemberOptions options, UnitService service) throws IOException {
        HazelcastMember member;
        try {
            member = new HazelcastMember(options, service);
        } catch (RuntimeException e) {
            throw new IOException("cannot start a cluster member on " + options.bind() + ": " + rootMessage(e), e);
        }
        int all = member.hz.getCluster().getMembers().size();
        if (all > 1 && member.compatibleMembers().size() == 1) {
            String theirs = member.hz.getCluster().getMembers().stream().filter(m -> !m.localMember())
                    .map(m -> m.getAttribute(VERSION_ATTRIBUTE)).distinct().reduce((a, b) -> a + ", " + b).orElse("?");
            member.hz.shutdown();
            throw new IOException("refused: the members at " + String.join(", ", options.join()) + " run strahl " + theirs
                    + ", this is strahl " + VERSION + " (run the same version on every machine)");
        }
        member.hz.getCluster().addMembershipListener(member);
        var a = member.hz.getCluster().getLocalMember().getAddress();
        member.log.accept("joined cluster '" + options.clusterName() + "' as " + a.getHost() + ":" + a.getPort() + " ("
                + member.hz.getCluster().getMembers().size() + " members, " + options.threads() + " threads here)");
        for (Member m : member.hz.getCluster().getMembers()) {
            member.checkVersion(m);
        }
        return member;
    }

    static String rootMessage(Throwable e) {
        while (e.getCause() != null && e.getCause() != e) {
            e = e.getCause();
        }
        return e.getMessage() != null ? e.getMessage() : e.toString();
    }

    private static String implementationVersion() {
        String v = HazelcastMember.class.getPackage().getImplementationVersion();
        return v != null ? v : "development";
    }

    private static Config config(MemberOptions o) {
        Config config = new Config();
        config.setClusterName(o.clusterName());
        config.setInstanceName("strahl-" + UUID.randomUUID());
        config.setProperty("hazelcast.phone.home.enabled", "false");
        config.setProperty("hazelcast.logging.type", System.getProperty("hazelcast.logging.type"));
        config.setProperty("hazelcast.shutdownhook.enabled", "false");
        config.setProperty("hazelcast.socket.bind.any", "false");
        config.setProperty("hazelcast.wait.seconds.before.join", "0");
        config.setProperty("hazelcast.max.wait.seconds.before.join", "1");
        config.setProperty("hazelcast.max.join.seconds", Long.toString(Math.max(1, o.joinTimeout().toSeconds())));
        config.setProperty("hazelcast.heartbeat.interval.seconds", "1");
        config.setProperty("hazelcast.max.no.heartbeat.seconds", "6");
        config.setProperty("hazelcast.health.monitoring.level", "OFF");
        config.setProperty("hazelcast.jmx", "false");
        config.setProperty("hazelcast.merge.first.run.delay.seconds", "5");
        config.setProperty("hazelcast.merge.next.run.delay.seconds", "5");
        NetworkConfig net = config.getNetworkConfig();
        net.setPort(o.port() == 0 ? MemberOptions.DEFAULT_PORT : o.port());
        net.setPortAutoIncrement(o.port() == 0);
        net.setPortCount(100);
        net.getInterfaces().setEnabled(true).addInterface(o.bind());
        net.getRestApiConfig().setEnabled(false);
        JoinConfig join = net.getJoin();
        join.getMulticastConfig().setEnabled(false);
        join.getAutoDetectionConfig().setEnabled(false);
        join.getTcpIpConfig().setEnabled(true).setConnectionTimeoutSeconds(5);
        for (String m : o.join()) {
            join.getTcpIpConfig().addMember(m);
        }
        config.getMemberAttributeConfig().setAttribute(VERSION_ATTRIBUTE, VERSION);
        config.getMemberAttributeConfig().setAttribute(THREADS_ATTRIBUTE, Integer.toString(o.threads()));
        config.getExecutorConfig(UNITS).setPoolSize(o.threads()).setStatisticsEnabled(false);
        config.getExecutorConfig(FETCHES).setPoolSize(4).setStatisticsEnabled(false);
        var serialization = config.getSerializationConfig();
        serialization.addDataSerializableFactory(Tasks.FACTORY_ID, new Tasks.Factory());
        var filter = new JavaSerializationFilterConfig();
        filter.getWhitelist().addPrefixes("dev.strahl.");
        filter.setDefaultsDisabled(true);
        serialization.setJavaSerializationFilterConfig(filter);
        return config;
    }

    // ---- the coordinator's side ----------------------------------------------------------------

    @Override
    public JobChannel open(JobSpec spec) throws IOException {
        String id = Long.toString(System.currentTimeMillis(), 36) + "-" + JOBS.incrementAndGet() + "-" + hz.getCluster().getLocalMember().getUuid().toString().substring(0, 8);
        Map<String, Path> byHash = new ConcurrentHashMap<>();
        JobFiles files = JobFiles.of(spec.sceneFile(), spec.camera(), spec.settings(), spec.digest(), byHash);
        var local = new ServedJob(id, localUuid());
        local.renderer = service.open(spec.scene(), spec.settings(), spec.digest(), options.threads());
        local.local = true;
        served.put(id, local);
        var job = new CoordinatedJob(this, id, files.encode(), byHash);
        coordinated.put(id, job);
        return job;
    }

    UUID localUuid() {
        return hz.getCluster().getLocalMember().getUuid();
    }

    IExecutorService units() {
        return hz.getExecutorService(UNITS);
    }

    /** Members running this strahl version, this one first, then by address. */
    List<Member> compatibleMembers() {
        List<Member> list = new ArrayList<>();
        for (Member m : hz.getCluster().getMembers()) {
            if (VERSION.equals(m.getAttribute(VERSION_ATTRIBUTE))) {
                list.add(m);
            }
        }
        list.sort(Comparator.comparing((Member m) -> !m.localMember()).thenComparing(m -> m.getAddress().toString()));
        return list;
    }

    static int threadsOf(Member m) {
        try {
            return Math.max(1, Integer.parseInt(m.getAttribute(THREADS_ATTRIBUTE)));
        } catch (NumberFormatException e) {
            return 1;
        }
    }

    static String name(Member m) {
        return m.getAddress().getHost() + ":" + m.getAddress().getPort();
    }

    void log(String line) {
        log.accept(line);
    }

    HazelcastInstance hazelcast() {
        return hz;
    }

    /** Where this member keeps shipped files by hash, and its jobs' folders. */
    Path cache() {
        return cache;
    }

    UnitService service() {
        return service;
    }

    MemberOptions options() {
        return options;
    }

    void ended(CoordinatedJob job) {
        coordinated.remove(job.id());
        served.remove(job.id());
        ended.add(job.id());
        if (closed) {
            return;
        }
        try {
            // waited for (briefly), so that the members hear of the end before this member may leave
            var answers = hz.getExecutorService(FETCHES).submitToAllMembers(new Tasks.EndJob(job.id(), localUuid(), VERSION));
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(3);
            for (var answer : answers.values()) {
                try {
                    answer.get(Math.max(1, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
                } catch (ExecutionException | TimeoutException e) {
                    // a member that left or is slow drops the job when this member leaves
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            // the cluster is shutting down: the members drop the job when this member leaves
        }
    }

    byte[] answerFetch(String job, String hash) throws IOException {
        CoordinatedJob j = coordinated.get(job);
        if (j == null) {
            return Tasks.Answers.failure("job " + job + " is not running (any more) on its coordinator");
        }
        if (hash.isEmpty()) {
            return Tasks.Answers.ok(j.description());
        }
        Path file = j.file(hash);
        if (file == null) {
            return Tasks.Answers.failure("job " + job + " has no file " + hash);
        }
        byte[] content = Files.readAllBytes(file);
        if (!JobFiles.hash(content).equals(hash)) {
            return Tasks.Answers.failure(file + " changed on the coordinator during the render");
        }
        return Tasks.Answers.ok(content);
    }

    // ---- the worker's side ---------------------------------------------------------------------

    byte[] renderUnit(String job, UUID coordinator, byte[] unitBytes) throws IOException {
        if (ended.contains(job)) {
            return Tasks.Answers.failure("job " + job + " has ended");
        }
        ServedJob j = served.computeIfAbsent(job, id -> new ServedJob(id, coordinator));
        UnitRenderer renderer = j.renderer(this);
        WorkUnit unit = WorkUnit.decode(unitBytes, 0);
        renderer.render(unit);
        j.units.incrementAndGet();
        return unit.encode(1);                     // the first byte 0: an answer with a result
    }

    void dropJob(String id, String why) {
        ended.add(id);
        ServedJob j = served.remove(id);
        if (j == null || j.local) {
            return;
        }
        if (j.renderer != null || j.failure != null) {
            log.accept("job " + id + " " + why + ": " + j.units.get() + " units rendered here");
        }
        j.deleteFolder();
    }

    private void checkVersion(Member m) {
        String v = m.getAttribute(VERSION_ATTRIBUTE);
        if (!VERSION.equals(v) && refused.add(m.getUuid())) {
            log.accept("refused member " + name(m) + ": it runs strahl " + v + ", this member strahl " + VERSION
                    + " (no work goes to it, none is taken from it)");
        }
    }

    @Override
    public void memberAdded(MembershipEvent event) {
        Member m = event.getMember();
        checkVersion(m);
        if (VERSION.equals(m.getAttribute(VERSION_ATTRIBUTE))) {
            log.accept("member " + name(m) + " joined (" + threadsOf(m) + " threads)");
        }
        for (CoordinatedJob j : coordinated.values()) {
            j.dispatch();
        }
    }

    @Override
    public void memberRemoved(MembershipEvent event) {
        Member m = event.getMember();
        if (VERSION.equals(m.getAttribute(VERSION_ATTRIBUTE))) {
            log.accept("member " + name(m) + " left");
        }
        for (ServedJob j : served.values()) {
            if (j.coordinator.equals(m.getUuid())) {
                dropJob(j.id, "dropped: its coordinator left");
            }
        }
        for (CoordinatedJob j : coordinated.values()) {
            j.dispatch();
        }
    }

    @Override
    public int memberCount() {
        return closed ? 0 : compatibleMembers().size();
    }

    @Override
    public void close() {
        if (closed) {
            return;
        }
        for (CoordinatedJob j : List.copyOf(coordinated.values())) {
            j.close();
        }
        closed = true;
        hz.shutdown();
    }


}
