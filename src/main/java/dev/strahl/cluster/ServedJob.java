package dev.strahl.cluster;

import com.hazelcast.cluster.Member;
import com.hazelcast.core.HazelcastInstance;
import dev.strahl.io.json.SceneFile;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.units.UnitRenderer;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Comparator;
import java.util.UUID;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Stream;

/**
 * A job this member renders units of, for another member (its coordinator): at the first unit it
 * fetches the job's description and the files the cache lacks, lays them out in a folder of its
 * own, loads the scene and opens the renderer; the folder goes when the job ends.
 */
final class ServedJob {
    final String id;
    final UUID coordinator;
    final AtomicLong units = new AtomicLong();
    volatile UnitRenderer renderer;
    volatile String failure;
    volatile Path dir;
    boolean local;

    ServedJob(String id, UUID coordinator) {
        this.id = id;
        this.coordinator = coordinator;
    }

    synchronized UnitRenderer renderer(HazelcastMember member) throws IOException {
        if (renderer == null) {
            if (failure != null) {
                throw new IOException(failure);
            }
            try {
                renderer = prepare(member);
            } catch (IOException | RuntimeException e) {
                failure = e.getMessage() != null ? e.getMessage() : e.toString();
                member.log("job " + id + ": " + failure);
                throw e;
            }
        }
        return renderer;
    }

    /** Fetches the job's description and files from its coordinator, loads the scene and opens a renderer. */
    private UnitRenderer prepare(HazelcastMember member) throws IOException {
        HazelcastInstance hz = member.hazelcast();
        Path cache = member.cache();
        Member from = hz.getCluster().getMembers().stream().filter(m -> m.getUuid().equals(coordinator)).findFirst()
                .orElseThrow(() -> new IOException("the coordinator of job " + id + " has left"));
        JobFiles files = JobFiles.decode(fetch(hz, from, ""));
        Files.createDirectories(cache.resolve("files"));
        long fetched = 0;
        int fetchedFiles = 0;
        Path folder = cache.resolve("jobs").resolve(id.replaceAll("[^0-9a-z-]", "_"));
        dir = folder;
        for (var e : files.files().entrySet()) {
            Path cached = cache.resolve("files").resolve(e.getValue());
            if (!Files.isRegularFile(cached) || !JobFiles.hash(cached).equals(e.getValue())) {
                byte[] content = fetch(hz, from, e.getValue());
                if (!JobFiles.hash(content).equals(e.getValue())) {
                    throw new IOException("file " + e.getKey() + " arrived damaged");
                }
                Path tmp = Files.createTempFile(cached.getParent(), ".fetch", ".tmp");
                Files.write(tmp, content);
                Files.move(tmp, cached, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
                fetched += content.length;
                fetchedFiles++;
            }
            Path target = folder.resolve(e.getKey()).normalize();
            if (!target.startsWith(folder)) {
                throw new IOException("refused file name " + e.getKey());
            }
            Files.createDirectories(target.getParent());
            Files.copy(cached, target, StandardCopyOption.REPLACE_EXISTING);
        }
        Scene scene;
        try {
            scene = SceneFile.load(folder.resolve(files.sceneFile())).scene().withCamera(files.camera());
        } catch (SceneException e) {
            throw new IOException("cannot load the scene here: " + e.getMessage(), e);
        }
        UnitRenderer renderer = member.service().open(scene, files.settings(), files.digest(), member.options().threads());
        member.log("job " + id + " from " + HazelcastMember.name(from) + ": " + files.sceneFile() + " (" + files.files().size() + " files, "
                + fetchedFiles + " fetched, " + fetched + " bytes; the others from the cache)");
        return renderer;
    }

    private byte[] fetch(HazelcastInstance hz, Member from, String hash) throws IOException {
        try {
            var fetch = new Tasks.Fetch(id, coordinator, HazelcastMember.VERSION, hash);
            byte[] answer = hz.getExecutorService(HazelcastMember.FETCHES).submitToMember(fetch, from).get(120, TimeUnit.SECONDS);
            if (!Tasks.Answers.isOk(answer)) {
                throw new IOException(Tasks.Answers.message(answer));
            }
            byte[] result = new byte[answer.length - 1];
            System.arraycopy(answer, 1, result, 0, result.length);
            return result;
        } catch (ExecutionException | TimeoutException e) {
            throw new IOException("cannot fetch from the coordinator " + HazelcastMember.name(from) + ": " + HazelcastMember.rootMessage(e), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
    }

    /** Deletes the job's folder, if it made one. */
    void deleteFolder() {
        if (dir == null) {
            return;
        }
        try (Stream<Path> walk = Files.walk(dir)) {
            walk.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException e) {
            // a temporary folder: left for the system to clean
        }
    }
}
