package dev.strahl.render;

import java.time.Duration;
import java.util.Collections;
import java.util.EnumSet;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.function.Consumer;

/**
 * How to render, by concern: the {@link Output} (film size, feature buffers), the {@link Sampling} (samples per
 * pixel, seed, noise threshold), the light {@link Transport} (integrator and its parameters) and the {@link Execution}
 * (threads, passes, time limit; none of it changes the image's bits). Immutable; start from {@link #defaults()} and
 * change what you need with the {@code with...} methods, which return modified copies:
 * <pre>{@code
 * RenderSettings s = RenderSettings.defaults().withSize(800, 600).withSamplesPerPixel(256).withSeed(7);
 * int depth = s.transport().maxDepth();
 * }</pre>
 *
 * @param output    what the render makes: the film and the feature buffers kept beside it
 * @param sampling  how many camera samples each pixel takes, and from which random sequence
 * @param transport which light transport algorithm computes the radiance, with its parameters
 * @param execution how the work is done: threads, passes, time limit and the teaching options that change no bit
 */
public record RenderSettings(Output output, Sampling sampling, Transport transport, Execution execution) {
    /** Largest accepted film edge, to refuse absurd sizes before allocating. */
    public static final int MAX_SIZE = 1 << 15;

    /**
     * Checks that no part is missing (each part checks its own values).
     *
     * @param output    the film and feature buffers
     * @param sampling  samples per pixel and seed
     * @param transport the integrator and its parameters
     * @param execution threads, passes, time limit
     */
    public RenderSettings {
        Objects.requireNonNull(output, "output");
        Objects.requireNonNull(sampling, "sampling");
        Objects.requireNonNull(transport, "transport");
        Objects.requireNonNull(execution, "execution");
    }

    /**
     * What the render makes.
     *
     * @param width  film width in pixels, 1 .. {@value RenderSettings#MAX_SIZE}
     * @param height film height in pixels, 1 .. {@value RenderSettings#MAX_SIZE}
     * @param aovs   the feature buffers to keep beside the image (empty: none); see {@link Aov}
     */
    public record Output(int width, int height, Set<Aov> aovs) {
        /**
         * Checks the size; copies the set (iterated in the order of {@link Aov}).
         *
         * @param width  film width in pixels
         * @param height film height in pixels
         * @param aovs   the feature buffers to keep
         */
        public Output {
            if (width <= 0 || height <= 0) {
                throw new IllegalArgumentException("image size must be positive, got " + width + "x" + height);
            }
            if (width > MAX_SIZE || height > MAX_SIZE) {
                throw new IllegalArgumentException("image size " + width + "x" + height + " is larger than " + MAX_SIZE + " pixels on a side");
            }
            aovs = aovs.isEmpty() ? Set.of() : Collections.unmodifiableSet(EnumSet.copyOf(aovs));
        }

        /**
         * Whether the film keeps the sums of the {@linkplain Aov#traced() traced} feature buffers (not needed for {@link Aov#SPP}).
         *
         * @return true if a traced feature buffer is among {@link #aovs()}
         */
        public boolean keepsFeatures() {
            return aovs.stream().anyMatch(Aov::traced);
        }
    }

    /**
     * The camera samples of every pixel.
     *
     * @param samplesPerPixel camera samples per pixel, positive; with a noise threshold, the most a pixel may take
     * @param seed            the render seed; with the other settings it fixes the image bit for bit
     * @param noiseThreshold  0, or the target relative standard error of every pixel's mean in (0, 1] (adaptive sampling)
     */
    public record Sampling(int samplesPerPixel, long seed, double noiseThreshold) {
        /**
         * Checks the sample count and the threshold.
         *
         * @param samplesPerPixel camera samples per pixel
         * @param seed            the render seed
         * @param noiseThreshold  0, or the target relative standard error in (0, 1]
         */
        public Sampling {
            if (samplesPerPixel <= 0) {
                throw new IllegalArgumentException("samples per pixel must be positive, got " + samplesPerPixel);
            }
            if (!(noiseThreshold >= 0 && noiseThreshold <= 1)) {
                throw new IllegalArgumentException("noise threshold must be 0 (off) or in (0, 1] (0.01 = 1 %), got " + noiseThreshold);
            }
        }
    }

