package dev.strahl.render;

import dev.strahl.camera.CameraRays;
import dev.strahl.film.Film;
import dev.strahl.integrator.FeatureTracer;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.PathWavefront;
import dev.strahl.scene.Scene;
import dev.strahl.units.UnitRenderer;
import dev.strahl.units.UnitService;
import dev.strahl.units.WorkUnit;
import dev.strahl.world.World;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.Supplier;

/**
 * The render package's side of a cluster member: makes the renderer of a job's work units from
 * the scene the member loaded and the settings the coordinator sent. A unit is rendered with the
 * very sample loop of the local passes ({@link SampleLoop#sample}), going on from the state of
 * its tile, so its sums are those of a local render.
 */
final class UnitRenderers implements UnitService {
    private static final String SAMPLER = "sampler";

    @Override
    public UnitRenderer open(Scene scene, String settingsText, byte[] digest, int threads) {
        Decoded d = decode(settingsText);
        if (!Arrays.equals(Checkpoint.of(scene, d.settings).sceneDigestBytes(), digest)) {
            throw new IllegalArgumentException("the scene loaded here differs from the coordinator's"
                    + " (a file it references may be missing from what was shipped, or be named by an absolute path)");
        }
        Integrator integrator = Integrators.create(World.of(scene), d.settings);
        if (integrator.preparesEachSample()) {
            throw new IllegalArgumentException("the " + d.settings.transport().integrator().id() + " integrator cannot render on a cluster");
        }
        var rays = CameraRays.of(scene.camera(), d.settings.output().width(), d.settings.output().height());
        World world = World.of(scene);
        Supplier<FeatureTracer> features = d.settings.output().keepsFeatures() ? () -> new FeatureTracer(world, d.settings.transport().cullBackFaces()) : null;
        return new Renderer(integrator, features, rays, d.settings.sampling().seed(), d.stratified);
    }

    /** The settings and the sampler choice, as a coordinator sends them. */
    record Decoded(RenderSettings settings, boolean stratified) {
    }

    /** Every setting by its name (the members render with exactly the coordinator's), and the sampler. */
    static String encode(RenderSettings s, boolean stratified) {
        Map<String, Object> entries = new LinkedHashMap<>(SettingsCodec.entries(s));
        entries.put(SAMPLER, stratified ? "stratified" : "independent");
        return SettingsCodec.text(entries);
    }

    /** What {@link #encode} wrote; a setting missing, unknown or of a bad value is refused naming it. */
    static Decoded decode(String text) {
        Map<String, String> values = new LinkedHashMap<>(SettingsCodec.parse(text));
        String sampler = values.remove(SAMPLER);
        if (!"stratified".equals(sampler) && !"independent".equals(sampler)) {
            throw new IllegalArgumentException("settings without a sampler: '" + text + "'");
        }
        return new Decoded(SettingsCodec.settings(values), sampler.equals("stratified"));
    }

    /** Renders units on any thread; each thread takes a worker (integrator scratch and sampler) from a pool. */
    private static final class Renderer implements UnitRenderer {
        private final Integrator integrator;
        private final Supplier<FeatureTracer> features;
        private final CameraRays rays;
        private final long seed;
        private final boolean stratified;
        private final ConcurrentLinkedQueue<SampleLoop.WorkerState> idle = new ConcurrentLinkedQueue<>();

        Renderer(Integrator integrator, Supplier<FeatureTracer> features, CameraRays rays, long seed, boolean stratified) {
            this.integrator = integrator;
            this.features = features;
            this.rays = rays;
            this.seed = seed;
            this.stratified = stratified;
        }

        @Override
        public void render(WorkUnit unit) {
            SampleLoop.WorkerState w = idle.poll();
            if (w == null) {
                PathWavefront wavefront = WavefrontLoop.of(integrator, WavefrontLoop.batch(), stratified, seed);
                w = new SampleLoop.WorkerState(0, wavefront != null ? wavefront.worker() : integrator.newWorker(),
                        SampleLoop.newSampler(stratified, seed), features != null ? features.get() : null, wavefront);
            }
            try {
                long raysBefore = w.integrator.rayCount();
                // the unit's state in a film of its own, so that samples reach it as they reach the image's film
                Film tile = new Film(unit.width(), unit.height(), features != null);
                int perPixel = unit.sumsPerPixel();
                if (perPixel != tile.stateSums()) {
                    throw new IllegalArgumentException("a unit of " + perPixel + " sums per pixel for a film of " + tile.stateSums());
                }
                int[] counts = unit.counts();
                double[] sums = unit.sums();
                double[] state = new double[perPixel];
                long invalid = 0;
                if (w.wavefront != null && rendersEveryPixel(unit)) {
                    forEachPixel(unit, (tx, ty, i) -> {
                        System.arraycopy(sums, perPixel * i, state, 0, perPixel);
                        tile.restorePixel(tx, ty, counts[i], state);
                    });
                    long[] invalidOnes = {0};
                    WavefrontLoop.renderRect(w, rays, seed, tile, 0, 0, unit.width(), unit.height(), unit.x0(), unit.y0(),
                            unit.firstSample(), unit.endSample(), invalidOnes);
                    invalid = invalidOnes[0];
                    forEachPixel(unit, (tx, ty, i) -> {
                        counts[i] = tile.pixelState(tx, ty, state);
                        System.arraycopy(state, 0, sums, perPixel * i, perPixel);
                    });
                } else {
                    for (int ty = 0; ty < unit.height(); ty++) {
                        for (int tx = 0; tx < unit.width(); tx++) {
                            int i = ty * unit.width() + tx;
                            System.arraycopy(sums, perPixel * i, state, 0, perPixel);
                            tile.restorePixel(tx, ty, counts[i], state);
                            if (!unit.renders(i)) {
                                continue;                              // converged: its state goes back as it came
                            }
                            int s0 = Math.max(unit.firstSample(), counts[i]);
                            invalid += SampleLoop.samplePixel(w, rays, seed, tile, tile.pixelIndex(tx, ty), unit.x0() + tx, unit.y0() + ty,
                                    s0, unit.endSample());
                            counts[i] = tile.pixelState(tx, ty, state);
                            System.arraycopy(state, 0, sums, perPixel * i, perPixel);
                        }
                    }
                }
                unit.recordFigures((int) invalid, w.integrator.rayCount() - raysBefore);
            } finally {
                idle.add(w);
            }
        }
    }

    /** Whether the unit renders all its pixels (adaptive sampling leaves converged ones out: those units go one sample at a time). */
    private static boolean rendersEveryPixel(WorkUnit unit) {
        for (int i = 0; i < unit.width() * unit.height(); i++) {
            if (!unit.renders(i)) {
                return false;
            }
        }
        return true;
    }

    private interface PixelVisitor {
        void visit(int tx, int ty, int index);
    }

    /** Each pixel of the unit's tile in row order, with its index in the unit's arrays. */
    private static void forEachPixel(WorkUnit unit, PixelVisitor visitor) {
        for (int ty = 0; ty < unit.height(); ty++) {
            for (int tx = 0; tx < unit.width(); tx++) {
                visitor.visit(tx, ty, ty * unit.width() + tx);
            }
        }
    }
}