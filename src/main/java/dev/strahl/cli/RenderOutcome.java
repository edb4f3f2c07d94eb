package dev.strahl.cli;

import dev.strahl.image.Image;
import dev.strahl.io.ImageWriters;
import dev.strahl.io.text.NumberText;
import dev.strahl.render.Aov;
import dev.strahl.render.Denoiser;
import dev.strahl.render.RenderBuffers;
import dev.strahl.render.RenderSettings;
import dev.strahl.render.RenderStats;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.math.MathContext;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;
import java.util.Set;

/**
 * What {@code render} does with a finished (or interrupted) render: denoises it if asked, writes
 * the image and the feature buffers asked for, the stats file, and the lines that report it.
 */
final class RenderOutcome {
    private final DenoiseOptions denoising;
    private final ImageWriters writer;
    private final Path output;
    private final boolean quiet;
    private final OidnDenoiser oidn;
    /** The pure-Java denoiser asked for (null with --denoiser oidn). */
    private final Denoiser denoiser;
    /** The feature buffers to write (those the denoiser needs are rendered also when not written). */
    private Set<Aov> written = Set.of();
    private double denoiseSeconds;

    /** Checks the denoiser's name, and finds oidnDenoise on the PATH if it is asked for. */
    RenderOutcome(DenoiseOptions denoising, ImageWriters writer, Path output, boolean quiet) {
        this.denoising = denoising;
        this.writer = writer;
        this.output = output;
        this.quiet = quiet;
        String name = denoising.denoiserName;
        this.denoiser = switch (name) {
            case "network" -> Denoiser.create();
            case "atrous", "strahl" -> Denoiser.atrous();
            case "oidn" -> null;
            default -> throw new IllegalArgumentException("--denoiser must be network, atrous or oidn, got '" + name + "'");
        };
        this.oidn = denoising.denoise && name.equals("oidn") ? OidnDenoiser.onPath() : null;
    }

    /** Writes these feature buffers of the render (the settings' --aov or the scene file's film.aovs). */
    void keep(Set<Aov> aovs) {
        written = aovs;
    }

    /** Denoises the image if asked, then writes it with the feature buffers kept. */
    void write(RenderBuffers buffers) {
        if (denoising.denoise) {
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
                written.contains(Aov.NORMAL) ? buffers.normal() : null, written.contains(Aov.DEPTH) ? buffers.depth() : null,
                written.contains(Aov.SPP) ? buffers.samples() : null);
        try {
            writer.write(buffers, output);
        } catch (IOException | UncheckedIOException e) {
            throw new RenderFailure("cannot write " + output + ": " + e.getMessage(), e);
        }
    }

    void writeStats(Path file, RenderStats stats, RenderSettings settings, double loadSeconds, double bvhSeconds, dev.strahl.scene.Scene scene) {
        try {
            StatsFile.write(file, stats, settings, loadSeconds, bvhSeconds, scene.textureBytes(), dev.strahl.world.World.of(scene));
        } catch (IOException e) {
            throw new RenderFailure("cannot write " + file + ": " + e.getMessage(), e);
        }
    }

    /** The lines after the render: interrupted, stopped by the time limit, done, denoised; NaN samples. */
    void report(PrintWriter err, RenderStats stats, RenderSettings settings, CheckpointOptions time, boolean interrupted) {
        Path checkpointFile = time.file();
        String resume = checkpointFile != null ? "; continue with --resume " + checkpointFile : "";
        int spp = settings.sampling().samplesPerPixel();
        boolean adaptive = settings.sampling().noiseThreshold() > 0;
        boolean allConverged = adaptive && stats.convergedFraction() >= 1;
        if (interrupted) {
            err.println(String.format(Locale.ROOT, "strahl: interrupted at %d of %d spp after %.2f s: wrote %s%s",
                    stats.samplesPerPixel(), spp, stats.seconds(), output, resume));
        } else if (!quiet) {
            if (stats.samplesPerPixel() < spp && !allConverged) {
                err.println("strahl: note: the time limit of " + limitText(time.timeLimit)
                        + " ended the render at " + stats.samplesPerPixel() + " of " + spp + " spp" + resume);
            }
            if (adaptive) {
                err.println(String.format(Locale.ROOT, "strahl: noise threshold %s: %s of the pixels converged%s; %d to %d spp, %.1f on average",
                        new BigDecimal(Double.toString(settings.sampling().noiseThreshold())).stripTrailingZeros().toPlainString(), percent(stats.convergedFraction()),
                        allConverged ? ", which ended the render" : "", stats.minSamplesPerPixel(), stats.maxSamplesPerPixel(),
                        stats.meanSamplesPerPixel()));
            }
            err.println(String.format(Locale.ROOT, "strahl: %s, %dx%d, %s spp in %.2f s (%s samples/s, %s rays/s, %d threads) -> %s",
                    settings.transport().integrator().id(), settings.output().width(), settings.output().height(),
                    adaptive ? "up to " + stats.maxSamplesPerPixel() : Integer.toString(stats.samplesPerPixel()),
                    stats.seconds(), NumberText.si(stats.samplesPerSecond()), NumberText.si(stats.raysPerSecond()), stats.threads(), output));
            if (denoising.denoise) {
                err.println(String.format(Locale.ROOT, "strahl: denoised with %s in %.2f s", oidn != null ? "oidnDenoise" : denoiser,
                        denoiseSeconds));
            }
        }
        if (!quiet && stats.invalidSamples() > 0) {
            err.println("strahl: warning: " + stats.invalidSamples() + " samples were NaN or infinite and counted as black");
        }
        err.flush();
    }

    /** "97 %", "99.9 %", "100 %": a share, never rounded up to all. */
    static String percent(double fraction) {
        double p = Math.floor(fraction * 1000) / 10;
        return (p == Math.floor(p) ? Integer.toString((int) p) : Double.toString(p)) + " %";
    }

    /** "0.3 s", "90 s", "5:00", "1:30:00". */
    static String limitText(Duration d) {
        double seconds = d.toNanos() * 1e-9;
        if (seconds >= 100) {
            return NumberText.duration(seconds);
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
