package dev.strahl.cli;

import picocli.CommandLine.Option;

/** {@code render}'s "Denoising" section: whether the image is denoised before it is written, and by which denoiser. */
final class DenoiseOptions {

    @Option(names = "--denoise", description = "Denoise the image before writing it (the feature buffers are then rendered too).")
    boolean denoise;

    @Option(names = "--denoiser", defaultValue = "strahl", paramLabel = "strahl|oidn",
            description = "With --denoise: strahl's own (pure Java, the default) or Intel Open Image Denoise's oidnDenoise found on the PATH.")
    String denoiserName;
}
