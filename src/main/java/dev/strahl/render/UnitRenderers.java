package dev.strahl.render;

import dev.strahl.camera.CameraRays;
import dev.strahl.integrator.Integrator;
import dev.strahl.scene.Camera;
import dev.strahl.scene.Scene;
import dev.strahl.units.UnitRenderer;
import dev.strahl.units.UnitService;
import dev.strahl.units.WorkUnit;
import dev.strahl.world.World;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.time.Duration;
import java.util.Arrays;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;

/**
 * The render package's side of a cluster member: makes the renderer of a job's work units from
 * the scene the member loaded and the settings the coordinator sent. A unit is rendered with the
 * very sample loop of the local passes ({@link RenderWorkers#sample}), going on from the state of
 * its tile, so its sums are those of a local render.
 */
final class UnitRenderers implements UnitService {
    private static final int SETTINGS_FORMAT = 1;

    @Override
    public UnitRenderer open(Scene scene, byte[] settingsBytes, byte[] digest, int threads) {
        Decoded d = decode(settingsBytes);
        if (!Arrays.equals(Checkpoint.of(scene, d.settings).sceneDigestBytes(), digest)) {
            throw new IllegalArgumentException("the scene loaded here differs from the coordinator's"
                    + " (a file it references may be missing from what was shipped, or be named by an absolute path)");
        }
        Integrator integrator = Integrators.create(World.of(scene), d.settings);
        if (integrator.preparesEachSample()) {
            throw new IllegalArgumentException("the " + d.settings.integrator().id() + " integrator cannot render on a cluster");
        }
        Camera c = scene.camera();
        var rays = new CameraRays(c.lookFrom(), c.lookAt(), c.up(), c.fovDegrees(), c.aperture(), c.focusDistance(), d.settings.width(), d.settings.height());
        return new Renderer(integrator, rays, d.settings.seed(), d.stratified);
    }

    /** The settings and the sampler choice, as a coordinator sends them. */
    record Decoded(RenderSettings settings, boolean stratified) {
    }

    /** Every setting (the members render with exactly the coordinator's), and the sampler. */
    static byte[] encode(RenderSettings s, boolean stratified) {
        var bytes = new ByteArrayOutputStream();
        try (var out = new DataOutputStream(bytes)) {
            out.writeInt(SETTINGS_FORMAT);
            out.writeInt(s.width());
            out.writeInt(s.height());
            out.writeInt(s.samplesPerPixel());
            out.writeInt(s.maxDepth());
            out.writeLong(s.seed());
            out.writeInt(s.threads());
            out.writeUTF(s.hemisphere().name());
            out.writeBoolean(s.cullBackFaces());
            out.writeInt(s.samplesPerPass());
            out.writeUTF(s.integrator().name());
            out.writeInt(s.lightSamples());
            out.writeLong(s.timeLimit().toNanos());
            out.writeInt(s.photons().photonsPerIteration());
            out.writeDouble(s.photons().initialRadius());
            out.writeBoolean(s.bruteForce());
            out.writeBoolean(s.stripes());
            out.writeBoolean(stratified);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return bytes.toByteArray();
    }

    static Decoded decode(byte[] bytes) {
        try (var in = new DataInputStream(new ByteArrayInputStream(bytes))) {
            int format = in.readInt();
            if (format != SETTINGS_FORMAT) {
                throw new IllegalArgumentException("settings of format " + format + "; this strahl reads " + SETTINGS_FORMAT);
            }
            var settings = new RenderSettings(in.readInt(), in.readInt(), in.readInt(), in.readInt(), in.readLong(), in.readInt(),
                    HemisphereSampling.valueOf(in.readUTF()), in.readBoolean(), in.readInt(), IntegratorKind.valueOf(in.readUTF()),
                    in.readInt(), Duration.ofNanos(in.readLong()), new PhotonParameters(in.readInt(), in.readDouble()),
                    in.readBoolean(), in.readBoolean(), Set.of());   // a cluster renders no feature buffers (RenderJob refuses them)
            return new Decoded(settings, in.readBoolean());
        } catch (IOException e) {
            throw new IllegalArgumentException("unreadable settings: " + e.getMessage(), e);
        }
    }

    /** Renders units on any thread; each thread takes a worker (integrator scratch and sampler) from a pool. */
    private static final class Renderer implements UnitRenderer {
        private final Integrator integrator;
        private final CameraRays rays;
        private final long seed;
        private final boolean stratified;
        private final ConcurrentLinkedQueue<RenderWorkers.WorkerState> idle = new ConcurrentLinkedQueue<>();

        Renderer(Integrator integrator, CameraRays rays, long seed, boolean stratified) {
            this.integrator = integrator;
            this.rays = rays;
            this.seed = seed;
            this.stratified = stratified;
        }

        @Override
        public void render(WorkUnit unit) {
            RenderWorkers.WorkerState w = idle.poll();
            if (w == null) {
                w = new RenderWorkers.WorkerState(0, integrator.newWorker(), RenderWorkers.newSampler(stratified, seed), null);
            }
            try {
                long raysBefore = w.integrator.rayCount();
                int[] counts = unit.counts();
                double[] sums = unit.sums();
                int end = unit.endSample();
                int invalid = 0;
                for (int ty = 0; ty < unit.height(); ty++) {
                    for (int tx = 0; tx < unit.width(); tx++) {
                        int i = ty * unit.width() + tx;
                        int x = unit.x0() + tx;
                        int y = unit.y0() + ty;
                        int k = 3 * i;
                        // as RenderWorkers.renderTiles and Film.add: each sample added to the sums in index order
                        for (int s = Math.max(unit.firstSample(), counts[i]); s < end; s++) {
                            if (RenderWorkers.sample(w, rays, seed, x, y, s)) {
                                sums[k] += w.radiance.r;
                                sums[k + 1] += w.radiance.g;
                                sums[k + 2] += w.radiance.b;
                            } else {
                                sums[k] += 0;
                                sums[k + 1] += 0;
                                sums[k + 2] += 0;
                                invalid++;
                            }
                            counts[i]++;
                        }
                    }
                }
                unit.recordFigures(invalid, w.integrator.rayCount() - raysBefore);
            } finally {
                idle.add(w);
            }
        }
    }
}
