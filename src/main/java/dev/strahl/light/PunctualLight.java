package dev.strahl.light;

import dev.strahl.geometry.Aabb;
import dev.strahl.geometry.Ray;
import dev.strahl.image.Rgb;
import dev.strahl.math.Frame;
import dev.strahl.color.MutableRgb;
import dev.strahl.sampling.Warp;
import java.util.Objects;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A punctual (delta) light of glTF's {@code KHR_lights_punctual}: a point, a spot or a
 * directional light. It has no area and no solid angle, so no ray ever hits it: it is reached by
 * next-event estimation only (without MIS weight) and emits photons. Immutable.
 *
 * <ul>
 *   <li><b>Point</b> at p with radiant intensity I (W/sr per channel): the irradiance on a
 *       surface at distance d whose normal makes angle θ with the way to the light is
 *       E = I cosθ / d².</li>
 *   <li><b>Spot</b>: a point light whose intensity is I·a(cd), cd the cosine between the spot's
 *       axis and the direction from the light to the lit point, with glTF's smooth falloff
 *       a = clamp((cd − cos θouter) / (cos θinner − cos θouter), 0, 1)² (the extension's
 *       implementation note); a hard edge where the two angles are equal.</li>
 *   <li><b>Directional</b>: parallel light travelling along a direction, irradiance E (W/m² per
 *       channel) on a surface facing it.</li>
 * </ul>
 * Power (flux, the mean over channels), used to choose among lights: a point light 4π·I, a spot
 * 2π·I·((1 − cos θinner) + (cos θinner − cos θouter)/3) (the falloff integrated exactly over the
 * cone), a directional light π R²·E for the scene's bounding sphere of radius R (what crosses the
 * scene; pbrt-v4's {@code DistantLight::Phi}).
 */
public final class PunctualLight {
    /** The three kinds of glTF punctual light. */
    public enum Type { POINT, SPOT, DIRECTIONAL }

    private final Type type;
    private final Vector3d position;          // point and spot; unused for directional
    private final Vector3d direction;         // unit: the spot's axis, the way directional light travels
    private final Rgb intensity;              // I (W/sr), or E (W/m²) for directional
    private final double cosInner;
    private final double cosOuter;

    private PunctualLight(Type type, Vector3dc position, Vector3dc direction, Rgb intensity, double cosInner, double cosOuter) {
        this.type = type;
        this.position = new Vector3d(position);
        this.direction = new Vector3d(direction);
        this.intensity = checkColour(intensity);
        this.cosInner = cosInner;
        this.cosOuter = cosOuter;
    }

    /** A point light of radiant intensity {@code intensity} (W/sr per channel) at {@code position}. */
    public static PunctualLight point(Vector3dc position, Rgb intensity) {
        return new PunctualLight(Type.POINT, checkPoint(position), new Vector3d(0, 0, -1), intensity, -1, -1);
    }

    /**
     * A spot light at {@code position} shining along {@code direction}, full intensity inside
     * {@code innerRadians} of its axis, none outside {@code outerRadians}.
     *
     * @throws IllegalArgumentException unless 0 ≤ inner ≤ outer ≤ π/2, outer &gt; 0
     */
    public static PunctualLight spot(Vector3dc position, Vector3dc direction, Rgb intensity, double innerRadians, double outerRadians) {
        if (!(innerRadians >= 0 && innerRadians <= outerRadians && Math.cos(outerRadians) < 1 && outerRadians <= Math.PI / 2)) {
            throw new IllegalArgumentException("spot cone angles need 0 <= inner <= outer <= 90 degrees and outer > 0, got inner "
                    + Math.toDegrees(innerRadians) + ", outer " + Math.toDegrees(outerRadians));
        }
        return new PunctualLight(Type.SPOT, checkPoint(position), unit(direction), intensity, Math.cos(innerRadians),
                Math.cos(outerRadians));
    }

    /** A directional light: light travelling along {@code direction}, irradiance {@code irradiance} on a surface facing it. */
    public static PunctualLight directional(Vector3dc direction, Rgb irradiance) {
        return new PunctualLight(Type.DIRECTIONAL, new Vector3d(), unit(direction), irradiance, -1, -1);
    }

    private static Vector3dc checkPoint(Vector3dc p) {
        Objects.requireNonNull(p, "position");
        if (!p.isFinite()) {
            throw new IllegalArgumentException("light position must be finite, got " + p);
        }
        return p;
    }

    private static Vector3d unit(Vector3dc d) {
        Objects.requireNonNull(d, "direction");
        double length = d.length();
        if (!(length > 0) || !Double.isFinite(length)) {
            throw new IllegalArgumentException("light direction must be a finite non-zero vector, got " + d);
        }
        return new Vector3d(d).div(length);
    }

    private static Rgb checkColour(Rgb c) {
        Objects.requireNonNull(c, "intensity");
        if (c.r() < 0 || c.g() < 0 || c.b() < 0) {
            throw new IllegalArgumentException("light intensity must not be negative, got " + c);
        }
        return c;
    }

    /** @return the kind of light */
    public Type type() {
        return type;
    }

