package dev.strahl.cli;

import dev.strahl.camera.Camera;
import dev.strahl.film.Film;
import dev.strahl.film.ImageWriters;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.SceneLoader;
import java.io.IOException;
import java.io.PrintWriter;
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

/** {@code strahl render}: renders a scene file to an image. */
@Command(name = "render",
        mixinStandardHelpOptions = true,
        versionProvider = Main.Version.class,
        description = {"Renders a scene (.json scene file or .obj) to a PNG (sRGB, 8 bit) or PFM (linear float) image.",
            "Without camera options the scene's camera is used; an OBJ is framed from +Z."},
        sortOptions = false)
final class RenderCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Mixin
    TransportOptions transport;

    @Parameters(index = "0", paramLabel = "SCENE", description = "Scene file: .json (strahl scene) or .obj (with its .mtl).")
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

    @Option(names = "--stats", paramLabel = "FILE.json", description = "Also write the render's figures (time, samples/s, rays/s, load and BVH build time) as JSON.")
    Path statsFile;

    private double loadSeconds;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        try {
            RenderSettings settings = settings();
            if (fov != null && !(fov > 0 && fov < 180)) {
                throw new IllegalArgumentException("--fov: the field of view must be in (0, 180) degrees, got " + fov);
            }
            checkOutput();
            Path statsDir = statsFile == null ? null : statsFile.toAbsolutePath().getParent();
            if (statsDir != null && !Files.isDirectory(statsDir)) {
                throw new IllegalArgumentException("--stats: directory does not exist: " + statsDir);
            }
            long loadStart = System.nanoTime();
            Scene loaded = SceneLoader.load(scene);
            loadSeconds = (System.nanoTime() - loadStart) * 1e-9 - loaded.bvhBuildSeconds();
            Scene s = loaded.withCamera(camera(loaded.camera()));
            if (!quiet) {
                for (String note : s.notes()) {
                    err.println("strahl: note: " + note);
                }
                err.flush();
            }
            return render(s, settings, err);
        } catch (SceneException e) {
            err.println("strahl: " + e.getMessage());
            return 2;
        } catch (IllegalArgumentException e) {
            err.println("strahl: " + e.getMessage());
            return 2;
        } catch (IOException e) {
            err.println("strahl: cannot write " + output + ": " + e.getMessage());
            return 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            err.println("strahl: interrupted");
            return 1;
        }
    }

    private RenderSettings settings() {
        return new RenderSettings(width, height, spp, transport.maxDepth, seed, threads, transport.hemisphere, cullBackFaces, 0, transport.integrator, transport.lightSamples,
                timeLimit == null ? Duration.ZERO : timeLimit);
    }

    /** Refuses an unwritable output before spending time on the render. */
    private void checkOutput() {
        if (!ImageWriters.isSupported(output)) {
            throw new IllegalArgumentException("unknown image format of " + output + ": use .png or .pfm");
        }
        Path dir = output.toAbsolutePath().getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new IllegalArgumentException("output directory does not exist: " + dir);
        }
        if (!Files.isWritable(dir)) {
            throw new IllegalArgumentException("output directory is not writable: " + dir);
        }
    }

    private Camera camera(Camera base) {
        return new Camera(lookFrom != null ? lookFrom : base.lookFrom(), lookAt != null ? lookAt : base.lookAt(),
                up != null ? up : base.up(), fov != null ? fov : base.fovDegrees());
    }

    private int render(Scene s, RenderSettings settings, PrintWriter err) throws IOException, InterruptedException {
        boolean showProgress = !quiet && Terminal.isStderrTerminal();
        ProgressBar bar = new ProgressBar(System.err);
        RenderStats stats;
        Film film;
        try (RenderJob job = RenderJob.start(s, settings)) {
            while (!job.await(200, TimeUnit.MILLISECONDS)) {
                if (showProgress) {
                    bar.update(job.progress(), job.elapsedSeconds(), job.samplesDone());
                }
            }
            stats = job.awaitStats();
            film = job.film();
        } finally {
            if (showProgress) {
                bar.finish();
            }
        }
        ImageWriters.write(film, output);
        if (statsFile != null) {
            try {
                StatsFile.write(statsFile, stats, settings, loadSeconds, s.bvhBuildSeconds());
            } catch (IOException e) {
                err.println("strahl: cannot write " + statsFile + ": " + e.getMessage());
                return 1;
            }
        }
        if (!quiet) {
            err.println(String.format(Locale.ROOT, "strahl: %s, %dx%d, %d spp in %.2f s (%s samples/s, %s rays/s, %d threads) -> %s",
                    transport.integrator.id(), settings.width(), settings.height(), stats.samplesPerPixel(), stats.seconds(),
                    ProgressBar.si(stats.samplesPerSecond()), ProgressBar.si(stats.raysPerSecond()), stats.threads(), output));
            if (stats.invalidSamples() > 0) {
                err.println("strahl: warning: " + stats.invalidSamples() + " samples were NaN or infinite and counted as black");
            }
        }
        return 0;
    }
}
