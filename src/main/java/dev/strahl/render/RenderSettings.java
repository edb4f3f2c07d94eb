package dev.strahl.render;

import java.time.Duration;
import java.util.Collections;
import java.util.EnumSet;
import java.util.Objects;
import java.util.Set;
import java.util.function.Consumer;

/**
 * How to render: film size, samples per pixel, path depth, seed, threads and the choice of light
 * transport. Immutable; start from {@link #defaults()} and change what you need with the
 * {@code with...} methods, which return modified copies:
 * <pre>{@code
 * RenderSettings s = RenderSettings.defaults().withSize(800, 600).withSamplesPerPixel(256).withSeed(7);
 * }</pre>
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
 * @param photons         the photon mapper's photons per iteration and initial gather radius
 * @param bruteForce      teaching option: every ray against every primitive instead of the BVH (same image, slower)
 * @param stripes         teaching option: one horizontal stripe per thread instead of tiles from a shared counter
 * @param shadows         whether shadow rays are traced; false is a teaching option: every light sample counts as
 *                        visible, so lights shine through everything onto whatever faces them (no shadows)
 * @param aovs            the feature buffers to keep beside the image (empty: none); see {@link Aov}
 */
public record RenderSettings(int width, int height, int samplesPerPixel, int maxDepth, long seed, int threads,
                             HemisphereSampling hemisphere, boolean cullBackFaces, int samplesPerPass,
                             IntegratorKind integrator, int lightSamples, Duration timeLimit, PhotonParameters photons,
                             boolean bruteForce, boolean stripes, boolean shadows, Set<Aov> aovs) {

    /** Largest accepted film edge, to refuse absurd sizes before allocating. */
    public static final int MAX_SIZE = 1 << 15;

    /**
     * Checks every setting; the message of the exception names the one that is wrong.
     *
     * @param width           film width in pixels, 1 .. {@value #MAX_SIZE}
     * @param height          film height in pixels, 1 .. {@value #MAX_SIZE}
     * @param samplesPerPixel camera samples per pixel, positive
     * @param maxDepth        path segments including the camera segment; -1 for unbounded
     * @param seed            the render seed
     * @param threads         worker threads; 0 for one per available processor
     * @param hemisphere      how diffuse surfaces sample directions
     * @param cullBackFaces   skip back faces of closed meshes for camera and continuation rays
     * @param samplesPerPass  samples per pixel in each pass; 0 chooses
     * @param integrator      which light transport algorithm computes the radiance
     * @param lightSamples    shadow rays per diffuse or glossy hit, at least 1
     * @param timeLimit       stop at the end of the pass that crosses this time; zero for no limit
     * @param photons         the photon mapper's parameters
     * @param bruteForce      teaching option: no BVH, every ray against every primitive (docs/experiments.md)
     * @param stripes         teaching option: one stripe of the image per thread instead of tiles (docs/experiments.md)
     * @param shadows         false is a teaching option: no shadow rays, every light sample visible (docs/experiments.md)
     * @param aovs            the feature buffers to keep; copied (iterated in the order of {@link Aov})
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
        Objects.requireNonNull(photons, "photons");
        aovs = aovs.isEmpty() ? Set.of() : Collections.unmodifiableSet(EnumSet.copyOf(aovs));
        if (timeLimit.isNegative()) {
            throw new IllegalArgumentException("time limit must not be negative, got " + timeLimit);
        }
    }

    /**
     * Settings with shadows, as before the teaching option {@link #shadows()} existed: the
     * canonical constructor's other components, checked the same way.
     *
     * @param width           film width in pixels, 1 .. {@value #MAX_SIZE}
     * @param height          film height in pixels, 1 .. {@value #MAX_SIZE}
     * @param samplesPerPixel camera samples per pixel, positive
     * @param maxDepth        path segments including the camera segment; -1 for unbounded
     * @param seed            the render seed
     * @param threads         worker threads; 0 for one per available processor
     * @param hemisphere      how diffuse surfaces sample directions
     * @param cullBackFaces   skip back faces of closed meshes for camera and continuation rays
     * @param samplesPerPass  samples per pixel in each pass; 0 chooses
     * @param integrator      which light transport algorithm computes the radiance
     * @param lightSamples    shadow rays per diffuse or glossy hit, at least 1
     * @param timeLimit       stop at the end of the pass that crosses this time; zero for no limit
     * @param photons         the photon mapper's parameters
     * @param bruteForce      teaching option: no BVH, every ray against every primitive
     * @param stripes         teaching option: one stripe of the image per thread instead of tiles
     * @param aovs            the feature buffers to keep
     */
    public RenderSettings(int width, int height, int samplesPerPixel, int maxDepth, long seed, int threads,
                          HemisphereSampling hemisphere, boolean cullBackFaces, int samplesPerPass,
                          IntegratorKind integrator, int lightSamples, Duration timeLimit, PhotonParameters photons,
                          boolean bruteForce, boolean stripes, Set<Aov> aovs) {
        this(width, height, samplesPerPixel, maxDepth, seed, threads, hemisphere, cullBackFaces, samplesPerPass, integrator,
                lightSamples, timeLimit, photons, bruteForce, stripes, true, aovs);
    }

    /**
     * 512×512, 64 spp, unbounded depth, seed 0, all processors, cosine sampling, no culling,
     * automatic passes, path tracing with one light sample, no time limit, the photon mapper's
     * {@linkplain PhotonParameters#defaults() defaults}, the BVH and tiles, shadows, and no feature buffers.
     *
     * @return the defaults
     */
    public static RenderSettings defaults() {
        return new RenderSettings(512, 512, 64, -1, 0, 0, HemisphereSampling.COSINE, false, 0, IntegratorKind.PATH, 1, Duration.ZERO,
                PhotonParameters.defaults(), false, false, true, Set.of());
    }

    /**
     * These settings with another film size.
     *
     * @param w width in pixels
     * @param h height in pixels
     * @return a new settings object
     */
    public RenderSettings withSize(int w, int h) {
        return edit(e -> {
            e.width = w;
            e.height = h;
        });
    }

    /**
     * These settings with another sample count.
     *
     * @param spp samples per pixel, positive
     * @return a new settings object
     */
    public RenderSettings withSamplesPerPixel(int spp) {
        return edit(e -> e.samplesPerPixel = spp);
    }

    /**
     * These settings with another path depth.
     *
     * @param depth path segments including the camera segment; -1 for unbounded
     * @return a new settings object
     */
    public RenderSettings withMaxDepth(int depth) {
        return edit(e -> e.maxDepth = depth);
    }

    /**
     * These settings with another seed.
     *
     * @param s the random seed
     * @return a new settings object
     */
    public RenderSettings withSeed(long s) {
        return edit(e -> e.seed = s);
    }

    /**
     * These settings with another thread count.
     *
     * @param n worker threads; 0 for one per processor
     * @return a new settings object
     */
    public RenderSettings withThreads(int n) {
        return edit(e -> e.threads = n);
    }

    /**
     * These settings with another sampling of diffuse bounces.
     *
     * @param h cosine or uniform
     * @return a new settings object
     */
    public RenderSettings withHemisphere(HemisphereSampling h) {
        return edit(e -> e.hemisphere = h);
    }

    /**
     * These settings with or without back-face culling.
     *
     * @param cull whether camera and continuation rays skip back faces of closed meshes
     * @return a new settings object
     */
    public RenderSettings withCullBackFaces(boolean cull) {
        return edit(e -> e.cullBackFaces = cull);
    }

    /**
     * These settings with another pass size.
     *
     * @param n samples per pixel per pass; 0 for automatic
     * @return a new settings object
     */
    public RenderSettings withSamplesPerPass(int n) {
        return edit(e -> e.samplesPerPass = n);
    }

    /**
     * These settings with another integrator.
     *
     * @param kind the integrator
     * @return a new settings object
     */
    public RenderSettings withIntegrator(IntegratorKind kind) {
        return edit(e -> e.integrator = kind);
    }

    /**
     * These settings with another number of shadow rays per hit.
     *
     * @param n shadow rays per diffuse or glossy hit, at least 1
     * @return a new settings object
     */
    public RenderSettings withLightSamples(int n) {
        return edit(e -> e.lightSamples = n);
    }

    /**
     * These settings with another time limit.
     *
     * @param limit stop after the pass that crosses it; zero for none
     * @return a new settings object
     */
    public RenderSettings withTimeLimit(Duration limit) {
        return edit(e -> e.timeLimit = limit);
    }

    /**
     * These settings with other parameters for the photon mapper.
     *
     * @param p photons per iteration and initial gather radius
     * @return a new settings object
     */
    public RenderSettings withPhotons(PhotonParameters p) {
        return edit(e -> e.photons = p);
    }

    /**
     * These settings with or without the BVH: a teaching option. Without it every ray is tested
     * against every primitive, the brute-force loop a first ray tracer starts from; same hits and
     * image, many times slower (docs/experiments.md).
     *
     * @param b true for brute force, false for the BVH (the default)
     * @return a new settings object
     */
    public RenderSettings withBruteForce(boolean b) {
        return edit(e -> e.bruteForce = b);
    }

    /**
     * These settings with another way of sharing the image among threads: a teaching option. With
     * stripes, thread i of n renders the i-th horizontal stripe and nothing else (the scheme of a
     * first multithreaded renderer); without, threads take 32×32 tiles from a shared counter.
     *
     * @param s true for stripes, false for tiles (the default)
     * @return a new settings object
     */
    public RenderSettings withStripes(boolean s) {
        return edit(e -> e.stripes = s);
    }

    /**
     * These settings with or without shadows. Without is a teaching option, the picture a first
     * ray tracer makes before it learns shadow rays: no shadow ray is traced and every light
     * sample counts as visible, so each point shows the light of every light in front of it as if
     * nothing stood between (for a diffuse surface: Lambert × light). Every integrator honours it
     * in its next-event estimation; the path tracer then samples lights alone (no MIS) and, like
     * the photon mapper, still traces its bounces through the scene, so only the direct light
     * loses its shadows (docs/experiments.md, experiment 3).
     *
     * @param s true to trace shadow rays (the default), false for none
     * @return a new settings object
     */
    public RenderSettings withShadows(boolean s) {
        return edit(e -> e.shadows = s);
    }

    /**
     * These settings with other feature buffers.
     *
     * @param kept the feature buffers to keep beside the image; none for an empty set
     * @return a new settings object
     */
    public RenderSettings withAovs(Set<Aov> kept) {
        return edit(e -> e.aovs = kept);
    }

    /**
     * The thread count to use.
     *
     * @return {@link #threads()}, or the available processors when it is 0
     */
    public int effectiveThreads() {
        return threads > 0 ? threads : Runtime.getRuntime().availableProcessors();
    }

    /** A copy with some fields changed: every {@code with...} method is one line, the fields are listed once here. */
    private RenderSettings edit(Consumer<Fields> change) {
        Fields f = new Fields(this);
        change.accept(f);
        return new RenderSettings(f.width, f.height, f.samplesPerPixel, f.maxDepth, f.seed, f.threads, f.hemisphere, f.cullBackFaces,
                f.samplesPerPass, f.integrator, f.lightSamples, f.timeLimit, f.photons, f.bruteForce, f.stripes, f.shadows, f.aovs);
    }

    /** The components as mutable fields, for {@link #edit}. */
    private static final class Fields {
        int width, height, samplesPerPixel, maxDepth, threads, samplesPerPass, lightSamples;
        long seed;
        HemisphereSampling hemisphere;
        boolean cullBackFaces;
        IntegratorKind integrator;
        Duration timeLimit;
        PhotonParameters photons;
        boolean bruteForce;
        boolean stripes;
        boolean shadows;
        Set<Aov> aovs;

        Fields(RenderSettings s) {
            width = s.width;
            height = s.height;
            samplesPerPixel = s.samplesPerPixel;
            maxDepth = s.maxDepth;
            seed = s.seed;
            threads = s.threads;
            hemisphere = s.hemisphere;
            cullBackFaces = s.cullBackFaces;
            samplesPerPass = s.samplesPerPass;
            integrator = s.integrator;
            lightSamples = s.lightSamples;
            timeLimit = s.timeLimit;
            photons = s.photons;
            bruteForce = s.bruteForce;
            stripes = s.stripes;
            shadows = s.shadows;
            aovs = s.aovs;
        }
    }
}
