package dev.strahl.render;

import dev.strahl.scene.Camera;
import dev.strahl.files.AtomicFile;
import dev.strahl.film.Film;
import dev.strahl.integrator.FeatureTracer;
import dev.strahl.world.World;
import dev.strahl.scene.Scene;
import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.UTFDataFormatException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.zip.CRC32C;
import java.util.zip.CheckedOutputStream;

/**
 * The saved state of a render, so that a long render survives an interruption: per pixel the
 * sample count and the r, g, b sums of the film, with a fingerprint of everything that decides
 * the image. Resuming ({@link RenderJob#resumeFrom}) continues every pixel from the sample index it
 * reached, so an interrupted and resumed render is bit-identical to an uninterrupted one.
 *
 * <p>File format (big-endian), version 3:
 * <pre>
 *   8 bytes   magic "STRAHLCK"
 *   int       format version
 *   32 bytes  SHA-256 of the scene's content (geometry, materials, camera, environment)
 *   UTF       the settings that decide the image, "name=value" joined by ';' (DataOutput.writeUTF)
 *   int, int  width, height
 *   int       samples per pixel every pixel has reached
 *   long      samples that were NaN or infinite (counted as black)
 *   double    seconds of rendering so far
 *   per pixel, row by row from the top: int sample count, double r, g, b sums, double sum of
 *             the squared luminance and, if the settings keep feature buffers, 7 doubles: the
 *             sums of albedo r, g, b, normal x, y, z and depth
 *   with a noise threshold (adaptive sampling, {@link NoiseTarget}): int, the last boundary decided
 *             at, and (width·height + 7) / 8 bytes, a bit per pixel row by row (most significant
 *             first) set if it still takes samples
 *   int       CRC-32C of all bytes before it
 * </pre>
 * Version 2 is version 3 without the noise threshold's section (it was written before there was
 * one) and is read as well. Version 1 (before the film kept the squared luminance for the
 * denoiser's variance) is refused with a message that says so: its films lack what the variance
 * needs, and a resumed render must be the same bits as one never interrupted.
 * The settings excluded from the fingerprint are those that do not change the bits of the image:
 * the target samples per pixel (a render may be resumed to go further), the thread count, the
 * pass size and the time limit. Every other setting, including any added later, is part of it;
 * a checkpoint written before a setting existed is compared as if it held the value it was
 * rendered with ({@link #ADDED_LATER}: shadows, true; no noise threshold; lightTree, false: lights were chosen by power), so it still resumes.
 */
final class Checkpoint {
    static final int VERSION = 3;
    private static final byte[] MAGIC = "STRAHLCK".getBytes(StandardCharsets.US_ASCII);
    private static final int PIXEL_BYTES = 4 + 3 * 8;
    private static final Set<String> NOT_IN_FINGERPRINT = Set.of("samplesPerPixel", "threads", "samplesPerPass", "timeLimit", "schedule", "aovs");
    /** Settings added to the fingerprint after version 2 was first written, with the value every older checkpoint was rendered with. */
    static final Map<String, String> ADDED_LATER = Map.of("shadows", "true", "noiseThreshold", "0.0", "lightTree", "false");

    private final byte[] sceneDigest;
    private final String settingsKey;
    private final int width;
    private final int height;
    private final boolean features;
    /** Whether the render has a noise threshold: its file holds the noise target's state. */
    private final boolean adaptive;

    private Checkpoint(byte[] sceneDigest, String settingsKey, int width, int height, boolean features, boolean adaptive) {
        this.sceneDigest = sceneDigest;
        this.settingsKey = settingsKey;
        this.width = width;
        this.height = height;
        this.features = features;
        this.adaptive = adaptive;
    }

    /** Bytes per pixel: the count, the r, g, b sums, the squared luminance and any feature sums. */
    private int pixelBytes() {
        return 4 + 4 * 8 + (features ? FeatureTracer.CHANNELS * 8 : 0);
    }

    /**
     * The checkpoint identity of a render of {@code scene} with {@code settings}; digests the
     * scene once (a fraction of a second for a million triangles).
     *
     * @param scene    the scene as it is rendered (with any camera override)
     * @param settings the render settings
     * @return the identity, to save and restore checkpoints of that render
     */
    static Checkpoint of(Scene scene, RenderSettings settings) {
        return new Checkpoint(sceneDigest(scene), settingsKey(settings), settings.output().width(), settings.output().height(),
                settings.output().keepsFeatures(), settings.sampling().noiseThreshold() > 0);
    }

