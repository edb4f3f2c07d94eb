package dev.strahl.render;

import dev.strahl.integrator.DirectLighting;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.PathTracer;
import dev.strahl.integrator.VolumePathTracer;
import dev.strahl.integrator.Whitted;
import dev.strahl.photon.PhotonMapper;
import dev.strahl.world.World;

/** Makes the integrator a render's settings choose, with all its parameters. */
final class Integrators {
    private Integrators() {}

    static Integrator create(World scene, RenderSettings s) {
        // the teaching option --accel none: the same world, every ray against every primitive
        World world = s.execution().bruteForce() ? scene.bruteForce() : scene;
        // the teaching option --light-selection power: lights chosen by power alone, as before the light tree
        world = s.transport().lightTree() ? world : world.lightsByPower();
        boolean uniform = s.transport().hemisphere() == HemisphereSampling.UNIFORM;
        // the teaching option without shadows: next-event estimation takes every light sample as visible
        PathTracer.Strategy path = s.transport().shadows() ? PathTracer.Strategy.MIS : PathTracer.Strategy.UNOCCLUDED;
        RenderSettings.Transport t = s.transport();
        if (world.media().any()) {                 // participating media or invisible surfaces: docs/media.md
            return switch (t.integrator()) {
                case PATH -> new VolumePathTracer(world, t.maxDepth(), uniform, 1, t.shadows());
                case DIRECT -> new VolumePathTracer(world, 2, uniform, t.lightSamples(), t.shadows());
                default -> throw new IllegalArgumentException("the " + t.integrator().id() + " integrator does not render participating"
                        + " media or null surfaces; this scene has them: use path or direct");
            };
        }
        return switch (t.integrator()) {
            case PATH -> new PathTracer(world, t.maxDepth(), uniform, t.cullBackFaces(), path);
            case DIRECT -> new DirectLighting(world, uniform, t.cullBackFaces(), t.lightSamples(), t.shadows());
            case WHITTED -> new Whitted(world, t.maxDepth(), t.cullBackFaces(), t.lightSamples(), t.shadows());
            case PHOTON -> new PhotonMapper(world, t.maxDepth(), uniform, t.cullBackFaces(), t.photons().photonsPerIteration(),
                    t.photons().initialRadius(), t.shadows());
        };
    }
}
