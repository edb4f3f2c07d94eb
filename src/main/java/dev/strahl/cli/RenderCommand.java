package dev.strahl.cli;

import dev.strahl.io.text.Units;
import dev.strahl.image.Image;
import dev.strahl.io.json.SceneFile;
import dev.strahl.render.PhotonParameters;
import dev.strahl.world.World;
import dev.strahl.scene.Camera;
import dev.strahl.io.ImageWriters;
import dev.strahl.render.CheckpointException;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.io.SceneLoader;
import dev.strahl.io.json.SceneSettings;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.math.MathContext;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import org.joml.Vector3d;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Mixin;
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
        description = {"Renders a scene (.json scene file, .obj or .ply) to a PNG (sRGB, 8 bit) or PFM (linear float) image.",
            "Without camera options the scene's camera is used; an OBJ is framed from +Z.",
            "Ctrl-C stops and writes the image rendered so far; a second Ctrl-C exits at once."},
        sortOptions = false)
final class RenderCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Mixin
    TransportOptions transport;

    @Parameters(index = "0", paramLabel = "SCENE", description = "Scene file: .json (strahl scene), .obj (with its .mtl) or .ply.")
    Path scene;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "FILE", description = "Output image; the extension chooses the format: .png or .pfm.")
    Path output;

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

    @Option(names = "--look-from", paramLabel = "X,Y,Z", converter = Vectors.class, description = "Camera position.")
    Vector3d lookFrom;

    @Option(names = "--look-at", paramLabel = "X,Y,Z", converter = Vectors.class, description = "Point the camera looks at.")
    Vector3d lookAt;

    @Option(names = "--up", paramLabel = "X,Y,Z", converter = Vectors.class, description = "Camera up vector.")
    Vector3d up;

    @Option(names = "--fov", paramLabel = "DEGREES", description = "Vertical field of view in degrees.")
    Double fov;

    @Option(names = {"-q", "--quiet"}, description = "Print nothing but errors.")
    boolean quiet;

    @Mixin
    DebugOption debug;

    @Option(names = "--stats", paramLabel = "FILE.json", description = "Also write the render's figures (time, samples/s, rays/s, load and BVH build time) as JSON.")
    Path statsFile;

    private double loadSeconds;
    private double bvhSeconds;

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
            return fail(err, e, "out of memory (the Java heap has at most " + Units.bytes(Runtime.getRuntime().maxMemory())
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
        if (fov != null && !(fov > 0 && fov < 180)) {
            throw new IllegalArgumentException("--fov: the field of view must be in (0, 180) degrees, got " + fov);
        }
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
        settings = loaded.settings().applyTo(settings, SceneFileOptions.given(spec.commandLine().getParseResult()));
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
                    + Units.bytes(Runtime.getRuntime().maxMemory()) + "): give Java more memory (java -Xmx...)", e);
        }
    }

    private RenderJob start(Scene s, RenderSettings settings, RenderListener listener, PrintWriter err) throws CheckpointException {
        if (resume == null) {
            return RenderJob.start(s, settings, listener);
        }
        RenderJob job;
        try {
            job = RenderJob.resumeFrom(resume, s, settings, listener);
        } catch (IOException e) {
            throw new CheckpointException(resume, "cannot read the checkpoint: " + e.getMessage());
        }
        if (!quiet) {
            err.println(String.format(Locale.ROOT, "strahl: resuming %s at %d spp (%.1f s rendered before)", resume,
                    job.completedSamplesPerPixel(), job.earlierSeconds()));
            err.flush();
        }
        return job;
    }

    private RenderSettings settings() {
        return new RenderSettings(width, height, spp, transport.maxDepth, seed, threads, transport.hemisphere, cullBackFaces, 0,
                transport.integrator, transport.lightSamples, timeLimit == null ? Duration.ZERO : timeLimit,
                new PhotonParameters(transport.photons, transport.photonRadius));
    }

    /**
     * The scene file's film and integrator keys, overridden by every option given on the command
     * line (an option left at its default does not override the file).
     */
    /** Refuses an unwritable output before spending time on the render. */
    private void checkOutput(Path file, String what) {
        if (!ImageWriters.isSupported(file)) {
            throw new IllegalArgumentException("unknown image format of " + file + ": use .png or .pfm");
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
        return new Camera(lookFrom != null ? lookFrom : base.lookFrom(), lookAt != null ? lookAt : base.lookAt(),
                up != null ? up : base.up(), fov != null ? fov : base.fovDegrees());
    }

    private int render(Scene s, RenderSettings settings, Path checkpointFile, PrintWriter err, Interrupts irq)
            throws InterruptedException, CheckpointException {
        var saver = checkpointFile == null ? null : new CheckpointSaver(checkpointFile, checkpointInterval, err);
        boolean showProgress = !quiet && Terminal.isStderrTerminal();
        ProgressBar bar = new ProgressBar(System.err);
        RenderStats stats;
        Image image;
        try (RenderJob job = start(s, settings, saver != null ? saver : new RenderListener() {}, err)) {
            if (saver != null) {
                saver.attach(job);
            }
            irq.onFirstSignal(job::cancel);
            while (!job.await(200, TimeUnit.MILLISECONDS)) {
                if (showProgress) {
                    bar.update(job.progress(), job.elapsedSeconds(), job.samplesDone());
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
            image = job.awaitCompletion();
            if (saver != null) {
                saver.saveFinal();
            }
        } finally {
            if (showProgress) {
                bar.finish();
            }
        }
        try {
            ImageWriters.write(image, output);
        } catch (IOException | UncheckedIOException e) {
            throw new RenderFailure("cannot write " + output + ": " + e.getMessage(), e);
        }
        if (statsFile != null) {
            try {
                StatsFile.write(statsFile, stats, settings, loadSeconds, bvhSeconds, s.textureBytes());
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
