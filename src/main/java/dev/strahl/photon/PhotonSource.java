package dev.strahl.photon;

import dev.strahl.color.MutableRgb;
import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Ray;
import dev.strahl.geometry.SurfacePoint;
import dev.strahl.light.Environment;
import dev.strahl.light.LightSampler;
import dev.strahl.math.Frame;
import dev.strahl.sampling.Sample2D;
import dev.strahl.sampling.Sampler;
import dev.strahl.sampling.Warp;
import dev.strahl.world.World;
import org.joml.Vector3d;

/**
 * Where photons start: on the area lights, in proportion to their power, from the punctual
 * lights and from the scene's environment, if it has one. Each photon carries the flux an estimator of the total
 * emitted power gives it: emitting it with density p (over everything that is sampled), it
 * carries Le·cosθ / p, so that the mean over photons is the total flux.
 *
 * <ul>
 *   <li><b>Area lights.</b> {@link LightSampler#samplePoint} picks a light and a point by power
 *       (area density p_A = mean(Le) / Σ area·mean(Le)); the direction is cosine-weighted in the
 *       hemisphere of the light's geometric normal (pdf cosθ/π; the lights are one-sided). Flux
 *       Le·cosθ / (p_A · cosθ/π) = π·Le / p_A; the mean over photons is Σ π·Le·area, the power of
 *       Lambertian emitters.</li>
 *   <li><b>Environment</b> of constant radiance L (pbrt-v4 §12.5, {@code UniformInfiniteLight::
 *       SampleLe}): a travel direction d uniform on the sphere (pdf 1/4π) and a start point
 *       uniform on the disk of radius R perpendicular to d that touches the scene's bounding
 *       sphere (centre c, radius R) on the side d comes from (pdf 1/πR²). Flux L·4π·πR²:
 *       the power that crosses the bounding sphere's cross-section from all directions.</li>
 *   <li><b>Environment map</b> (pbrt-v4 {@code ImageInfiniteLight::SampleLe}): the direction
 *       towards the environment wi is sampled as for next-event estimation, {@link
 *       Environment#sample} (density p(wi)), the photon travels along −wi from a point of the same
 *       disk; flux L(wi)·πR² / p(wi).</li>
 *   <li><b>Punctual lights</b>: one chosen by power ({@link LightSampler#selectPunctual}), its
 *       photon from {@code PunctualLight.emit} (points: uniform directions; spots: uniform in the
 *       outer cone, flux weighted by the falloff; directional: from the same disk as the
 *       environment's), the flux divided by the light's probability.</li>
 * </ul>
 * When a scene has several kinds, a photon comes from the area lights, the punctual lights or the
 * environment with probability proportional to their mean power (P_area, P_punctual, P_env), and
 * its flux is divided by that probability. One per thread (scratch).
 */
final class PhotonSource {
    private final LightSampler lights;
    private final Environment environment;
    private final MutableRgb radiance = new MutableRgb();
    private final double[] uv = new double[2];
    private final double lightProbability;       // 1 without environment, 0 without lights
    private final double punctualProbability;    // 0 without punctual lights
    private final Vector3d center = new Vector3d();
    private final double radius;
    private final SurfacePoint point = new SurfacePoint();
    private final Frame frame = new Frame();
    private final Vector3d local = new Vector3d();
    private final Vector3d dir = new Vector3d();
    private final Sample2D u = new Sample2D();

    PhotonSource(World world) {
        this.lights = world.lights();
        this.environment = world.environment();
        Aabb box = world.bounds();
        if (box.isEmpty()) {
            this.radius = 1;
        } else {
            center.set(0.5 * (box.minX + box.maxX), 0.5 * (box.minY + box.maxY), 0.5 * (box.minZ + box.maxZ));
            this.radius = LightSampler.boundingRadius(box);
        }
        double lightPower = lights.lightCount() == 0 ? 0 : Math.PI * lights.totalPower();
        double envPower = environment.power() * Math.PI * radius * radius;
        double punctualPower = lights.punctualPower();
        double total = lightPower + envPower + punctualPower;
        this.lightProbability = total > 0 ? lightPower / total : 0;
        this.punctualProbability = total > 0 ? punctualPower / total : 0;
    }

    /** Whether anything emits: without lights and environment there are no photons. */
    boolean isEmpty() {
        return lights.lightCount() == 0 && lights.punctualCount() == 0 && environment.isBlack();
    }

    /** Radius of the bounding sphere from which environment photons start. */
    double boundingRadius() {
        return radius;
    }

    /**
     * Emits one photon with random numbers from {@code sampler}: its start point and direction into
     * {@code ray} (the origin moved off the light), its flux into {@code flux}. Returns true for a
     * photon of the environment (which no light sampling accounts for, so it is stored from its
     * first hit on), false for one of an area light.
     */
    boolean emit(Sampler sampler, Ray ray, MutableRgb flux) {
        double uChoice = sampler.get1D();
        if (uChoice < lightProbability) {
            double uLight = sampler.get1D();
            sampler.get2D(u);
            double pA = lights.samplePoint(uLight, u.u1, u.u2, point);
            sampler.get2D(u);
            Warp.cosineHemisphere(u.u1, u.u2, local);
            frame.set(point.ng).toWorld(local, dir);
            SurfacePoint.offset(point.p, point.ng, dir, ray.o);
            ray.d.set(dir);
            ray.tMax = Double.POSITIVE_INFINITY;
            lights.emission(point.material).eval(point.uv, flux).mul(Math.PI / (pA * lightProbability));
            return false;
        }
        if (uChoice - lightProbability < punctualProbability) {
            int i = lights.selectPunctual(sampler.get1D());
            sampler.get2D(u);
            double u1 = u.u1, u2 = u.u2;
            sampler.get2D(u);
            lights.punctualLight(i).emit(u1, u2, u.u1, u.u2, center, radius, frame, local, ray, flux);
            flux.mul(1 / (lights.punctualProbability(i) * punctualProbability));
            return false;
        }
        sampler.get2D(u);
        double scale = Math.PI * radius * radius / (1 - lightProbability - punctualProbability);
        if (environment.isConstant()) {
            Warp.uniformSphere(u.u1, u.u2, dir);
            radiance.set(environment.constantRadiance()).mul(4 * Math.PI);
        } else {
            double pdf = environment.sample(u.u1, u.u2, uv, dir, radiance);
            dir.negate();
            radiance.mul(pdf > 0 ? 1 / pdf : 0);
        }
        sampler.get2D(u);
        Warp.concentricDisk(u.u1, u.u2, local);
        frame.set(dir).toWorld(local.mul(radius), ray.o);
        ray.o.add(center).fma(-radius, dir);
        ray.d.set(dir);
        ray.tMax = Double.POSITIVE_INFINITY;
        flux.set(radiance).mul(scale);
        return true;
    }
}
