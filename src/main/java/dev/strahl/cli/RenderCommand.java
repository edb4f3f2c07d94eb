package dev.strahl.cli;

import dev.strahl.codec.ImageLimits;
import dev.strahl.codec.Printable;
import dev.strahl.io.ImageWriters;
import dev.strahl.io.SceneLoader;
import dev.strahl.io.json.SceneFile;
import dev.strahl.render.Aov;
import dev.strahl.render.CheckpointException;
import dev.strahl.render.RenderBuffers;
import dev.strahl.render.RenderCluster;
import dev.strahl.render.RenderJob;
import dev.strahl.render.RenderListener;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import dev.strahl.scene.Scene;
import dev.strahl.scene.SceneException;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code strahl render}: renders a scene file to an image. Exit codes: 0 done, 1 a failure while
 * rendering or writing, 2 bad usage or input (nothing is written), 130/143 interrupted by
 * SIGINT/SIGTERM (the image rendered so far, and a checkpoint if asked for, are written). The
 * options come in sections, one class each (FilmOptions, TransportOptions, ...); what happens after
 * the render is {@link RenderOutcome}'s.
 */
@Command(name = "render",
        mixinStandardHelpOptions = true,
        abbreviateSynopsis = true,
        versionProvider = Main.Version.class,
        description = {"Renders a scene (.json scene file, .obj, .ply, .gltf or .glb) to a PNG (sRGB, 8 bit), PFM (linear float) or OpenEXR image.",
            "Without camera options the scene's camera is used; an OBJ or PLY is framed from a raised three-quarter view and, without lights, lit by a built-in studio sky.",
            "An option given here wins over the scene file's film and integrator keys. Ctrl-C stops and writes the image rendered so far;"
                    + " a second Ctrl-C exits at once."},
        sortOptions = false)
