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

    /**
     * Checks that nothing is null and the emission is not negative.
     *
     * @param name     for messages and scene files
     * @param bsdf     the scattering function
     * @param emission emitted radiance Le, linear RGB
     */
    public Material {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(bsdf, "bsdf");
        Objects.requireNonNull(emission, "emission");
        if (emission.r() < 0 || emission.g() < 0 || emission.b() < 0) {
            throw new IllegalArgumentException("emission must not be negative, got " + emission + " for material '" + name + "'");
        }
    }

    /**
     * A Lambertian diffuse material.
     *
     * @param name   for messages
     * @param albedo reflectance, each channel in [0, 1]
     * @return the material
     */
    public static Material diffuse(String name, Rgb albedo) {
        return new Material(name, new Lambert(albedo), Rgb.BLACK);
    }

    /**
     * A diffuse area light: reflects with {@code albedo} and emits {@code radiance} (one-sided).
     *
     * @param name     for messages
     * @param albedo   reflectance, each channel in [0, 1]
     * @param radiance emitted radiance, not negative
     * @return the material
     */
    public static Material emissive(String name, Rgb albedo, Rgb radiance) {
        return new Material(name, new Lambert(albedo), radiance);
    }

    /**
     * A perfect mirror (no Fresnel term).
     *
     * @param name        for messages
     * @param reflectance each channel in [0, 1]
     * @return the material
     */
    public static Material mirror(String name, Rgb reflectance) {
        return new Material(name, new Mirror(reflectance), Rgb.BLACK);
    }

    /**
     * Smooth glass: exact dielectric Fresnel reflection and Snell refraction, no absorption.
     *
     * @param name for messages
     * @param ior  index of refraction inside (the side the geometric normal points away from); 1 outside
     * @return the material
     */
    public static Material dielectric(String name, double ior) {
        return new Material(name, new Dielectric(ior), Rgb.BLACK);
    }

    /**
     * A glossy surface, diffuse·Lambert + specular·Beckmann microfacet mirror, as MTL's
     * {@code illum 2} with Ks &gt; 0 (see {@link Glossy#fromPhongExponent}).
     *
     * @param name     for messages
     * @param diffuse  the Lambertian part Kd, each channel in [0, 1]
     * @param specular the microfacet part Ks, each channel in [0, 1]
     * @param exponent Phong exponent Ns &gt;= 0: larger is sharper
     * @return the material
     */
    public static Material glossy(String name, Rgb diffuse, Rgb specular, double exponent) {
        return new Material(name, Glossy.fromPhongExponent(diffuse, specular, exponent), Rgb.BLACK);
    }

    /**
     * The same surface emitting {@code radiance} as well (a one-sided area light).
     *
     * @param radiance emitted radiance, not negative
     * @return a new material
     */
    public Material withEmission(Rgb radiance) {
        return new Material(name, bsdf, radiance);
    }

    /**
     * Whether the material emits light.
     *
     * @return true if its emission is not black
     */
    public boolean isEmissive() {
        return !emission.isBlack();
    }
}
