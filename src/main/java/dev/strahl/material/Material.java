package dev.strahl.material;

import dev.strahl.math.Rgb;
import java.util.Objects;

/**
 * What a surface is made of: its scattering function and the radiance it emits (black for
 * non-emitters). Emission is one-sided, into the hemisphere of the geometric normal.
 *
 * @param name     for messages and scene files
 * @param bsdf     the scattering function
 * @param emission emitted radiance Le, linear RGB
 */
public record Material(String name, Bsdf bsdf, Rgb emission) {

    public Material {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(bsdf, "bsdf");
        Objects.requireNonNull(emission, "emission");
        if (emission.r() < 0 || emission.g() < 0 || emission.b() < 0) {
            throw new IllegalArgumentException("emission must not be negative, got " + emission + " for material '" + name + "'");
        }
    }

    /** A Lambertian diffuse material. */
    public static Material diffuse(String name, Rgb albedo) {
        return new Material(name, new Lambert(albedo), Rgb.BLACK);
    }

    /** A diffuse area light: reflects with {@code albedo} and emits {@code radiance}. */
    public static Material emissive(String name, Rgb albedo, Rgb radiance) {
        return new Material(name, new Lambert(albedo), radiance);
    }

    public boolean isEmissive() {
        return !emission.isBlack();
    }
}