    /**
     * The light transport.
     *
     * @param integrator    which light transport algorithm computes the radiance
     * @param maxDepth      path segments including the camera segment; -1 for unbounded
     * @param lightSamples  shadow rays per diffuse or glossy hit for the direct and Whitted integrators, at least 1
     * @param hemisphere    how diffuse surfaces sample directions
     * @param cullBackFaces skip back faces of closed meshes for camera and continuation rays
     * @param shadows       whether shadow rays are traced (false, a teaching option: every light sample counts as visible)
     * @param lightTree     whether lights are chosen by a light tree (false, a teaching option: by their power alone)
     * @param photons       the photon mapper's photons per iteration and initial gather radius
     */
    public record Transport(IntegratorKind integrator, int maxDepth, int lightSamples, HemisphereSampling hemisphere,
                            boolean cullBackFaces, boolean shadows, boolean lightTree, PhotonParameters photons) {
        /**
         * Checks every value; the message names the one that is wrong.
         *
         * @param integrator    the integrator
         * @param maxDepth      -1 or at least 1
         * @param lightSamples  at least 1
         * @param hemisphere    cosine or uniform
         * @param cullBackFaces whether back faces of closed meshes are skipped
         * @param shadows       whether shadow rays are traced
         * @param lightTree     whether lights are chosen by the light tree (else by power)
         * @param photons       the photon mapper's parameters
         */
        public Transport {
            Objects.requireNonNull(integrator, "integrator");
            if (maxDepth == 0 || maxDepth < -1) {
                throw new IllegalArgumentException("max depth must be -1 (unbounded) or >= 1, got " + maxDepth);
            }
            if (lightSamples < 1) {
                throw new IllegalArgumentException("light samples must be >= 1, got " + lightSamples);
            }
            Objects.requireNonNull(hemisphere, "hemisphere");
            Objects.requireNonNull(photons, "photons");
        }
    }

