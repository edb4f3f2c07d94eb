package dev.strahl.render;

import dev.strahl.integrator.IntegratorKind;
import dev.strahl.integrator.PhotonParameters;
import dev.strahl.sampling.HemisphereSampling;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.SceneSettings;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;
import java.util.Set;

/**
 * How to render: film size, samples per pixel, path depth, seed, threads and sampling choices.
 * Immutable; the {@code with...} methods return modified copies.
 *
 * @param width           film width in pixels
 * @param height          film height in pixels
 * @param samplesPerPixel camera samples per pixel
 * @param maxDepth        path segments including the camera segment; -1 for unbounded
 * @param seed            the render seed; with the other settings it fixes the image bit for bit
 * @param threads         worker threads; 0 for one per available processor
 * @param hemisphere      how diffuse surfaces sample directions
 * @param cullBackFaces   skip back faces of closed meshes for camera and continuation rays
 * @param samplesPerPass  samples per pixel in each pass over the image; 0 chooses (1, 2, 4, … up to 16)
 * @param integrator      which light transport algorithm computes the radiance
 * @param lightSamples    shadow rays per diffuse or glossy hit for the direct and Whitted integrators
 * @param timeLimit       stop at the end of the pass during which this much time has passed; zero for no limit
 * @param photons         photons emitted per iteration (= per sample per pixel) by the photon mapper
 * @param photonRadius    the photon mapper's initial gather radius in scene units; 0 = automatic (from the scene size)
 */
