package dev.strahl.cli;

import dev.strahl.render.RenderSettings;
import java.nio.file.Path;
import java.time.Duration;
import picocli.CommandLine.Option;

/** {@code render}'s "Time and checkpoints" section: when to stop, where to save the state, what to continue. */
final class CheckpointOptions {

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

    /** {@code base} with the time limit (none if not given). */
    RenderSettings applyTo(RenderSettings base) {
        return base.withTimeLimit(timeLimit == null ? Duration.ZERO : timeLimit);
    }

    /** Where checkpoints are saved: --checkpoint, else the --resume file; null for none. */
    Path file() {
        return checkpoint != null ? checkpoint : resume;
    }

    /** Refuses a checkpoint file that is the output image or cannot be written. */
    void check(Path output) {
        Path file = file();
        if (file == null) {
            return;
        }
        if (file.toAbsolutePath().normalize().equals(output.toAbsolutePath().normalize())) {
            throw new IllegalArgumentException("the checkpoint " + file + " and the output image must be different files");
        }
        OutputFileOptions.checkWritable(file, "checkpoint");
    }
}
