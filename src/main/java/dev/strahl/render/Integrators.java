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
        World world = s.bruteForce() ? scene.bruteForce() : scene;
        boolean uniform = s.hemisphere() == HemisphereSampling.UNIFORM;
        // the teaching option without shadows: next-event estimation takes every light sample as visible
        PathTracer.Strategy path = s.shadows() ? PathTracer.Strategy.MIS : PathTracer.Strategy.UNOCCLUDED;
        if (world.media().any()) {                 // participating media or invisible surfaces: docs/media.md
            return switch (s.integrator()) {
                case PATH -> new VolumePathTracer(world, s.maxDepth(), uniform, 1, s.shadows());
                case DIRECT -> new VolumePathTracer(world, 2, uniform, s.lightSamples(), s.shadows());
                default -> throw new IllegalArgumentException("the " + s.integrator().id() + " integrator does not render participating"
                        + " media or null surfaces; this scene has them: use path or direct");
            };
        }
        return switch (s.integrator()) {
            case PATH -> new PathTracer(world, s.maxDepth(), uniform, s.cullBackFaces(), path);
            case DIRECT -> new DirectLighting(world, uniform, s.cullBackFaces(), s.lightSamples(), s.shadows());
            case WHITTED -> new Whitted(world, s.maxDepth(), s.cullBackFaces(), s.lightSamples(), s.shadows());
            case PHOTON -> new PhotonMapper(world, s.maxDepth(), uniform, s.cullBackFaces(), s.photons().photonsPerIteration(),
                    s.photons().initialRadius(), s.shadows());
        };
    }
}
