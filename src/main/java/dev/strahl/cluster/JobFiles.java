package dev.strahl.cluster;

import dev.strahl.files.FileReads;
import dev.strahl.io.json.SceneFile;
import dev.strahl.scene.Camera;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.DigestInputStream;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.joml.Vector3d;

/**
 * A job as the members learn it: the scene file and every file it references, each by its path
 * below their common folder and the SHA-256 of its content (members keep the files by that
 * hash, so a file shipped once is not shipped again for the next job), with the camera, the
 * encoded settings and the scene's fingerprint.
 *
 * @param sceneFile the scene file, relative to the common folder
 * @param files     relative path → content hash, the scene file included
 * @param sizes     relative path → bytes
 * @param camera    the camera to render with
 * @param settings  the settings, by name, as the render package wrote them
 * @param digest    the fingerprint of the coordinator's scene
 */
record JobFiles(String sceneFile, Map<String, String> files, Map<String, Long> sizes, Camera camera, String settings, byte[] digest) {
    private static final int FORMAT = 2;

    /**
     * Finds the files of a scene (by loading it and noting every file a reader opens) and hashes them.
     *
     * @param sceneFile the scene file on the coordinator
     * @param byHash    receives content hash → absolute path, to answer the members' fetches
     */
    static JobFiles of(Path sceneFile, Camera camera, String settings, byte[] digest, Map<String, Path> byHash) throws IOException {
        var read = new TreeSet<Path>();
        Path scene = sceneFile.toAbsolutePath().normalize();
        read.add(scene);
        try {
            FileReads.recording(read, () -> SceneFile.load(scene));
        } catch (IOException e) {
            throw e;
        } catch (Exception e) {
            throw new IOException(e.getMessage(), e);
        }
        Path root = scene.getParent();
        for (Path p : read) {
            while (!p.startsWith(root)) {
                root = root.getParent();
            }
        }
        var files = new LinkedHashMap<String, String>();
        var sizes = new LinkedHashMap<String, Long>();
        for (Path p : read) {
            String hash = hash(p);
            String rel = root.relativize(p).toString().replace('\\', '/');
            files.put(rel, hash);
            sizes.put(rel, Files.size(p));
            byHash.put(hash, p);
        }
        return new JobFiles(root.relativize(scene).toString().replace('\\', '/'), files, sizes, camera, settings, digest);
    }

    static String hash(Path file) throws IOException {
        MessageDigest sha = sha256();
        try (InputStream in = new DigestInputStream(Files.newInputStream(file), sha)) {
            in.transferTo(OutputStreams.NULL);
        }
        return HexFormat.of().formatHex(sha.digest());
    }

    static String hash(byte[] content) {
        return HexFormat.of().formatHex(sha256().digest(content));
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    byte[] encode() {
        var bytes = new ByteArrayOutputStream();
        try (var out = new DataOutputStream(bytes)) {
            out.writeInt(FORMAT);
            out.writeUTF(sceneFile);
            for (Vector3d v : List.of(new Vector3d(camera.lookFrom()), new Vector3d(camera.lookAt()), new Vector3d(camera.up()))) {
                out.writeDouble(v.x);
                out.writeDouble(v.y);
                out.writeDouble(v.z);
            }
            out.writeDouble(camera.fovDegrees());
            out.writeDouble(camera.aperture());
            out.writeDouble(camera.focusDistance());
            out.writeUTF(settings);
            out.writeInt(digest.length);
            out.write(digest);
            out.writeInt(files.size());
            for (var e : files.entrySet()) {
                out.writeUTF(e.getKey());
                out.writeUTF(e.getValue());
                out.writeLong(sizes.get(e.getKey()));
            }
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
        return bytes.toByteArray();
    }

    /** Reads what {@link #encode} wrote; refuses paths that would leave the job's folder. */
    static JobFiles decode(byte[] data) throws IOException {
        var in = new DataInputStream(new ByteArrayInputStream(data));
        int format = in.readInt();
        if (format != FORMAT) {
            throw new IOException("job description of format " + format + "; this strahl reads " + FORMAT);
        }
        String scene = safe(in.readUTF());
        var from = new Vector3d(in.readDouble(), in.readDouble(), in.readDouble());
        var at = new Vector3d(in.readDouble(), in.readDouble(), in.readDouble());
        var up = new Vector3d(in.readDouble(), in.readDouble(), in.readDouble());
        var camera = new Camera(from, at, up, in.readDouble(), in.readDouble(), in.readDouble());
        String settings = in.readUTF();
        byte[] digest = in.readNBytes(checkedLength(in.readInt()));
        int n = in.readInt();
        if (n < 1 || n > 1_000_000) {
            throw new IOException("job description with " + n + " files");
        }
        var files = new LinkedHashMap<String, String>();
        var sizes = new LinkedHashMap<String, Long>();
        for (int i = 0; i < n; i++) {
            String rel = safe(in.readUTF());
            String hash = in.readUTF();
            if (!hash.matches("[0-9a-f]{64}")) {
                throw new IOException("bad content hash in job description");
            }
            files.put(rel, hash);
            sizes.put(rel, in.readLong());
        }
        return new JobFiles(scene, files, sizes, camera, settings, digest);
    }

    private static int checkedLength(int n) throws IOException {
        if (n < 0 || n > 1 << 20) {
            throw new IOException("bad length " + n + " in job description");
        }
        return n;
    }

    /** A relative path that stays inside the folder it is resolved against. */
    static String safe(String rel) throws IOException {
        List<String> parts = new ArrayList<>(List.of(rel.split("/", -1)));
        if (rel.isEmpty() || rel.startsWith("/") || rel.contains("\\") || rel.contains(":") || rel.indexOf('\0') >= 0
                || parts.stream().anyMatch(p -> p.isEmpty() || p.equals(".") || p.equals(".."))) {
            throw new IOException("refused file name " + rel + " in job description");
        }
        return rel;
    }

    /** A sink for hashing. */
    private static final class OutputStreams {
        static final java.io.OutputStream NULL = java.io.OutputStream.nullOutputStream();
    }
}
