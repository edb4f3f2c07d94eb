package dev.strahl.io.json;

import dev.strahl.render.Aov;
import dev.strahl.render.HemisphereSampling;
import dev.strahl.render.IntegratorKind;
import dev.strahl.render.PhotonParameters;
import dev.strahl.render.RenderSettings;
import dev.strahl.scene.SceneException;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

/**
 * How a scene file asks to be rendered: its {@code film} and {@code integrator} keys. Every field
 * is null where the file says nothing. {@link #applyTo} puts the others on top of given settings,
 * except the {@link Setting}s a command line gives itself, which win. The reader has checked every
 * value against the limits of {@link RenderSettings}, so applying cannot fail.
 *
 * @param width           film width in pixels, or null
 * @param height          film height in pixels, or null
 * @param samplesPerPixel samples per pixel, or null
 * @param maxDepth        path segments including the camera segment (-1 unbounded), or null
 * @param seed            the random seed, or null
 * @param integrator      the integrator, or null
 * @param lightSamples    shadow rays per hit for the direct and Whitted integrators, or null
 * @param hemisphere      how diffuse bounces are sampled, or null
 * @param photons         photons per iteration for the photon mapper, or null
 * @param photonRadius    the photon mapper's initial gather radius in scene units (0 = automatic), or null
 * @param aovs            the feature buffers to keep ({@code film.aovs}), or null
 * @param aspectRatio     the film's width / height to keep when a command line gives only one of
 *                        them (a glTF camera's {@code aspectRatio}), or null: each on its own
 * @param noiseThreshold  the noise threshold of adaptive sampling ({@code integrator.noiseThreshold}; 0 = none), or null
 */
