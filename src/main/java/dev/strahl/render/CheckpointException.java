package dev.strahl.render;

import java.nio.file.Path;

/**
 * A checkpoint that cannot be resumed: not a checkpoint, truncated or corrupt, or made for
 * another scene or other settings. The message starts with the file ({@code file: what is wrong}).
 */
public final class CheckpointException extends Exception {
    private final transient Path file;

    /**
     * An error about a checkpoint file.
     *
     * @param file    the checkpoint
     * @param message what is wrong, without the file name
     */
    public CheckpointException(Path file, String message) {
        super(file + ": " + message);
        this.file = file;
    }

    /**
     * The checkpoint file the error is about.
     *
     * @return the file
     */
    public Path file() {
        return file;
    }
}