    /**
     * How the work is done; none of it changes the image's bits (docs/experiments.md for the teaching options).
     *
     * @param threads        worker threads; 0 for one per available processor
     * @param samplesPerPass samples per pixel in each pass over the image; 0 chooses (1, 2, 4, … up to 16)
     * @param timeLimit      stop at the end of the pass during which this much time has passed; zero for no limit
     * @param bruteForce     teaching option: every ray against every primitive instead of the BVH (same image, slower)
     * @param stripes        teaching option: one horizontal stripe per thread instead of tiles from a shared counter
     */
    public record Execution(int threads, int samplesPerPass, Duration timeLimit, boolean bruteForce, boolean stripes) {
        /**
         * Checks every value; the message names the one that is wrong.
         *
         * @param threads        worker threads, 0 or more
         * @param samplesPerPass samples per pixel per pass, 0 or more
         * @param timeLimit      not negative
         * @param bruteForce     whether the BVH is left out
         * @param stripes        whether threads render stripes instead of tiles
         */
        public Execution {
            if (threads < 0) {
                throw new IllegalArgumentException("threads must be >= 0 (0 = all processors), got " + threads);
            }
            if (samplesPerPass < 0) {
                throw new IllegalArgumentException("samples per pass must be >= 0 (0 = automatic), got " + samplesPerPass);
            }
            Objects.requireNonNull(timeLimit, "timeLimit");
            if (timeLimit.isNegative()) {
                throw new IllegalArgumentException("time limit must not be negative, got " + timeLimit);
            }
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

    /**
     * 512×512 without feature buffers; 64 spp, seed 0, no noise threshold; path tracing with unbounded depth, one light
     * sample, cosine sampling, no culling, shadows, the light tree and the photon mapper's
     * {@linkplain PhotonParameters#defaults() defaults}; all processors, automatic passes, no time
     * limit, the BVH and tiles.
     *
     * @return the defaults
     */
    public static RenderSettings defaults() {
        return new RenderSettings(new Output(512, 512, Set.of()), new Sampling(64, 0, 0),
                new Transport(IntegratorKind.PATH, -1, 1, HemisphereSampling.COSINE, false, true, true, PhotonParameters.defaults()),
                new Execution(0, 0, Duration.ZERO, false, false));
    }

    /**
     * Every setting by name ({@code width}, {@code seed}, {@code photons.photonsPerIteration}, …) with its value
     * (Integer, Long, Double, Boolean, an enum, a Duration or a set of {@link Aov}): what checkpoints, cluster
     * members and {@code render --stats} record.
     *
     * @return the settings in the order of the parts and their components, unmodifiable
     */
    public Map<String, Object> entries() {
        return SettingsCodec.entries(this);
    }

    /**
     * These settings with another film size.
     *
     * @param w width in pixels
     * @param h height in pixels
     * @return a new settings object
     */
    public RenderSettings withSize(int w, int h) {
        return edit(e -> e.size(w, h));
    }

    /**
     * These settings with other feature buffers.
     *
     * @param kept the buffers to keep beside the image; none for an empty set
     * @return a new settings object
     */
    public RenderSettings withAovs(Set<Aov> kept) {
        return edit(e -> e.aovs = kept);
    }

    /**
     * These settings with another sample count (with a noise threshold: the most a pixel takes).
     *
     * @param spp samples per pixel, positive
     * @return a new settings object
     */
    public RenderSettings withSamplesPerPixel(int spp) {
        return edit(e -> e.samplesPerPixel = spp);
    }

    /**
     * These settings with another noise threshold (adaptive sampling: docs/integrators.md, "Render until clean"),
     * or (0) none; with one, the sample count is the most a pixel takes.
     *
     * @param t 0 for none, or the target relative standard error of every pixel's mean, in (0, 1]
     * @return a new settings object
     */
    public RenderSettings withNoiseThreshold(double t) {
        return edit(e -> e.noiseThreshold = t);
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
     * These settings with another integrator.
     *
     * @param kind the integrator
     * @return a new settings object
     */
    public RenderSettings withIntegrator(IntegratorKind kind) {
        return edit(e -> e.integrator = kind);
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
     * These settings with another number of shadow rays per hit.
     *
     * @param n shadow rays per diffuse or glossy hit, at least 1
     * @return a new settings object
     */
    public RenderSettings withLightSamples(int n) {
        return edit(e -> e.lightSamples = n);
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
     * These settings with or without shadows; without is a teaching option (docs/experiments.md, experiment 3).
     *
     * @param s true to trace shadow rays (the default), false for none
     * @return a new settings object
     */
    public RenderSettings withShadows(boolean s) {
        return edit(e -> e.shadows = s);
    }

    /**
     * These settings with lights chosen by the light tree or, a teaching option, by their power alone
     * wherever the shading point is: same image, more noise (docs/integrators.md, many lights).
     *
     * @param tree true for the light tree (the default), false for power alone
     * @return a new settings object
     */
    public RenderSettings withLightTree(boolean tree) {
        return edit(e -> e.lightTree = tree);
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
     * These settings with another thread count.
     *
     * @param n worker threads; 0 for one per processor
     * @return a new settings object
     */
    public RenderSettings withThreads(int n) {
        return edit(e -> e.threads = n);
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
     * These settings with another time limit.
     *
     * @param limit stop after the pass that crosses it; zero for none
     * @return a new settings object
     */
    public RenderSettings withTimeLimit(Duration limit) {
        return edit(e -> e.timeLimit = limit);
    }

    /**
     * These settings with or without the BVH: a teaching option (docs/experiments.md). Without it every ray is
     * tested against every primitive, as in a first ray tracer; same image, many times slower.
     *
     * @param b true for brute force, false for the BVH (the default)
     * @return a new settings object
     */
    public RenderSettings withBruteForce(boolean b) {
        return edit(e -> e.bruteForce = b);
    }

    /**
     * These settings with one horizontal stripe per thread (a teaching option) or 32×32 tiles shared by all.
     *
     * @param s true for stripes, false for tiles (the default)
     * @return a new settings object
     */
    public RenderSettings withStripes(boolean s) {
        return edit(e -> e.stripes = s);
    }

    /** A copy with some values changed: every {@code with...} method is one line, the parts are rebuilt in {@link SettingsFields}. */
    private RenderSettings edit(Consumer<SettingsFields> change) {
        return new SettingsFields(this).apply(change);
    }
}