public record RenderSettings(int width, int height, int samplesPerPixel, int maxDepth, long seed, int threads,
                             HemisphereSampling hemisphere, boolean cullBackFaces, int samplesPerPass,
                             IntegratorKind integrator, int lightSamples, Duration timeLimit,
                             int photons, double photonRadius) {

    /** Largest accepted film edge, to refuse absurd sizes before allocating. */
    public static final int MAX_SIZE = 1 << 15;

    /**
     * Checks every setting; the message of the exception names the one that is wrong.
     *
     * @param width           film width in pixels
     * @param height          film height in pixels
     * @param samplesPerPixel camera samples per pixel
     * @param maxDepth        path segments including the camera segment; -1 for unbounded
     * @param seed            the render seed; with the other settings it fixes the image bit for bit
     * @param threads         worker threads; 0 for one per available processor
     * @param hemisphere      how diffuse surfaces sample directions
     * @param cullBackFaces   skip back faces of closed meshes for camera and continuation rays
     * @param samplesPerPass  samples per pixel in each pass over the image; 0 chooses (1, 2, 4, … up to 16)
     * @param integrator      which light transport algorithm computes the radiance
     * @param lightSamples    shadow rays per diffuse or glossy hit for the direct and Whitted integrators
     * @param timeLimit       stop at the end of the pass during which this much time has passed; zero for no limit
     * @param photons         photons per iteration of the photon mapper, 1 .. {@value PhotonParameters#MAX_PHOTONS}
     * @param photonRadius    the photon mapper's initial gather radius, finite and &gt;= 0; 0 = automatic
     */
    public RenderSettings {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("image size must be positive, got " + width + "x" + height);
        }
        if (width > MAX_SIZE || height > MAX_SIZE) {
            throw new IllegalArgumentException("image size " + width + "x" + height + " is larger than " + MAX_SIZE + " pixels on a side");
        }
        if (samplesPerPixel <= 0) {
            throw new IllegalArgumentException("samples per pixel must be positive, got " + samplesPerPixel);
        }
        if (maxDepth == 0 || maxDepth < -1) {
            throw new IllegalArgumentException("max depth must be -1 (unbounded) or >= 1, got " + maxDepth);
        }
        if (threads < 0) {
            throw new IllegalArgumentException("threads must be >= 0 (0 = all processors), got " + threads);
        }
        if (samplesPerPass < 0) {
            throw new IllegalArgumentException("samples per pass must be >= 0 (0 = automatic), got " + samplesPerPass);
        }
        if (lightSamples < 1) {
            throw new IllegalArgumentException("light samples must be >= 1, got " + lightSamples);
        }
        Objects.requireNonNull(hemisphere, "hemisphere");
        Objects.requireNonNull(integrator, "integrator");
        Objects.requireNonNull(timeLimit, "timeLimit");
        if (timeLimit.isNegative()) {
            throw new IllegalArgumentException("time limit must not be negative, got " + timeLimit);
        }
        new PhotonParameters(photons, photonRadius);        // validates
    }

    /**
     * Settings with the photon mapper's defaults ({@value PhotonParameters#DEFAULT_PHOTONS} photons
     * per iteration, automatic radius).
     *
     * @param width           film width in pixels
     * @param height          film height in pixels
     * @param samplesPerPixel camera samples per pixel
     * @param maxDepth        path segments including the camera segment; -1 for unbounded
     * @param seed            the render seed
     * @param threads         worker threads; 0 for one per available processor
     * @param hemisphere      how diffuse surfaces sample directions
     * @param cullBackFaces   skip back faces of closed meshes for camera and continuation rays
     * @param samplesPerPass  samples per pixel in each pass; 0 chooses
     * @param integrator      which light transport algorithm computes the radiance
     * @param lightSamples    shadow rays per diffuse or glossy hit for the direct and Whitted integrators
     * @param timeLimit       stop at the end of the pass that crosses this time; zero for no limit
     */
    public RenderSettings(int width, int height, int samplesPerPixel, int maxDepth, long seed, int threads,
                          HemisphereSampling hemisphere, boolean cullBackFaces, int samplesPerPass,
                          IntegratorKind integrator, int lightSamples, Duration timeLimit) {
        this(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples,
                timeLimit, PhotonParameters.DEFAULT_PHOTONS, 0);
    }

    /**
     * 512×512, 64 spp, unbounded depth, seed 0, all processors, cosine sampling, no culling, path
     * tracing (and for the photon mapper {@value PhotonParameters#DEFAULT_PHOTONS} photons per
     * iteration, automatic radius).
     *
     * @return the defaults
     */
    public static RenderSettings defaults() {
        return new RenderSettings(512, 512, 64, -1, 0, 0, HemisphereSampling.COSINE, false, 0, IntegratorKind.PATH, 1, Duration.ZERO);
    }

    /**
     * These settings with another the film size.
     *
     * @param w width in pixels
     * @param h height in pixels
     * @return a new settings object
     */
    public RenderSettings withSize(int w, int h) {
        return new RenderSettings(w, h, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit, photons, photonRadius);
    }

    /**
     * These settings with another the samples per pixel.
     *
     * @param spp samples per pixel, positive
     * @return a new settings object
     */
    public RenderSettings withSamplesPerPixel(int spp) {
        return new RenderSettings(width, height, spp, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit, photons, photonRadius);
    }

    /**
     * These settings with another the path depth.
     *
     * @param depth path segments including the camera segment; -1 for unbounded
     * @return a new settings object
     */
    public RenderSettings withMaxDepth(int depth) {
        return new RenderSettings(width, height, samplesPerPixel, depth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit, photons, photonRadius);
    }

    /**
     * These settings with another the seed.
     *
     * @param s the random seed
     * @return a new settings object
     */
    public RenderSettings withSeed(long s) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, s, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit, photons, photonRadius);
    }

    /**
     * These settings with another the thread count.
     *
     * @param n worker threads; 0 for one per processor
     * @return a new settings object
     */
    public RenderSettings withThreads(int n) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, n, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit, photons, photonRadius);
    }

    /**
     * These settings with another the sampling of diffuse bounces.
     *
     * @param h cosine or uniform
     * @return a new settings object
     */
    public RenderSettings withHemisphere(HemisphereSampling h) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, h, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit, photons, photonRadius);
    }

    /**
     * These settings with another back-face culling.
     *
     * @param cull whether camera and continuation rays skip back faces of closed meshes
     * @return a new settings object
     */
    public RenderSettings withCullBackFaces(boolean cull) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cull, samplesPerPass, integrator, lightSamples, timeLimit, photons, photonRadius);
    }

    /**
     * These settings with another the pass size.
     *
     * @param n samples per pixel per pass; 0 for automatic
     * @return a new settings object
     */
    public RenderSettings withSamplesPerPass(int n) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, n, integrator, lightSamples, timeLimit, photons, photonRadius);
    }

    /**
     * These settings with another the integrator.
     *
     * @param kind the integrator
     * @return a new settings object
     */
    public RenderSettings withIntegrator(IntegratorKind kind) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, kind, lightSamples, timeLimit, photons, photonRadius);
    }

    /**
     * These settings with another the shadow rays per hit.
     *
     * @param n shadow rays per diffuse or glossy hit, at least 1
     * @return a new settings object
     */
    public RenderSettings withLightSamples(int n) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, n, timeLimit, photons, photonRadius);
    }

    /**
     * These settings with another the time limit.
     *
     * @param limit stop after the pass that crosses it; zero for none
     * @return a new settings object
     */
    public RenderSettings withTimeLimit(Duration limit) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, limit, photons, photonRadius);
    }

    /**
     * These settings with another photon count for the photon mapper.
     *
     * @param n photons traced per iteration (= per sample per pixel), 1 .. {@value PhotonParameters#MAX_PHOTONS}
     * @return a new settings object
     */
    public RenderSettings withPhotons(int n) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit, n, photonRadius);
    }

    /**
     * These settings with another initial gather radius for the photon mapper.
     *
     * @param radius the first iteration's radius in scene units; 0 chooses it from the scene size
     * @return a new settings object
     */
    public RenderSettings withPhotonRadius(double radius) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit, photons, radius);
    }

    /**
     * The photon mapper's parameters.
     *
     * @return photons per iteration and initial radius
     */
    public PhotonParameters photonParameters() {
        return new PhotonParameters(photons, photonRadius);
    }

    /**
     * These settings with what a scene file asks for applied on top (its {@code film} and
     * {@code integrator} keys); keys the file leaves out keep their value here.
     *
     * @param scene the scene file's settings ({@code scene.settings()})
     * @return the combined settings
     * @throws IllegalArgumentException if the file names an unknown integrator (or a value out of range,
     *                                  which a scene file read by {@code SceneLoader} cannot hold)
     */
    public RenderSettings withScene(SceneSettings scene) {
        RenderSettings s = this;
        if (scene.width() != null || scene.height() != null) {
            s = s.withSize(scene.width() != null ? scene.width() : width, scene.height() != null ? scene.height() : height);
        }
        if (scene.samplesPerPixel() != null) {
            s = s.withSamplesPerPixel(scene.samplesPerPixel());
        }
        if (scene.maxDepth() != null) {
            s = s.withMaxDepth(scene.maxDepth());
        }
        if (scene.seed() != null) {
            s = s.withSeed(scene.seed());
        }
        if (scene.lightSamples() != null) {
            s = s.withLightSamples(scene.lightSamples());
        }
        if (scene.hemisphere() != null) {
            s = s.withHemisphere(scene.hemisphere());
        }
        if (scene.integrator() != null) {
            s = s.withIntegrator(integratorNamed(scene.integrator()));
        }
        if (scene.photons() != null) {
            s = s.withPhotons(scene.photons());
        }
        if (scene.photonRadius() != null) {
            s = s.withPhotonRadius(scene.photonRadius());
        }
        return s;
    }

    /**
     * These settings combined with a scene file's the way the command line combines them: the
     * file's {@code film} and {@code integrator} keys replace the values here, except those of the
     * settings in {@code given} (options given on the command line), which keep their value here.
     * Every key of the file is checked, also those overridden, so a file is refused or accepted
     * whatever the command line says. {@code strahl render} and {@code strahl view} both combine
     * their options with a scene file here.
     *
     * @param file  the scene file, for the error message
     * @param scene the scene file's settings ({@code scene.settings()})
     * @param given the settings whose value here wins over the file's
     * @return the combined settings
     * @throws SceneException naming {@code file} if the file names an unknown integrator (or a value
     *                        out of range, which a scene file read by {@code SceneLoader} cannot hold)
     */
    public RenderSettings withSceneFile(Path file, SceneSettings scene, Set<SceneSettings.Setting> given) throws SceneException {
        RenderSettings s;
        try {
            s = withScene(scene);
        } catch (IllegalArgumentException e) {
            throw new SceneException(file, e.getMessage(), e);
        }
        for (SceneSettings.Setting setting : given) {
            s = s.withValueOf(setting, this);
        }
        return s;
    }

    /**
     * These settings with the value of one scene-file setting taken from {@code from}. (A switch
     * expression: a new {@link SceneSettings.Setting} does not compile until it is handled here.)
     */
    private RenderSettings withValueOf(SceneSettings.Setting setting, RenderSettings from) {
        return switch (setting) {
            case WIDTH -> withSize(from.width, height);
            case HEIGHT -> withSize(width, from.height);
            case SAMPLES_PER_PIXEL -> withSamplesPerPixel(from.samplesPerPixel);
            case MAX_DEPTH -> withMaxDepth(from.maxDepth);
            case SEED -> withSeed(from.seed);
            case INTEGRATOR -> withIntegrator(from.integrator);
            case LIGHT_SAMPLES -> withLightSamples(from.lightSamples);
            case HEMISPHERE -> withHemisphere(from.hemisphere);
            case PHOTONS -> withPhotons(from.photons);
            case PHOTON_RADIUS -> withPhotonRadius(from.photonRadius);
        };
    }

    /**
     * The integrator of a name as used on the command line and in scene files.
     *
     * @param name "path", "direct", "whitted", ...
     * @return the integrator kind
     * @throws IllegalArgumentException for an unknown name
     */
    public static IntegratorKind integratorNamed(String name) {
        for (IntegratorKind k : IntegratorKind.values()) {
            if (k.id().equals(name)) {
                return k;
            }
        }
        throw new IllegalArgumentException("unknown integrator '" + name + "' (known: "
                + String.join(", ", java.util.Arrays.stream(IntegratorKind.values()).map(IntegratorKind::id).toList()) + ")");
    }

    /**
     * The thread count to use.
     *
     * @return {@link #threads()}, or the available processors when it is 0
     */
    public int effectiveThreads() {
        return threads > 0 ? threads : Runtime.getRuntime().availableProcessors();
    }
}
