package dev.strahl.cli;

import dev.strahl.render.Aov;
import dev.strahl.render.RenderSettings;
import java.util.List;
import java.util.Set;
import picocli.CommandLine.Option;

/** The film's size and the feature buffers kept beside it: the "Film" section of {@code render} and {@code view}. */
final class FilmOptions {

    @Option(names = "--width", defaultValue = "512", description = "Image width in pixels (default: ${DEFAULT-VALUE}).")
    int width;

    @Option(names = "--height", defaultValue = "512", description = "Image height in pixels (default: ${DEFAULT-VALUE}).")
    int height;

    @Option(names = "--aov", split = ",", paramLabel = "LIST",
            description = "Buffers to keep beside the image, as a scene file's film.aovs: albedo, normal, depth (comma-separated),"
                    + " the denoiser's guides, and spp, the samples each pixel took. render writes them: in an .exr as channels of the"
                    + " same file, beside a .png or .pfm as NAME.albedo.pfm, NAME.normal.pfm, NAME.depth.pfm, NAME.spp.pfm.")
    List<String> aovNames;

    /** The feature buffers asked for with --aov (checked), or none. */
    Set<Aov> aovs() {
        return SceneFileOptions.aovs(aovNames);
    }

    /** {@code base} with this film. */
    RenderSettings applyTo(RenderSettings base) {
        return base.withSize(width, height).withAovs(aovs());
    }
}