    /** The fingerprint of the scene's content (SHA-256). */
    byte[] sceneDigestBytes() {
        return sceneDigest.clone();
    }

    /**
     * What a checkpoint held: the film to resume into and the figures of the runs before.
     *
     * @param film            the film with every pixel's count and sums
     * @param samplesPerPixel samples per pixel every pixel has reached
     * @param invalidSamples  samples that were NaN or infinite, counted as black
     * @param seconds         seconds of rendering before
     * @param noise           with a noise threshold, which pixels still render; else null
     */
    record Restored(Film film, int samplesPerPixel, long invalidSamples, double seconds, NoiseTarget.State noise) {
        /**
         * Checks the film is there.
         *
         * @param film            the film
         * @param samplesPerPixel samples per pixel reached
         * @param invalidSamples  invalid samples so far
         * @param seconds         seconds rendered so far
         * @param noise           the noise target's state, or null
         */
        Restored {
            Objects.requireNonNull(film, "film");
        }
    }

    /**
     * The size of a checkpoint of this render.
     *
     * @return bytes
     */
    long fileSize() {
        return headerSize(settingsKey) + (long) width * height * pixelBytes() + noiseBytes() + 4;
    }

    /** Bytes of the noise target's section in a file of this render. */
    private long noiseBytes() {
        return adaptive ? 4 + ((long) width * height + 7) / 8 : 0;
    }

    /** Whether a file's settings (as {@link #settingsKey} writes them) have a noise threshold: its file has the section. */
    private static boolean hasNoiseThreshold(String settings) {
        for (String entry : settings.split(";")) {
            if (entry.startsWith("noiseThreshold=")) {
                return !entry.equals("noiseThreshold=0.0");
            }
        }
        return false;
    }

    /**
     * Saves the state of {@code film} atomically. Call it only while nothing renders into the
     * film: between passes (in {@link RenderListener#passCompleted}) or after the render.
     *
     * @param file           where to save; replaced atomically
     * @param film           the render's film, of the settings' size
     * @param noise          with a noise threshold, the noise target's state; else null
     * @param invalidSamples NaN or infinite samples so far, to report after a resume
     * @param seconds        seconds rendered so far
     * @throws IOException if the file cannot be written; a previous checkpoint is then kept
     * @throws IllegalArgumentException if the film is not of the settings' size, or the noise state is missing or not wanted
     */
    void save(Path file, Film film, NoiseTarget.State noise, long invalidSamples, double seconds) throws IOException {
        if (film.width() != width || film.height() != height) {
            throw new IllegalArgumentException("film " + film.width() + "x" + film.height() + " is not " + width + "x" + height);
        }
        if (film.hasFeatures() != features) {
            throw new IllegalArgumentException("the film " + (features ? "lacks" : "has") + " the feature buffers of the settings");
        }
        if ((noise != null) != adaptive) {
            throw new IllegalArgumentException(adaptive ? "a render with a noise threshold needs its state saved" : "no noise threshold, no state");
        }
        int reached = film.minSampleCount();
        AtomicFile.write(file, os -> {
            var crc = new CRC32C();
            var out = new DataOutputStream(new CheckedOutputStream(os, crc));
            out.write(MAGIC);
            out.writeInt(VERSION);
            out.write(sceneDigest);
            out.writeUTF(settingsKey);
            out.writeInt(width);
            out.writeInt(height);
            out.writeInt(reached);
            out.writeLong(invalidSamples);
            out.writeDouble(seconds);
            double[] sums = new double[film.stateSums()];
            for (int y = 0; y < height; y++) {
                for (int x = 0; x < width; x++) {
                    out.writeInt(film.pixelState(x, y, sums));
                    for (double v : sums) {
                        out.writeDouble(v);
                    }
                }
            }
            if (noise != null) {
                out.writeInt(noise.boundary());
                out.write(noise.packedMask());
            }
            out.flush();
            new DataOutputStream(os).writeInt((int) crc.getValue());
        });
    }

