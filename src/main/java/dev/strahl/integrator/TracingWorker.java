package dev.strahl.integrator;

import dev.strahl.image.Rgb;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.world.World;

/**
 * What the workers of every integrator start from: a {@link Tracer} of their own (closest hits
 * with shading set up, next-event estimation, the ray count), the scene's lights and its
 * environment. One per thread, like the worker it is part of.
 */
public abstract class TracingWorker implements Integrator.Worker {
    protected final Tracer tracer;
    protected final LightSampler lights;
    protected final Rgb environment;

    protected TracingWorker(World world, Bsdf[] bsdfs, boolean cullBackFaces) {
        this.tracer = new Tracer(world, bsdfs, cullBackFaces);
        this.lights = world.lights();
        this.environment = world.environment();
    }

    @Override
    public final long rayCount() {
        return tracer.rayCount();
    }
}
