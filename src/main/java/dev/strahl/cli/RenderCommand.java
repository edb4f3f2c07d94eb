package dev.strahl.cli;

import dev.strahl.image.Image;
import dev.strahl.image.ToneMapping;
import dev.strahl.io.ImageWriters;
import dev.strahl.io.SceneLoader;
import dev.strahl.io.image.ImageLimits;
import dev.strahl.io.json.EnvironmentMaps;
import dev.strahl.io.json.SceneFile;
import dev.strahl.io.json.SceneSettings;
import dev.strahl.io.text.Units;
import dev.strahl.render.Aov;
import dev.strahl.render.CheckpointException;
import dev.strahl.render.Denoiser;
import dev.strahl.render.PhotonParameters;
import dev.strahl.render.RenderBuffers;
import dev.strahl.render.RenderCluster;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.world.World;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.math.MathContext;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import org.joml.Vector3d;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code strahl render}: renders a scene file to an image. Exit codes: 0 done, 1 a failure while
 * rendering or writing, 2 bad usage or input (nothing is written), 130/143 interrupted by
 * SIGINT/SIGTERM (the image rendered so far, and a checkpoint if asked for, are written).
 */
@Command(name = "render",
        mixinStandardHelpOptions = true,
        versionProvider = Main.Version.class,
        description = {"Renders a scene (.json scene file, .obj, .ply, .gltf or .glb) to a PNG (sRGB, 8 bit), PFM (linear float) or OpenEXR image.",
            "Without camera options the scene's camera is used; an OBJ or PLY is framed from a raised three-quarter view and, without lights, lit by a built-in studio sky.",
            "Ctrl-C stops and writes the image rendered so far; a second Ctrl-C exits at once."},
        sortOptions = false)
