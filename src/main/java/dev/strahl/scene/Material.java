package dev.strahl.scene;

import dev.strahl.material.Bsdf;
import dev.strahl.material.Dielectric;
import dev.strahl.material.Glossy;
import dev.strahl.material.Lambert;
import dev.strahl.material.Mirror;
import dev.strahl.image.Rgb;
import java.util.Objects;

/**
 * What a surface is made of: how it scatters light and the radiance it emits (black for
 * non-emitters). Emission is one-sided, into the hemisphere of the geometric normal; every
 * material but glass scatters alike on both sides. Immutable; made by the factories below.
 */
public final class Material {
    private final String name;
    private final Bsdf bsdf;
    private final Rgb emission;

    private Material(String name, Bsdf bsdf, Rgb emission) {
        this.name = Objects.requireNonNull(name, "name");
        this.bsdf = Objects.requireNonNull(bsdf, "bsdf");
        this.emission = Objects.requireNonNull(emission, "emission");
        if (emission.r() < 0 || emission.g() < 0 || emission.b() < 0) {
            throw new IllegalArgumentException("emission must not be negative, got " + emission + " for material '" + name + "'");
        }
    }

    /** A material with a given scattering function (for strahl's own packages and tests). */
    static Material of(String name, Bsdf bsdf, Rgb emission) {
        return new Material(name, bsdf, emission);
    }

    /**
     * The name given to the material, for messages.
     *
     * @return the name
     */
    public String name() {
        return name;
    }

    /**
     * The emitted radiance Le, linear RGB.
     *
     * @return black for a material that does not emit
     */
    public Rgb emission() {
        return emission;
    }

    Bsdf bsdf() {
        return bsdf;
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
     * {@code illum 2} with Ks &gt; 0: roughness α = sqrt(2 / (Ns + 2)), Fresnel ≡ 1; where
     * diffuse + specular exceeds 1 in a channel, both are scaled down to conserve energy.
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

    @Override
    public boolean equals(Object o) {
        return o instanceof Material m && m.name.equals(name) && m.bsdf.equals(bsdf) && m.emission.equals(emission);
    }

    @Override
    public int hashCode() {
        return Objects.hash(name, bsdf, emission);
    }

    /** The name, the scattering function with all its parameters and the emission. */
    @Override
    public String toString() {
        return "Material[name=" + name + ", bsdf=" + bsdf + ", emission=" + emission + "]";
    }
}