final class RenderCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE", description = "Scene file: .json (strahl scene), .obj (with its .mtl), .ply, or glTF 2.0 (.gltf, .glb).")
    Path scene;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "FILE",
            description = "Output image; the extension chooses the format: .png (sRGB, 8 bit), .pfm (linear float) or .exr (OpenEXR, linear).")
    Path output;

    @Option(names = {"-q", "--quiet"}, description = "Print nothing but errors.")
    boolean quiet;

    @Mixin
    DebugOption debug;

    @ArgGroup(validate = false, heading = "%nFilm:%n")
    FilmOptions film = new FilmOptions();

    @ArgGroup(validate = false, heading = "%nSampling:%n")
    Sampling sampling = new Sampling();

    @ArgGroup(validate = false, heading = "%nLight transport:%n")
    TransportOptions transport = new TransportOptions();

    @ArgGroup(validate = false, heading = "%nCamera:%n")
    CameraOptions camera = new CameraOptions();

    @ArgGroup(validate = false, heading = "%nLens:%n")
    LensOptions lens = new LensOptions();

    @ArgGroup(validate = false, heading = "%nEnvironment:%n")
    EnvironmentOptions environment = new EnvironmentOptions();

    @ArgGroup(validate = false, heading = "%nOutput files:%n")
    OutputFileOptions files = new OutputFileOptions();

    @ArgGroup(validate = false, heading = "%nDenoising:%n")
    DenoiseOptions denoising = new DenoiseOptions();

    @ArgGroup(validate = false, heading = "%nTime and checkpoints:%n")
    CheckpointOptions time = new CheckpointOptions();

    @ArgGroup(validate = false, heading = "%nExecution:%n")
    ExecutionOptions execution = new ExecutionOptions();

    @ArgGroup(validate = false, heading = "%nCluster:%n")
    ClusterOptions cluster = new ClusterOptions();

    @ArgGroup(validate = false, heading = "%nTeaching options (docs/experiments.md):%n")
    TeachingOptions teaching = new TeachingOptions();

    /** render's --spp, the samples per pixel to take, beside the shared --seed. */
    static final class Sampling extends SamplingOptions {
        @Option(names = "--spp", defaultValue = "64", order = 1, description = "Samples per pixel (default: ${DEFAULT-VALUE}).")
        int spp;

        @Override
        RenderSettings applyTo(RenderSettings base) {
            return super.applyTo(base).withSamplesPerPixel(spp);
        }
    }

    private double loadSeconds;
    private double bvhSeconds;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        try (SimdOption.Scope kernel = execution.apply(); Interrupts irq = Interrupts.install(err)) {
            return run(err, irq);
        } catch (SceneException | CheckpointException e) {
            return fail(err, e, e.getMessage(), 2);
        } catch (IllegalArgumentException e) {
            return fail(err, e, e.getMessage(), 2);
        } catch (OutOfMemoryError e) {
            return fail(err, e, "out of memory (the Java heap has at most " + ImageLimits.bytes(Runtime.getRuntime().maxMemory())
                    + "): give Java more memory (java -Xmx...) or render a smaller scene or image", 1);
        } catch (RenderOutcome.RenderFailure e) {
            return fail(err, e.getCause(), e.getMessage(), 1);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return fail(err, e, "interrupted", 1);
        }
    }

    private int fail(PrintWriter err, Throwable e, String message, int code) {
        err.println("strahl: " + Printable.line(message));       // one line, whatever a file put into the message
        if (debug.enabled && e != null) {
            e.printStackTrace(err);
        }
        err.flush();
        return code;
    }

    /** The settings the options give, without a scene file's (checked as they are made). */
    RenderSettings settings() {
        RenderSettings s = film.applyTo(RenderSettings.defaults());
        s = transport.applyTo(sampling.applyTo(s));
        return teaching.applyTo(execution.applyTo(time.applyTo(s)));
    }

    private int run(PrintWriter err, Interrupts irq) throws SceneException, CheckpointException, InterruptedException {
        RenderSettings settings = settings();
        cluster.check(spec.commandLine().getParseResult());
        ImageWriters writer = files.writer();
        RenderOutcome outcome = new RenderOutcome(denoising, writer, output, quiet);
        camera.check();
        lens.check();
        OutputFileOptions.checkImage(output, "output");
        if (files.statsFile != null) {
            OutputFileOptions.checkWritable(files.statsFile, "--stats");
        }
        time.check(output);
        HeapCheck.checkRender(settings.output().width(), settings.output().height(), keepsFeatures(settings), denoising.denoise);
        long loadStart = System.nanoTime();
        SceneFile loaded = load();
        bvhSeconds = loaded.scene().bvhBuildSeconds();
        loadSeconds = (System.nanoTime() - loadStart) * 1e-9 - bvhSeconds;
        Scene s = loaded.scene().withCamera(camera.camera(loaded.scene().camera(), lens));
        if (environment.envmap != null) {
            s = s.withEnvironmentMap(SceneLoader.readImage(environment.envmap), 1, 0);
        }
        settings = loaded.settings().applyTo(settings, SceneFileOptions.given(spec.commandLine().getParseResult()));
        outcome.keep(settings.output().aovs());
        if (denoising.denoise) {
            Set<Aov> guides = EnumSet.of(Aov.ALBEDO, Aov.NORMAL, Aov.DEPTH);    // the denoiser's guides, written or not
            guides.addAll(settings.output().aovs());
            settings = settings.withAovs(guides);
        }
        // the scene file's size and feature buffers
        HeapCheck.checkRender(settings.output().width(), settings.output().height(), keepsFeatures(settings), denoising.denoise);
        if (!quiet) {
            for (String note : s.notes()) {
                err.println("strahl: " + Printable.line(note.startsWith("warning: ") ? note : "note: " + note));
            }
            err.flush();
        }
        try (RenderCluster members = cluster.join(settings, quiet, err)) {
            return render(s, settings, outcome, err, irq, members);
        }
    }

    /** Whether the film keeps feature sums: feature buffers asked for, or the denoiser's guides. */
    private boolean keepsFeatures(RenderSettings settings) {
        return denoising.denoise || settings.output().keepsFeatures();
    }

    private SceneFile load() throws SceneException {
        try {
            return SceneFile.load(scene);
        } catch (OutOfMemoryError e) {
            throw new IllegalArgumentException(scene + ": the scene does not fit in the Java heap (at most "
                    + ImageLimits.bytes(Runtime.getRuntime().maxMemory()) + "): give Java more memory (java -Xmx...)", e);
        } catch (StackOverflowError e) {
            throw new IllegalArgumentException(scene + ": the scene is nested too deeply to read (the reader's stack overflowed)", e);
        }
    }

    private RenderJob start(Scene s, RenderSettings settings, RenderListener listener, PrintWriter err, RenderCluster members)
            throws CheckpointException {
        Path resume = time.resume;
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

    private int render(Scene s, RenderSettings settings, RenderOutcome outcome, PrintWriter err, Interrupts irq, RenderCluster members)
            throws InterruptedException, CheckpointException {
        Path checkpointFile = time.file();
        var saver = checkpointFile == null ? null : new CheckpointSaver(checkpointFile, time.checkpointInterval, err);
        boolean showProgress = !quiet && Terminal.isStderrTerminal();
        ProgressBar bar = new ProgressBar(System.err);
        RenderStats stats;
        RenderBuffers buffers;
        try (RenderJob job = start(s, settings, saver != null ? saver : new RenderListener() {}, err, members)) {
            if (saver != null) {
                saver.attach(job);
            }
            irq.onFirstSignal(job::cancel);
            double limit = settings.execution().timeLimit().toNanos() * 1e-9;
            while (!job.await(200, TimeUnit.MILLISECONDS)) {
                if (showProgress) {
                    // towards the end that comes first: the samples the render will take, or the time limit
                    double seconds = job.elapsedSeconds();
                    bar.update(limit > 0 ? Math.max(job.progress(), Math.min(1, seconds / limit)) : job.progress(), seconds, job.samplesDone(),
                            members != null ? "  " + members.memberCount() + " members" : "");
                }
            }
            try {
                stats = job.awaitStats();
            } catch (IllegalStateException e) {
                if (e.getCause() instanceof OutOfMemoryError oom) {
                    throw oom;                         // on a render thread: the same advice as on this one
                }
                throw new RenderOutcome.RenderFailure("the render failed: " + e.getCause(), e.getCause());
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
        outcome.write(buffers);
        if (files.statsFile != null) {
            outcome.writeStats(files.statsFile, stats, settings, loadSeconds, bvhSeconds, s);
        }
        irq.written();
        outcome.report(err, stats, settings, time, irq.interrupted());
        return irq.interrupted() ? irq.exitCode() : 0;
    }
}
