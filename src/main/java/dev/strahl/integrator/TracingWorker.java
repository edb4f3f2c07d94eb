package dev.strahl.integrator;

import dev.strahl.geometry.Ray;
import dev.strahl.light.Environment;
import dev.strahl.color.MutableRgb;
import dev.strahl.light.LightSampler;
import dev.strahl.material.Bsdf;
import dev.strahl.world.World;

/**
 * What the workers of every integrator start from: a {@link Tracer} of their own (closest hits
 * with shading set up, next-event estimation, the ray count), the scene's lights and its
 * environment (with a scratch colour to evaluate it in). One per thread, like the worker it is part of.
 */
public abstract class TracingWorker implements Integrator.Worker {
    protected final Tracer tracer;
    protected final LightSampler lights;
    protected final Environment environment;
    private final MutableRgb environmentRadiance = new MutableRgb();

    protected TracingWorker(World world, Bsdf[] bsdfs, boolean cullBackFaces) {
        this.tracer = new Tracer(world, bsdfs, cullBackFaces);
        this.lights = world.lights();
        this.environment = world.environment();
    }

    /** Adds beta · Le(ray.d) · w to {@code out}: the environment seen along a ray that left the scene. */
    protected final void addEnvironment(Ray ray, MutableRgb beta, double w, MutableRgb out) {
        if (!environment.isBlack()) {
            out.addProduct(beta, environment.eval(ray.d, environmentRadiance), w);
        }
    }

    @Override
    public final long rayCount() {
        return tracer.rayCount();
    }
}
