package dev.strahl.cli;

import dev.strahl.render.HemisphereSampling;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.PhotonParameters;
import dev.strahl.render.RenderSettings;
import picocli.CommandLine.Option;

/** The light transport: the "Integrator" section of {@code render} and {@code view} (RenderSettings.Transport). */
final class TransportOptions {

    @Option(names = "--integrator", defaultValue = "path", paramLabel = "path|direct|whitted|photon",
            description = "Light transport: path (unbiased global illumination), direct (direct light only), whitted (recursive ray tracing) "
                    + "or photon (progressive photon mapping: clean caustics early) (default: ${DEFAULT-VALUE}).")
    IntegratorKind integrator;

    @Option(names = "--max-depth", defaultValue = "-1",
            description = "Path segments including the camera segment: 1 = emitters only, 2 = direct light, -1 = unbounded (default: ${DEFAULT-VALUE}).")
    int maxDepth;

    @Option(names = "--hemisphere", defaultValue = "cosine", paramLabel = "cosine|uniform",
            description = "Diffuse direction sampling: cosine-weighted or uniform; same image, uniform is noisier (default: ${DEFAULT-VALUE}).")
    HemisphereSampling hemisphere;

    @Option(names = "--light-samples", defaultValue = "1", paramLabel = "N",
            description = "Shadow rays per diffuse hit for direct and whitted: more gives smoother soft shadows (default: ${DEFAULT-VALUE}).")
    int lightSamples;

    @Option(names = "--photons", defaultValue = "" + PhotonParameters.DEFAULT_PHOTONS, paramLabel = "N",
            description = "Photons per iteration (one iteration per sample per pixel) for photon (default: ${DEFAULT-VALUE}).")
    int photons;

    @Option(names = "--photon-radius", defaultValue = "0", paramLabel = "R",
            description = "Initial photon gather radius in scene units for photon; it shrinks with the iterations. "
                    + "0 = 1/100 of the scene's bounding-box diagonal (default: ${DEFAULT-VALUE}).")
    double photonRadius;

    @Option(names = "--cull-back-faces", description = "Skip back faces of closed meshes for camera and bounce rays.")
    boolean cullBackFaces;

    /** {@code base} with this light transport (the photon parameters checked as they are made). */
    RenderSettings applyTo(RenderSettings base) {
        return base.withIntegrator(integrator).withMaxDepth(maxDepth).withHemisphere(hemisphere).withLightSamples(lightSamples)
                .withPhotons(new PhotonParameters(photons, photonRadius)).withCullBackFaces(cullBackFaces);
    }
}
