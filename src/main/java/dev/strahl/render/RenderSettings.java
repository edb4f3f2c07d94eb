package dev.strahl.render;

import dev.strahl.integrator.IntegratorKind;
import dev.strahl.sampling.HemisphereSampling;
import dev.strahl.scene.SceneSettings;
import java.time.Duration;
import java.util.Objects;

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
 */
public record RenderSettings(int width, int height, int samplesPerPixel, int maxDepth, long seed, int threads,
                             HemisphereSampling hemisphere, boolean cullBackFaces, int samplesPerPass,
                             IntegratorKind integrator, int lightSamples, Duration timeLimit) {

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
    }

    /**
     * 512×512, 64 spp, unbounded depth, seed 0, all processors, cosine sampling, no culling, path tracing.
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
        return new RenderSettings(w, h, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit);
    }

    /**
     * These settings with another the samples per pixel.
     *
     * @param spp samples per pixel, positive
     * @return a new settings object
     */
    public RenderSettings withSamplesPerPixel(int spp) {
        return new RenderSettings(width, height, spp, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit);
    }

    /**
     * These settings with another the path depth.
     *
     * @param depth path segments including the camera segment; -1 for unbounded
     * @return a new settings object
     */
    public RenderSettings withMaxDepth(int depth) {
        return new RenderSettings(width, height, samplesPerPixel, depth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit);
    }

    /**
     * These settings with another the seed.
     *
     * @param s the random seed
     * @return a new settings object
     */
    public RenderSettings withSeed(long s) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, s, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit);
    }

    /**
     * These settings with another the thread count.
     *
     * @param n worker threads; 0 for one per processor
     * @return a new settings object
     */
    public RenderSettings withThreads(int n) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, n, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit);
    }

    /**
     * These settings with another the sampling of diffuse bounces.
     *
     * @param h cosine or uniform
     * @return a new settings object
     */
    public RenderSettings withHemisphere(HemisphereSampling h) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, h, cullBackFaces, samplesPerPass, integrator, lightSamples, timeLimit);
    }

    /**
     * These settings with another back-face culling.
     *
     * @param cull whether camera and continuation rays skip back faces of closed meshes
     * @return a new settings object
     */
    public RenderSettings withCullBackFaces(boolean cull) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cull, samplesPerPass, integrator, lightSamples, timeLimit);
    }

    /**
     * These settings with another the pass size.
     *
     * @param n samples per pixel per pass; 0 for automatic
     * @return a new settings object
     */
    public RenderSettings withSamplesPerPass(int n) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, n, integrator, lightSamples, timeLimit);
    }

    /**
     * These settings with another the integrator.
     *
     * @param kind the integrator
     * @return a new settings object
     */
    public RenderSettings withIntegrator(IntegratorKind kind) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, kind, lightSamples, timeLimit);
    }

    /**
     * These settings with another the shadow rays per hit.
     *
     * @param n shadow rays per diffuse or glossy hit, at least 1
     * @return a new settings object
     */
    public RenderSettings withLightSamples(int n) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, n, timeLimit);
    }

    /**
     * These settings with another the time limit.
     *
     * @param limit stop after the pass that crosses it; zero for none
     * @return a new settings object
     */
    public RenderSettings withTimeLimit(Duration limit) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator, lightSamples, limit);
    }

    /**
     * These settings with what a scene file asks for applied on top (its {@code film} and
     * {@code integrator} keys); keys the file leaves out keep their value here.
     *
     * @param scene the scene file's settings ({@code scene.settings()})
     * @return the combined settings
     * @throws IllegalArgumentException if the file names an unknown integrator
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
        return s;
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