    /**
     * Reads a checkpoint made by {@link #save} for this scene and these settings.
     *
     * @param file the checkpoint
     * @return the film and figures it holds
     *
     * @throws CheckpointException if the file is no checkpoint, of another version, truncated,
     *                             corrupt, or made for another scene or other settings
     * @throws IOException         if it cannot be read
     */
    Restored restore(Path file) throws CheckpointException, IOException {
        long size;
        try {
            size = Files.size(file);
        } catch (NoSuchFileException e) {
            throw new CheckpointException(file, "checkpoint not found");
        }
        try (InputStream raw = new BufferedInputStream(Files.newInputStream(file), 1 << 16)) {
            var in = new DataInputStream(raw);
            byte[] magic = in.readNBytes(MAGIC.length);
            if (!Arrays.equals(magic, MAGIC)) {
                throw new CheckpointException(file, "not a strahl checkpoint");
            }
            int version = in.readInt();
            if (version == 1) {
                throw new CheckpointException(file, "checkpoint format version 1, made before strahl kept the per-pixel variance;"
                        + " this strahl reads version " + VERSION + " only: render anew");
            }
            if (version != VERSION && version != 2) {
                throw new CheckpointException(file, "checkpoint format version " + version + "; this strahl reads version " + VERSION);
            }
            byte[] digest = in.readNBytes(32);
            String settings = in.readUTF();
            int w = in.readInt();
            int h = in.readInt();
            // The size the header announces, checked before anything is allocated
            long expected = headerSize(settings) + (long) Math.max(w, 0) * Math.max(h, 0) * pixelBytes()
                    + (version >= 3 && hasNoiseThreshold(settings) ? 4 + ((long) Math.max(w, 0) * Math.max(h, 0) + 7) / 8 : 0) + 4;
            if (w <= 0 || h <= 0 || size > expected) {
                throw new CheckpointException(file, "corrupt checkpoint (" + size + " bytes for a " + w + "x" + h + " film)");
            }
            if (size < expected) {
                throw new CheckpointException(file, "truncated checkpoint (" + size + " of " + expected + " bytes)");
            }
            if (!checksumMatches(file, size)) {
                throw new CheckpointException(file, "corrupt checkpoint (checksum mismatch)");
            }
            String mismatch = settingsMismatch(settings);
            if (mismatch != null) {
                throw new CheckpointException(file, "checkpoint was made with other settings (" + mismatch + ")");
            }
            if (!Arrays.equals(digest, sceneDigest)) {
                throw new CheckpointException(file,
                        "checkpoint was made for another scene (its geometry, materials, camera or environment differ)");
            }
            int reached = in.readInt();
            long invalid = in.readLong();
            double seconds = in.readDouble();
            Film film = new Film(width, height, features);
            double[] sums = new double[film.stateSums()];
            int min = Integer.MAX_VALUE;
            for (int y = 0; y < height; y++) {
                for (int x = 0; x < width; x++) {
                    int n = in.readInt();
                    boolean finite = n >= 0;
                    for (int i = 0; i < sums.length; i++) {
                        sums[i] = in.readDouble();
                        finite &= Double.isFinite(sums[i]);
                    }
                    if (!finite) {
                        throw new CheckpointException(file, "corrupt checkpoint (pixel " + x + "," + y + ")");
                    }
                    film.restorePixel(x, y, n, sums);
                    min = Math.min(min, n);
                }
            }
            if (reached != min || invalid < 0 || !(seconds >= 0)) {
                throw new CheckpointException(file, "corrupt checkpoint (inconsistent header)");
            }
            NoiseTarget.State noise = null;
            if (adaptive) {                        // version 3: a version-2 file has no noise threshold, which the settings refused
                int boundary = in.readInt();
                byte[] bits = in.readNBytes((width * height + 7) / 8);
                if (boundary < 0 || bits.length != (width * height + 7) / 8) {
                    throw new CheckpointException(file, "corrupt checkpoint (noise threshold's state)");
                }
                noise = NoiseTarget.State.unpacked(boundary, bits, width * height);
            }
            return new Restored(film, reached, invalid, seconds, noise);
        } catch (EOFException e) {
            throw new CheckpointException(file, "truncated checkpoint");
        } catch (UTFDataFormatException e) {
            throw new CheckpointException(file, "corrupt checkpoint (settings)");
        }
    }