    /**
     * glTF's spot falloff a(cd) for the cosine cd between the axis and the direction from the
     * light to the lit point; 1 for point and directional lights.
     */
    double falloff(double cd) {
        if (type != Type.SPOT) {
            return 1;
        }
        if (cosInner <= cosOuter) {                        // equal angles: a hard edge
            return cd >= cosOuter ? 1 : 0;
        }
        double t = Math.min(Math.max((cd - cosOuter) / (cosInner - cosOuter), 0), 1);
        return t * t;
    }

    /** Power (mean over channels, W) for choosing among lights; {@code sceneRadius} sizes a directional light's beam. */
    double power(double sceneRadius) {
        double mean = (intensity.r() + intensity.g() + intensity.b()) / 3;
        return switch (type) {
            case POINT -> 4 * Math.PI * mean;
            case SPOT -> 2 * Math.PI * mean * ((1 - cosInner) + (cosInner - cosOuter) / 3);
            case DIRECTIONAL -> Math.PI * sceneRadius * sceneRadius * mean;
        };
    }

    /**
     * The light tree's bounds of a point or spot light: its position, and its intensity mean(I)
     * (W/sr, as an area light's area × mean(Le)); a point light emits every way, a spot around
     * its axis within θinner at full intensity and up to θouter − θinner beyond.
     */
    LightBounds bounds() {
        Aabb box = new Aabb().include(position.x, position.y, position.z);
        double mean = (intensity.r() + intensity.g() + intensity.b()) / 3;
        if (type == Type.POINT) {
            return LightBounds.everyWay(box, mean);
        }
        double sinInner = Math.sqrt(Math.max(0, 1 - cosInner * cosInner)), sinOuter = Math.sqrt(Math.max(0, 1 - cosOuter * cosOuter));
        double cosSpread = cosOuter * cosInner + sinOuter * sinInner;           // cos(θouter − θinner)
        return LightBounds.facing(box, direction.x, direction.y, direction.z, cosInner, cosSpread, mean);
    }

    /**
     * The light arriving at {@code ref}: direction {@code out.wi} towards the light, its distance
     * (infinite for a directional light, {@code out.infinite}) and position {@code out.p}, and in
     * {@code out.radiance} the irradiance it gives a surface facing it, I·a/d² or E. Leaves the
     * pdf to the caller. Returns false where it gives nothing (outside a spot's cone, at the light).
     */
    boolean illuminate(Vector3dc ref, LightSample out) {
        out.delta = true;
        if (type == Type.DIRECTIONAL) {
            out.infinite = true;
            out.distance = Double.POSITIVE_INFINITY;
            out.wi.set(direction).negate();
            out.radiance.set(intensity.r(), intensity.g(), intensity.b());
            return true;
        }
        out.infinite = false;
        double dist2 = out.aim(ref, position.x, position.y, position.z);
        if (dist2 == 0) {
            return false;
        }
        double a = falloff(-out.wi.dot(direction));
        if (a <= 0) {
            return false;
        }
        out.p.set(position);
        out.ng.set(out.wi).negate();
        double scale = a / dist2;
        out.radiance.set(intensity.r() * scale, intensity.g() * scale, intensity.b() * scale);
        return true;
    }

    /**
     * Emits a photon from this light with the uniform numbers (u1, u2) for its direction and
     * (u3, u4) for a directional light's start point: into {@code ray} its start and direction,
     * into {@code flux} Φ = emitted / pdf (not yet divided by the light's selection probability).
     * Points: a uniform direction on the sphere, Φ = 4π·I. Spots: uniform in the outer cone,
     * Φ = 2π(1 − cos θouter)·I·a. Directional: a start point uniform on the disc of radius R
     * across the scene's bounding sphere (centre c) on the side the light comes from, Φ = πR²·E.
     *
     * @param frame scratch
     * @param local scratch
     */
    public void emit(double u1, double u2, double u3, double u4, Vector3dc center, double radius, Frame frame, Vector3d local,
              Ray ray, MutableRgb flux) {
        ray.tMax = Double.POSITIVE_INFINITY;
        double scale;
        switch (type) {
            case POINT -> {
                Warp.uniformSphere(u1, u2, ray.d);
                ray.o.set(position);
                scale = 1 / Warp.uniformSpherePdf();
            }
            case SPOT -> {
                Warp.uniformCone(u1, u2, cosOuter, local);
                frame.set(direction).toWorld(local, ray.d);
                ray.o.set(position);
                scale = falloff(local.z) / Warp.uniformConePdf(local.z, cosOuter);
            }
            default -> {
                Warp.concentricDisk(u3, u4, local);
                frame.set(direction).toWorld(local.mul(radius), ray.o);
                ray.o.add(center).fma(-radius, direction);
                ray.d.set(direction);
                scale = Math.PI * radius * radius;
            }
        }
        flux.set(intensity.r() * scale, intensity.g() * scale, intensity.b() * scale);
    }

    /** Every parameter in full precision: for the checkpoint's scene digest. */
    @Override
    public String toString() {
        return type + " " + position.x + " " + position.y + " " + position.z + " " + direction.x + " " + direction.y + " "
                + direction.z + " " + intensity + " " + cosInner + " " + cosOuter;
    }
}
