package dev.strahl.cli;

import picocli.CommandLine.Option;

/** {@code render}'s "Denoising" section: whether the image is denoised before it is written, and by which denoiser. */
final class DenoiseOptions {

    @Option(names = "--denoise", description = "Denoise the image before writing it (the feature buffers are then rendered too).")
    boolean denoise;

    @Option(names = "--denoiser", defaultValue = "network", paramLabel = "network|atrous|oidn",
            description = "With --denoise: network (the default: Intel Open Image Denoise's trained network, run in pure Java),"
                    + " atrous (a blurrier wavelet filter with no weights to read; its old name strahl works too) or oidn (OIDN's oidnDenoise found on the PATH).")
    String denoiserName;
}
