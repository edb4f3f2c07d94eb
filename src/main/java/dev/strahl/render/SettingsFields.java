package dev.strahl.render;

import java.time.Duration;
import java.util.Set;
import java.util.function.Consumer;

/**
 * Every value of a {@link RenderSettings} as a mutable field, for its {@code with...} methods: each
 * sets a field or two, {@link #settings()} rebuilds the four parts (which check the values). The
 * values are listed here once, part by part.
 */
final class SettingsFields {
    int width, height;
    Set<Aov> aovs;
    int samplesPerPixel;
    long seed;
    double noiseThreshold;
    IntegratorKind integrator;
    int maxDepth, lightSamples;
    HemisphereSampling hemisphere;
    boolean cullBackFaces, shadows, lightTree;
    PhotonParameters photons;
    int threads, samplesPerPass;
    Duration timeLimit;
    boolean bruteForce, stripes;

    SettingsFields(RenderSettings s) {
        RenderSettings.Output o = s.output();
        width = o.width();
        height = o.height();
        aovs = o.aovs();
        samplesPerPixel = s.sampling().samplesPerPixel();
        seed = s.sampling().seed();
        noiseThreshold = s.sampling().noiseThreshold();
        RenderSettings.Transport t = s.transport();
        integrator = t.integrator();
        maxDepth = t.maxDepth();
        lightSamples = t.lightSamples();
        hemisphere = t.hemisphere();
        cullBackFaces = t.cullBackFaces();
        shadows = t.shadows();
        lightTree = t.lightTree();
        photons = t.photons();
        RenderSettings.Execution x = s.execution();
        threads = x.threads();
        samplesPerPass = x.samplesPerPass();
        timeLimit = x.timeLimit();
        bruteForce = x.bruteForce();
        stripes = x.stripes();
    }

    void size(int w, int h) {
        width = w;
        height = h;
    }

    /** These fields after {@code change}, as settings (each part checks its values). */
    RenderSettings apply(Consumer<SettingsFields> change) {
        change.accept(this);
        return settings();
    }

    RenderSettings settings() {
        return new RenderSettings(new RenderSettings.Output(width, height, aovs), new RenderSettings.Sampling(samplesPerPixel, seed, noiseThreshold),
                new RenderSettings.Transport(integrator, maxDepth, lightSamples, hemisphere, cullBackFaces, shadows, lightTree, photons),
                new RenderSettings.Execution(threads, samplesPerPass, timeLimit, bruteForce, stripes));
    }
}