public record SceneSettings(Integer width, Integer height, Integer samplesPerPixel, Integer maxDepth, Long seed,
                            IntegratorKind integrator, Integer lightSamples, HemisphereSampling hemisphere,
                            Integer photons, Double photonRadius, Set<Aov> aovs, Double aspectRatio, Double noiseThreshold) {

    public SceneSettings {
        aovs = aovs == null ? null : Set.copyOf(aovs);
    }

    /** Settings without a noise threshold. */
    public SceneSettings(Integer width, Integer height, Integer samplesPerPixel, Integer maxDepth, Long seed, IntegratorKind integrator,
                         Integer lightSamples, HemisphereSampling hemisphere, Integer photons, Double photonRadius, Set<Aov> aovs,
                         Double aspectRatio) {
        this(width, height, samplesPerPixel, maxDepth, seed, integrator, lightSamples, hemisphere, photons, photonRadius, aovs, aspectRatio, null);
    }

    /** Settings without an aspect ratio to keep. */
    public SceneSettings(Integer width, Integer height, Integer samplesPerPixel, Integer maxDepth, Long seed, IntegratorKind integrator,
                         Integer lightSamples, HemisphereSampling hemisphere, Integer photons, Double photonRadius, Set<Aov> aovs) {
        this(width, height, samplesPerPixel, maxDepth, seed, integrator, lightSamples, hemisphere, photons, photonRadius, aovs, null);
    }

    /** Settings without {@code film.aovs}. */
    public SceneSettings(Integer width, Integer height, Integer samplesPerPixel, Integer maxDepth, Long seed, IntegratorKind integrator,
                         Integer lightSamples, HemisphereSampling hemisphere, Integer photons, Double photonRadius) {
        this(width, height, samplesPerPixel, maxDepth, seed, integrator, lightSamples, hemisphere, photons, photonRadius, null);
    }

    /**
     * The settings a scene file can give, one per field. A command line names the ones it gives
     * itself, so that the file's value of those is not used.
     */
    public enum Setting {
        WIDTH, HEIGHT, SAMPLES_PER_PIXEL, MAX_DEPTH, SEED, INTEGRATOR, LIGHT_SAMPLES, HEMISPHERE, PHOTONS, PHOTON_RADIUS, AOVS, NOISE_THRESHOLD
    }

    /** A file that says nothing about rendering (and every OBJ or PLY). */
    public static final SceneSettings NONE = new SceneSettings(null, null, null, null, null, null, null, null, null, null, null, null);

    public boolean isEmpty() {
        return equals(NONE);
    }

    /** {@code base} with the file's values on top. */
    public RenderSettings applyTo(RenderSettings base) {
        return applyTo(base, Set.of());
    }

    /**
     * {@code base} with the file's values on top, except those of the settings in {@code given}
     * (options given on a command line), which keep their value in {@code base}. {@code strahl
     * render} and {@code strahl view} both combine their options with a scene file here.
     */
    public RenderSettings applyTo(RenderSettings base, Set<Setting> given) {
        RenderSettings s = base;
        if (width != null && !given.contains(Setting.WIDTH)) {
            s = s.withSize(width, s.output().height());
        }
        if (height != null && !given.contains(Setting.HEIGHT)) {
            s = s.withSize(s.output().width(), height);
        }
        if (aspectRatio != null && given.contains(Setting.WIDTH) != given.contains(Setting.HEIGHT)) {
            s = given.contains(Setting.WIDTH) ? s.withSize(s.output().width(), filmSide(s.output().width() / aspectRatio))
                    : s.withSize(filmSide(s.output().height() * aspectRatio), s.output().height());
        }
        if (samplesPerPixel != null && !given.contains(Setting.SAMPLES_PER_PIXEL)) {
            s = s.withSamplesPerPixel(samplesPerPixel);
        }
        if (maxDepth != null && !given.contains(Setting.MAX_DEPTH)) {
            s = s.withMaxDepth(maxDepth);
        }
        if (seed != null && !given.contains(Setting.SEED)) {
            s = s.withSeed(seed);
        }
        if (noiseThreshold != null && !given.contains(Setting.NOISE_THRESHOLD)) {
            s = s.withNoiseThreshold(noiseThreshold);
        }
        if (integrator != null && !given.contains(Setting.INTEGRATOR)) {
            s = s.withIntegrator(integrator);
        }
        if (lightSamples != null && !given.contains(Setting.LIGHT_SAMPLES)) {
            s = s.withLightSamples(lightSamples);
        }
        if (hemisphere != null && !given.contains(Setting.HEMISPHERE)) {
            s = s.withHemisphere(hemisphere);
        }
        PhotonParameters p = s.transport().photons();
        if (photons != null && !given.contains(Setting.PHOTONS)) {
            p = new PhotonParameters(photons, p.initialRadius());
        }
        if (photonRadius != null && !given.contains(Setting.PHOTON_RADIUS)) {
            p = new PhotonParameters(p.photonsPerIteration(), photonRadius);
        }
        if (aovs != null && !given.contains(Setting.AOVS)) {
            s = s.withAovs(aovs.isEmpty() ? EnumSet.noneOf(Aov.class) : EnumSet.copyOf(aovs));
        }
        return s.withPhotons(p);
    }

    /** A film side of about {@code pixels}, within the limits of {@link RenderSettings}. */
    public static int filmSide(double pixels) {
        return (int) Math.max(1, Math.min(RenderSettings.MAX_SIZE, Math.round(pixels)));
    }

    /**
     * The {@code integrator.noiseThreshold} key of an integrator object the reader has checked
     * ({@code null}: no integrator): 0 (none) or a number in (0, 1]; null where the key is absent.
     */
    static Double readNoiseThreshold(JsonNode integrator, JsonValues v) throws SceneException {
        JsonNode node = integrator == null ? null : integrator.object().get("noiseThreshold");
        if (node == null) {
            return null;
        }
        double t = v.number(node, "integrator.noiseThreshold");
        if (!(t >= 0 && t <= 1)) {
            throw v.error(node, "'integrator.noiseThreshold' must be 0 (none) or in (0, 1] (0.01 = 1 %), got " + JsonValues.format(t));
        }
        return t;
    }

    /**
     * The {@code film.aovs} key of a film object the reader has checked ({@code null}: no film):
     * an array of "albedo", "normal", "depth", each at most once; null where the key is absent.
     */
    static Set<Aov> readAovs(JsonNode film, JsonValues v) throws SceneException {
        JsonNode node = film == null ? null : film.object().get("aovs");
        if (node == null) {
            return null;
        }
        Set<Aov> aovs = EnumSet.noneOf(Aov.class);
        List<JsonNode> list = v.array(node, "film.aovs");
        for (JsonNode item : list) {
            String id = v.string(item, "film.aovs[]");
            try {
                if (!aovs.add(Aov.of(id))) {
                    throw v.error(item, "'film.aovs' names '" + id + "' twice");
                }
            } catch (IllegalArgumentException e) {
                throw v.error(item, "'film.aovs': " + e.getMessage());
            }
        }
        return aovs;
    }
}