final class RenderCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Mixin
    TransportOptions transport;

    @Parameters(index = "0", paramLabel = "SCENE", description = "Scene file: .json (strahl scene), .obj (with its .mtl), .ply, or glTF 2.0 (.gltf, .glb).")
    Path scene;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "FILE",
            description = "Output image; the extension chooses the format: .png (sRGB, 8 bit), .pfm (linear float) or .exr (OpenEXR, linear).")
    Path output;

    @Option(names = "--aov", split = ",", paramLabel = "LIST",
            description = "Feature buffers to keep and write: albedo, normal, depth (comma-separated). In an .exr they are channels"
                    + " of the same file; beside a .png or .pfm they go to NAME.albedo.pfm, NAME.normal.pfm, NAME.depth.pfm.")
    List<String> aovNames;

    @Option(names = "--exr-type", defaultValue = "half", paramLabel = "half|float",
            description = "Sample type of .exr output (default: ${DEFAULT-VALUE}); depth is always float.")
    String exrType;

    @Option(names = "--exr-compression", defaultValue = "zip", paramLabel = "zip|none",
            description = "Compression of .exr output (default: ${DEFAULT-VALUE}).")
    String exrCompression;

    @Option(names = "--denoise", description = "Denoise the image before writing it (the feature buffers are then rendered too).")
    boolean denoise;

    @Option(names = "--denoiser", defaultValue = "network", paramLabel = "network|atrous|oidn",
            description = "With --denoise: network (the default: Intel Open Image Denoise's trained network, run in pure Java),"
                    + " atrous (a fast, blurrier wavelet filter; its old name strahl works too) or oidn (OIDN's oidnDenoise found on the PATH).")
    String denoiserName;

    @Option(names = "--tonemap", defaultValue = "clamp", paramLabel = "clamp|aces|agx",
            description = "Tone curve of .png output (default: ${DEFAULT-VALUE}: values above 1 are white).")
    String tonemap;

    @Option(names = "--exposure", defaultValue = "0", paramLabel = "EV",
            description = "Exposure of .png output in stops: values are multiplied by 2^EV before the tone curve (default: ${DEFAULT-VALUE}).")
    double exposure;

    @Option(names = "--width", defaultValue = "512", description = "Image width in pixels (default: ${DEFAULT-VALUE}).")
    int width;

    @Option(names = "--height", defaultValue = "512", description = "Image height in pixels (default: ${DEFAULT-VALUE}).")
    int height;

    @Option(names = "--spp", defaultValue = "64", description = "Samples per pixel (default: ${DEFAULT-VALUE}).")
    int spp;

    @Option(names = "--seed", defaultValue = "0", description = "Random seed; the same seed gives the same image (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--threads", defaultValue = "0", description = "Worker threads; 0 = all processors (default: ${DEFAULT-VALUE}).")
    int threads;

    @Option(names = "--time-limit", paramLabel = "DURATION", converter = Durations.class,
            description = "Stop at the end of the pass that crosses this time (e.g. 90s, 5m, 1h30m) and write the image.")
    Duration timeLimit;

    @Option(names = "--checkpoint", paramLabel = "FILE",
            description = "Save the render's state to FILE periodically, when interrupted and at the end, for --resume.")
    Path checkpoint;

    @Option(names = "--checkpoint-interval", paramLabel = "DURATION", converter = Durations.class, defaultValue = "5m",
            description = "Time between periodic checkpoints (default: ${DEFAULT-VALUE}).")
    Duration checkpointInterval;

    @Option(names = "--resume", paramLabel = "FILE",
            description = "Continue the render saved in checkpoint FILE (same scene and settings; --spp may be raised)."
                    + " New checkpoints go to FILE too unless --checkpoint names another.")
    Path resume;

    @Option(names = "--cull-back-faces", description = "Skip back faces of closed meshes for camera and bounce rays.")
    boolean cullBackFaces;

    // Teaching options (docs/experiments.md): what a first ray tracer did, to measure what strahl does instead.
    @Option(names = "--accel", defaultValue = "bvh", paramLabel = "bvh|none",
            description = "Teaching option: none tests every ray against every primitive (no BVH), to measure what the BVH buys; "
                    + "same image, many times slower (default: ${DEFAULT-VALUE}).")
    Accel accel;

    @Option(names = "--schedule", defaultValue = "tiles", paramLabel = "tiles|stripes",
            description = "Teaching option: stripes gives each of n threads one horizontal stripe of the image instead of "
                    + "32x32 tiles taken by whichever thread is free; same image, threads wait more (default: ${DEFAULT-VALUE}).")
    Schedule schedule;

    /** The values of the teaching options --accel and --schedule. */
    enum Accel { BVH, NONE }

    enum Schedule { TILES, STRIPES }

    @Option(names = "--look-from", paramLabel = "X,Y,Z", converter = Vectors.class, description = "Camera position.")
    Vector3d lookFrom;

    @Option(names = "--look-at", paramLabel = "X,Y,Z", converter = Vectors.class, description = "Point the camera looks at.")
    Vector3d lookAt;

    @Option(names = "--up", paramLabel = "X,Y,Z", converter = Vectors.class, description = "Camera up vector.")
    Vector3d up;

    @Option(names = "--fov", paramLabel = "DEGREES", description = "Vertical field of view in degrees.")
    Double fov;

    @Option(names = "--cluster", paramLabel = "HOST[:PORT],...", split = ",",
            description = "Render on a cluster: join the 'strahl worker' members there and render with them (docs/cluster.md);"
                    + " the image is the same bits as without.")
    List<String> cluster;

    @Option(names = "--cluster-name", paramLabel = "NAME", defaultValue = "strahl",
            description = "With --cluster: the cluster's name (default: ${DEFAULT-VALUE}).")
    String clusterName;

    @Option(names = "--bind", paramLabel = "ADDR", defaultValue = "127.0.0.1",
            description = "With --cluster: the address this member listens on, reachable by the workers (default: ${DEFAULT-VALUE}).")
    String bind;

    @Option(names = "--port", defaultValue = "0",
            description = "With --cluster: the port this member listens on; 0 = 5701 or the next free one (default: ${DEFAULT-VALUE}).")
    int port;

    @Mixin
    EnvironmentLensOptions lens;

    @Option(names = {"-q", "--quiet"}, description = "Print nothing but errors.")
    boolean quiet;

    @Mixin
    DebugOption debug;

    @Option(names = "--stats", paramLabel = "FILE.json", description = "Also write the render's figures (time, samples/s, rays/s, load and BVH build time) as JSON.")
    Path statsFile;

    private double loadSeconds;
    private double bvhSeconds;
    private ImageWriters.Options writeOptions;
    private OidnDenoiser oidn;
    private Denoiser denoiser;
    /** The feature buffers to write (those the denoiser needs are rendered also when not written). */
    private Set<Aov> written = Set.of();

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        try (Interrupts irq = Interrupts.install(err)) {
            return run(err, irq);
        } catch (SceneException | CheckpointException e) {
            return fail(err, e, e.getMessage(), 2);
        } catch (IllegalArgumentException e) {
            return fail(err, e, e.getMessage(), 2);
        } catch (OutOfMemoryError e) {
            return fail(err, e, "out of memory (the Java heap has at most " + ImageLimits.bytes(Runtime.getRuntime().maxMemory())
                    + "): give Java more memory (java -Xmx...) or render a smaller scene or image", 1);
        } catch (RenderFailure e) {
            return fail(err, e.getCause(), e.getMessage(), 1);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return fail(err, e, "interrupted", 1);
        }
    }

    private int fail(PrintWriter err, Throwable e, String message, int code) {
        err.println("strahl: " + message);
        if (debug.enabled && e != null) {
            e.printStackTrace(err);
        }
        err.flush();
        return code;
    }

    private int run(PrintWriter err, Interrupts irq) throws SceneException, CheckpointException, InterruptedException {
        RenderSettings settings = settings();
        checkClusterOptions();
        writeOptions = writeOptions();
        switch (denoiserName) {
            case "network" -> denoiser = Denoiser.create();
            case "atrous", "strahl" -> denoiser = Denoiser.atrous();
            case "oidn" -> oidn = denoise ? OidnDenoiser.onPath() : null;
            default -> throw new IllegalArgumentException("--denoiser must be network, atrous or oidn, got '" + denoiserName + "'");
        }
        if (fov != null && !(fov > 0 && fov < 180)) {
            throw new IllegalArgumentException("--fov: the field of view must be in (0, 180) degrees, got " + fov);
        }
        lens.check();
        checkOutput(output, "output");
        if (statsFile != null) {
            checkWritable(statsFile, "--stats");
        }
        Path checkpointFile = checkpoint != null ? checkpoint : resume;
        if (checkpointFile != null) {
            checkCheckpointFile(checkpointFile);
        }
        HeapCheck.checkFilm(width, height);
        long loadStart = System.nanoTime();
        SceneFile loaded = load();
        bvhSeconds = World.of(loaded.scene()).bvhBuildSeconds();
        loadSeconds = (System.nanoTime() - loadStart) * 1e-9 - bvhSeconds;
        Scene s = loaded.scene().withCamera(camera(loaded.scene().camera()));
        if (lens.envmap != null) {
            s = s.withEnvironmentMap(EnvironmentMaps.read(lens.envmap), 1, 0);
        }
        settings = loaded.settings().applyTo(settings, SceneFileOptions.given(spec.commandLine().getParseResult()));
        written = settings.aovs();
        if (denoise) {
            settings = settings.withAovs(EnumSet.allOf(Aov.class));      // the denoiser's guides, written or not
        }
        if (settings.width() != width || settings.height() != height) {
            HeapCheck.checkFilm(settings.width(), settings.height());          // the scene file's size
        }
        if (!quiet) {
            for (String note : s.notes()) {
                err.println("strahl: " + (note.startsWith("warning: ") ? note : "note: " + note));
            }
            err.flush();
        }
        return render(s, settings, checkpointFile, err, irq);
    }

    private SceneFile load() throws SceneException {
        try {
            return SceneFile.load(scene);
        } catch (OutOfMemoryError e) {
            throw new IllegalArgumentException(scene + ": the scene does not fit in the Java heap (at most "
                    + ImageLimits.bytes(Runtime.getRuntime().maxMemory()) + "): give Java more memory (java -Xmx...)", e);
        }
    }

    private RenderJob start(Scene s, RenderSettings settings, RenderListener listener, PrintWriter err, RenderCluster members)
            throws CheckpointException {
        if (members != null && resume == null) {
            try {
                return members.render(s, scene, settings, listener);
            } catch (IOException e) {
                throw new IllegalArgumentException("cannot send the scene to the cluster: " + e.getMessage(), e);
            }
        }
        if (resume == null) {
            return RenderJob.start(s, settings, listener);
        }
        RenderJob job;
        try {
            job = members != null ? members.resume(resume, s, scene, settings, listener) : RenderJob.resumeFrom(resume, s, settings, listener);
        } catch (IOException e) {
            throw new CheckpointException(resume, "cannot read the checkpoint: " + e.getMessage());
        }
        if (!quiet) {
            err.println(String.format(Locale.ROOT, "strahl: resuming %s at %d spp (%.1f s rendered before)", resume,
                    job.earlierSamplesPerPixel(), job.earlierSeconds()));
            err.flush();
        }
        return job;
    }

    private RenderSettings settings() {
        return new RenderSettings(width, height, spp, transport.maxDepth, seed, threads, transport.hemisphere, cullBackFaces, 0,
                transport.integrator, transport.lightSamples, timeLimit == null ? Duration.ZERO : timeLimit, new PhotonParameters(
                transport.photons, transport.photonRadius), accel == Accel.NONE, schedule == Schedule.STRIPES, transport.shadows(), aovs());
    }

    /** The feature buffers asked for with --aov (checked), or none. */
    private Set<Aov> aovs() {
        return SceneFileOptions.aovs(aovNames);
    }

    /** The PNG's tone curve and exposure, the EXR's type and compression, from the options (checked). */
    private ImageWriters.Options writeOptions() {
        ToneMapping curve;
        try {
            curve = ToneMapping.of(tonemap);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--tonemap: " + e.getMessage());
        }
        if (!Double.isFinite(exposure)) {
            throw new IllegalArgumentException("--exposure must be a finite number of stops, got " + exposure);
        }
        if (!exrType.equals("half") && !exrType.equals("float")) {
            throw new IllegalArgumentException("--exr-type must be half or float, got '" + exrType + "'");
        }
        if (!exrCompression.equals("zip") && !exrCompression.equals("none")) {
            throw new IllegalArgumentException("--exr-compression must be zip or none, got '" + exrCompression + "'");
        }
        return new ImageWriters.Options(curve, exposure, exrType.equals("float"), exrCompression.equals("zip"));
    }

    /**
     * The scene file's film and integrator keys, overridden by every option given on the command
     * line (an option left at its default does not override the file).
     */
    /** Refuses an unwritable output before spending time on the render. */
    private void checkOutput(Path file, String what) {
        if (!ImageWriters.isSupported(file)) {
            throw new IllegalArgumentException("unknown image format of " + file + ": use .png, .pfm or .exr");
        }
        checkWritable(file, what);
    }

    private void checkCheckpointFile(Path file) {
        if (file.toAbsolutePath().normalize().equals(output.toAbsolutePath().normalize())) {
            throw new IllegalArgumentException("the checkpoint " + file + " and the output image must be different files");
        }
        checkWritable(file, "checkpoint");
    }

    /** The directory must exist and take a new file: tried for real, since permissions alone do not tell (root, read-only mounts). */
    private static void checkWritable(Path file, String what) {
        Path dir = file.toAbsolutePath().getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new IllegalArgumentException(what + " directory does not exist: " + dir);
        }
        if (Files.isDirectory(file)) {
            throw new IllegalArgumentException(what + " " + file + " is a directory");
        }
        try {
            Files.delete(Files.createTempFile(dir, ".strahl-write-test", ".tmp"));
        } catch (IOException | SecurityException e) {
            throw new IllegalArgumentException(what + " directory is not writable: " + dir);
        }
    }

    private Camera camera(Camera base) {
        Camera c = new Camera(lookFrom != null ? lookFrom : base.lookFrom(), lookAt != null ? lookAt : base.lookAt(),
                up != null ? up : base.up(), fov != null ? fov : base.fovDegrees());
        boolean moved = lookFrom != null || lookAt != null;
        return c.withLens(lens.aperture != null ? lens.aperture : base.aperture(),
                lens.focusDistance != null ? lens.focusDistance : moved ? c.focusDistance() : base.focusDistance());
    }

    /** Checks the cluster options before anything is loaded: they need --cluster, and a port in range. */
    private void checkClusterOptions() {
        var parsed = spec.commandLine().getParseResult();
        if (cluster == null) {
            for (String option : List.of("--cluster-name", "--bind", "--port")) {
                if (parsed.hasMatchedOption(option)) {
                    throw new IllegalArgumentException(option + " needs --cluster");
                }
            }
            return;
        }
        if (cluster.isEmpty() || cluster.stream().anyMatch(String::isBlank)) {
            throw new IllegalArgumentException("--cluster: give the members to join as HOST[:PORT],...");
        }
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("--port must be in 0..65535, got " + port);
        }
        if (clusterName.isBlank()) {
            throw new IllegalArgumentException("--cluster-name must not be empty");
        }
    }

    /** Joins the cluster (a member that renders too); null without --cluster. */
    private RenderCluster joinCluster(RenderSettings settings, PrintWriter err) {
        if (cluster == null) {
            return null;
        }
        if (settings.integrator() == dev.strahl.render.IntegratorKind.PHOTON) {
            throw new IllegalArgumentException("--cluster: the photon mapper cannot render on a cluster (each sample needs the photon map of the whole scene)");
        }
        try {
            RenderCluster members = RenderCluster.builder().join(cluster.toArray(String[]::new)).bind(bind).port(port).clusterName(clusterName)
                    .threads(settings.threads()).joinTimeout(Duration.ofSeconds(10))
                    .log(quiet ? null : line -> {
                        synchronized (err) {
                            err.println("strahl: cluster: " + line);
                            err.flush();
                        }
                    }).start();
            return members;
        } catch (IOException | IllegalStateException e) {
            throw new IllegalArgumentException("--cluster: " + e.getMessage(), e);
        }
    }

    private int render(Scene s, RenderSettings settings, Path checkpointFile, PrintWriter err, Interrupts irq)
            throws InterruptedException, CheckpointException {
        try (RenderCluster members = joinCluster(settings, err)) {
            return render(s, settings, checkpointFile, err, irq, members);
        }
    }

    private int render(Scene s, RenderSettings settings, Path checkpointFile, PrintWriter err, Interrupts irq, RenderCluster members)
            throws InterruptedException, CheckpointException {
        var saver = checkpointFile == null ? null : new CheckpointSaver(checkpointFile, checkpointInterval, err);
        boolean showProgress = !quiet && Terminal.isStderrTerminal();
        ProgressBar bar = new ProgressBar(System.err);
        RenderStats stats;
        RenderBuffers buffers;
        try (RenderJob job = start(s, settings, saver != null ? saver : new RenderListener() {}, err, members)) {
            if (saver != null) {
                saver.attach(job);
            }
            irq.onFirstSignal(job::cancel);
            while (!job.await(200, TimeUnit.MILLISECONDS)) {
                if (showProgress) {
                    bar.update(job.progress(), job.elapsedSeconds(), job.samplesDone(),
                            members != null ? "  " + members.memberCount() + " members" : "");
                }
            }
            try {
                stats = job.awaitStats();
            } catch (IllegalStateException e) {
                if (e.getCause() instanceof OutOfMemoryError oom) {
                    throw oom;                         // on a render thread: the same advice as on this one
                }
                throw new RenderFailure("the render failed: " + e.getCause(), e.getCause());
            }
            buffers = job.awaitBuffers();
            if (saver != null) {
                saver.saveFinal();
            }
        } finally {
            if (showProgress) {
                bar.finish();
            }
        }
        double denoiseSeconds = 0;
        if (denoise) {
            long t0 = System.nanoTime();
            Image clean;
            try {
                clean = oidn != null ? oidn.denoise(buffers) : denoiser.denoise(buffers);
            } catch (IOException e) {
                throw new RenderFailure("oidnDenoise failed: " + e.getMessage(), e);
            } catch (UncheckedIOException e) {                 // the network's weights missing or damaged in the jar
                throw new RenderFailure(e.getMessage(), e);
            }
            denoiseSeconds = (System.nanoTime() - t0) * 1e-9;
            buffers = buffers.withColor(clean);
        }
        buffers = new RenderBuffers(buffers.color(), buffers.variance(), written.contains(Aov.ALBEDO) ? buffers.albedo() : null,
                written.contains(Aov.NORMAL) ? buffers.normal() : null, written.contains(Aov.DEPTH) ? buffers.depth() : null);
        try {
            ImageWriters.write(buffers, output, writeOptions);
        } catch (IOException | UncheckedIOException e) {
            throw new RenderFailure("cannot write " + output + ": " + e.getMessage(), e);
        }
        if (statsFile != null) {
            try {
                StatsFile.write(statsFile, stats, settings, loadSeconds, bvhSeconds, s.textureBytes(), StatsFile.figures(members));
            } catch (IOException e) {
                throw new RenderFailure("cannot write " + statsFile + ": " + e.getMessage(), e);
            }
        }
        boolean savedCheckpoint = saver != null;
        irq.written();
        long invalid = stats.invalidSamples();
        if (irq.interrupted()) {
            err.println(String.format(Locale.ROOT, "strahl: interrupted at %d of %d spp after %.2f s: wrote %s%s",
                    stats.samplesPerPixel(), settings.samplesPerPixel(), stats.seconds(), output,
                    savedCheckpoint ? "; continue with --resume " + checkpointFile : ""));
        } else if (!quiet) {
            if (stats.samplesPerPixel() < settings.samplesPerPixel()) {
                err.println("strahl: note: the time limit of " + limitText(timeLimit)
                        + " ended the render at " + stats.samplesPerPixel() + " of " + settings.samplesPerPixel() + " spp"
                        + (savedCheckpoint ? "; continue with --resume " + checkpointFile : ""));
            }
            err.println(String.format(Locale.ROOT, "strahl: %s, %dx%d, %d spp in %.2f s (%s samples/s, %s rays/s, %d threads) -> %s",
                    settings.integrator().id(), settings.width(), settings.height(), stats.samplesPerPixel(), stats.seconds(),
                    Units.si(stats.samplesPerSecond()), Units.si(stats.raysPerSecond()), stats.threads(), output));
            if (denoise) {
                err.println(String.format(Locale.ROOT, "strahl: denoised with %s in %.2f s", oidn != null ? "oidnDenoise" : denoiser,
                        denoiseSeconds));
            }
        }
        if (!quiet && invalid > 0) {
            err.println("strahl: warning: " + invalid + " samples were NaN or infinite and counted as black");
        }
        err.flush();
        return irq.interrupted() ? irq.exitCode() : 0;
    }

    /** "0.3 s", "90 s", "5:00", "1:30:00". */
    static String limitText(Duration d) {
        double seconds = d.toNanos() * 1e-9;
        if (seconds >= 100) {
            return Units.duration(seconds);
        }
        return new BigDecimal(seconds).round(new MathContext(3)).stripTrailingZeros().toPlainString() + " s";
    }

    /** A failure while rendering or writing the result: exit code 1. */
    static final class RenderFailure extends RuntimeException {
        RenderFailure(String message, Throwable cause) {
            super(message, cause);
        }
    }
}
