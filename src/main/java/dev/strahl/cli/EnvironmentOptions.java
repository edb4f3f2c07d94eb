package dev.strahl.cli;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/** The environment map that replaces the scene's environment: the "Environment" section of {@code render} and {@code view}. */
final class EnvironmentOptions {

    @Option(names = "--envmap", paramLabel = "FILE",
            description = "Light the scene with this latitude-longitude environment map (.hdr, .exr or .pfm; +Y up, centre column"
                    + " along +Z) instead of its own environment.")
    Path envmap;
}
