package dev.strahl.render;

import dev.strahl.integrator.DirectLighting;
import dev.strahl.integrator.Integrator;
import dev.strahl.integrator.PathTracer;
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
        return switch (s.transport().integrator()) {
            case PATH -> new PathTracer(world, s.transport().maxDepth(), uniform, s.transport().cullBackFaces(), path);
            case DIRECT -> new DirectLighting(world, uniform, s.transport().cullBackFaces(), s.transport().lightSamples(), s.transport().shadows());
            case WHITTED -> new Whitted(world, s.transport().maxDepth(), s.transport().cullBackFaces(), s.transport().lightSamples(), s.transport().shadows());
            case PHOTON -> new PhotonMapper(world, s.transport().maxDepth(), uniform, s.transport().cullBackFaces(), s.transport().photons().photonsPerIteration(),
                    s.transport().photons().initialRadius(), s.transport().shadows());
        };
    }
}