    /** Whether the CRC-32C of the first {@code size - 4} bytes equals the last 4. */
    private static boolean checksumMatches(Path file, long size) throws IOException {
        var crc = new CRC32C();
        try (var in = new DataInputStream(new BufferedInputStream(Files.newInputStream(file), 1 << 16))) {
            byte[] buf = new byte[1 << 16];
            for (long left = size - 4; left > 0; ) {
                int n = in.read(buf, 0, (int) Math.min(buf.length, left));
                if (n < 0) {
                    return false;
                }
                crc.update(buf, 0, n);
                left -= n;
            }
            return in.readInt() == (int) crc.getValue();
        }
    }

    /** Magic, version, digest, the settings in writeUTF's form, width, height, spp, invalid count, seconds. */
    private static int headerSize(String settings) {
        int utf = 2 + settings.getBytes(StandardCharsets.UTF_8).length;   // ASCII in practice, so modified UTF-8 = UTF-8
        return MAGIC.length + 4 + 32 + utf + 4 + 4 + 4 + 8 + 8;
    }

    /** Which setting differs, as "seed 5 in the checkpoint, 6 now", or null if none does. */
    private String settingsMismatch(String saved) {
        if (saved.equals(settingsKey)) {
            return null;
        }
        Map<String, String> then = new LinkedHashMap<>(SettingsCodec.parse(saved));
        ADDED_LATER.forEach(then::putIfAbsent);
        Map<String, String> now = SettingsCodec.parse(settingsKey);
        if (then.equals(now)) {
            return null;                           // an older checkpoint, of the settings it could not name
        }
        StringBuilder sb = new StringBuilder();
        for (var e : now.entrySet()) {
            String old = then.get(e.getKey());
            if (!e.getValue().equals(old)) {
                sb.append(sb.length() == 0 ? "" : ", ").append(e.getKey()).append(' ')
                        .append(old == null ? "unset" : old).append(" in the checkpoint, ").append(e.getValue()).append(" now");
            }
        }
        return sb.length() == 0 ? "unknown settings " + saved : sb.toString();
    }

    /**
     * "width=512;height=512;seed=0;integrator=PATH;maxDepth=-1;...;photons.photonsPerIteration=100000;...;sampler=stratified"
     * over everything that decides the image: the settings as {@link SettingsCodec} names them,
     * without those that do not change the bits.
     */
    static String settingsKey(RenderSettings settings) {
        Map<String, Object> entries = new LinkedHashMap<>(SettingsCodec.entries(settings));
        entries.keySet().removeAll(NOT_IN_FINGERPRINT);
        // Not a setting but decides the samples as much: the sample mode of the JVM (-Dstrahl.sampler).
        entries.put("sampler", SampleLoop.stratifiedSampler() ? "stratified" : "independent");
        // Which buffers are written does not matter, whether the film keeps features does (its layout).
        entries.put("features", settings.output().keepsFeatures());
        return SettingsCodec.text(entries);
    }

    /** SHA-256 of the geometry arrays, the materials (exact parameters), the camera and the environment. */
    static byte[] sceneDigest(Scene scene) {
        MessageDigest md;
        try {
            md = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every Java platform", e);
        }
        World world = World.of(scene);
        world.digest(md);
        StringBuilder sb = new StringBuilder();
        for (int m = 0; m < world.materialCount(); m++) {
            // records: every parameter, doubles in full precision
            sb.append(world.bsdf(m)).append(' ').append(world.emission(m)).append('\n');
        }
        Camera c = scene.camera();
        sb.append("camera ").append(c.lookFrom().x()).append(' ').append(c.lookFrom().y()).append(' ').append(c.lookFrom().z())
                .append(' ').append(c.lookAt().x()).append(' ').append(c.lookAt().y()).append(' ').append(c.lookAt().z())
                .append(' ').append(c.up().x()).append(' ').append(c.up().y()).append(' ').append(c.up().z())
                .append(' ').append(c.fovDegrees()).append('\n');
        if (c.aperture() > 0) {                       // a pinhole camera's digest stays what it was
            sb.append("lens ").append(c.aperture()).append(' ').append(c.focusDistance()).append('\n');
        }
        sb.append("environment ").append(world.environment()).append('\n');
        world.punctualLights().forEach(l -> sb.append("light ").append(l).append('\n'));   // none: the digest stays what it was
        md.update(sb.toString().getBytes(StandardCharsets.UTF_8));
        if (world.media().any()) {                    // none: the digest stays what it was
            world.media().digest(md);
        }
        return md.digest();
    }
}
