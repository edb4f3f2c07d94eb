package dev.strahl.scene;

import dev.strahl.texture.TextureLookup;
import dev.strahl.image.Rgb;
import dev.strahl.texture.Channel;
import java.util.Objects;

/**
 * The setters of {@link Material.PrincipledBuilder} (a package-private base, as the JDK's
 * AbstractStringBuilder is StringBuilder's), kept apart from {@link Material}'s factories: the
 * builder's state with glTF's defaults, and one method per parameter, each returning the builder.
 */
abstract class PrincipledParameters {
    final String name;
    TextureLookup baseColor = TextureLookup.of(Rgb.WHITE);
    TextureLookup metallic = TextureLookup.of(1);
    TextureLookup roughness = TextureLookup.of(1);
    TextureLookup specular = TextureLookup.of(1);
    TextureLookup specularColor = TextureLookup.of(Rgb.WHITE);
    TextureLookup transmission = TextureLookup.of(0);
    double ior = 1.5;
    /** Le for constant emission; the strength (grey) with {@link #emissionTexture}. */
    Rgb emission = Rgb.BLACK;
    TextureLookup emissionTexture;

    PrincipledParameters(String name) {
        this.name = Objects.requireNonNull(name, "name");
    }

    private Material.PrincipledBuilder self() {
        return (Material.PrincipledBuilder) this;
    }

    /**
     * The base colour.
     *
     * @param colour linear RGB, each channel in [0, 1]
     * @return this builder
     */
    public Material.PrincipledBuilder baseColor(Rgb colour) {
        baseColor = TextureLookup.of(Surface.unit(colour, "baseColor", name));
        return self();
    }

    /**
     * The base colour as a texture.
     *
     * @param texture a colour texture
     * @return this builder
     */
    public Material.PrincipledBuilder baseColor(Texture texture) {
        baseColor = texture.colour();
        return self();
    }

    /**
     * Metallic: 0 a dielectric, 1 a metal.
     *
     * @param value in [0, 1]
     * @return this builder
     */
    public Material.PrincipledBuilder metallic(double value) {
        metallic = TextureLookup.of(Surface.unit(value, "metallic", name));
        return self();
    }

    /**
     * Metallic as a texture (its luminance).
     *
     * @param texture a linear texture
     * @return this builder
     */
    public Material.PrincipledBuilder metallic(Texture texture) {
        metallic = texture.scalar(Channel.LUMINANCE);
        return self();
    }

    /**
     * Perceptual roughness; GGX α = roughness².
     *
     * @param value in [0, 1]
     * @return this builder
     */
    public Material.PrincipledBuilder roughness(double value) {
        roughness = TextureLookup.of(Surface.unit(value, "roughness", name));
        return self();
    }

    /**
     * Roughness as a texture (its luminance).
     *
     * @param texture a linear texture
     * @return this builder
     */
    public Material.PrincipledBuilder roughness(Texture texture) {
        roughness = texture.scalar(Channel.LUMINANCE);
        return self();
    }

    /**
     * glTF's metallicRoughness texture: roughness from its G channel, metallic from its B channel.
     *
     * @param texture a linear texture
     * @return this builder
     */
    public Material.PrincipledBuilder metallicRoughness(Texture texture) {
        roughness = texture.scalar(Channel.G);
        metallic = texture.scalar(Channel.B);
        return self();
    }

    /**
     * KHR_materials_specular's specular factor: the strength of the dielectric's specular layer (0: a pure Lambertian base).
     *
     * @param value in [0, 1]
     * @return this builder
     */
    public Material.PrincipledBuilder specular(double value) {
        specular = TextureLookup.of(Surface.unit(value, "specular", name));
        return self();
    }

    /**
     * The specular factor as a texture (its luminance).
     *
     * @param texture a linear texture
     * @return this builder
     */
    public Material.PrincipledBuilder specular(Texture texture) {
        specular = texture.scalar(Channel.LUMINANCE);
        return self();
    }

    /**
     * KHR_materials_specular's specular colour, which tints the dielectric's f0.
     *
     * @param colour linear RGB, each channel ≥ 0
     * @return this builder
     */
    public Material.PrincipledBuilder specularColor(Rgb colour) {
        specularColor = TextureLookup.of(Surface.nonNegative(colour, "specularColor", name));
        return self();
    }

    /**
     * The specular colour as a texture.
     *
     * @param texture a colour texture
     * @return this builder
     */
    public Material.PrincipledBuilder specularColor(Texture texture) {
        specularColor = texture.colour();
        return self();
    }

    /**
     * KHR_materials_transmission's factor: the part of the dielectric base that is transmitted (thin-walled).
     *
     * @param value in [0, 1]
     * @return this builder
     */
    public Material.PrincipledBuilder transmission(double value) {
        transmission = TextureLookup.of(Surface.unit(value, "transmission", name));
        return self();
    }

    /**
     * The transmission factor as a texture (its luminance).
     *
     * @param texture a linear texture
     * @return this builder
     */
    public Material.PrincipledBuilder transmission(Texture texture) {
        transmission = texture.scalar(Channel.LUMINANCE);
        return self();
    }

    /**
     * The index of refraction, which sets the dielectric's f0 = ((ior − 1)/(ior + 1))².
     *
     * @param value positive
     * @return this builder
     */
    public Material.PrincipledBuilder ior(double value) {
        if (!(value > 0) || !Double.isFinite(value)) {
            throw new IllegalArgumentException("ior must be positive, got " + value + " for material '" + name + "'");
        }
        ior = value;
        return self();
    }

    /**
     * Emitted radiance: colour × strength (glTF's emissiveFactor and KHR_materials_emissive_strength).
     *
     * @param colour   linear RGB, not negative
     * @param strength a factor ≥ 0
     * @return this builder
     */
    public Material.PrincipledBuilder emission(Rgb colour, double strength) {
        emission = colour.scale(Surface.nonNegative(strength, "emission strength", name));
        emissionTexture = null;
        return self();
    }

    /**
     * Textured emission: Le(u, v) = colour(u, v) × strength (glTF's emissiveTexture with
     * KHR_materials_emissive_strength; the texture is sRGB-decoded unless {@link Texture#linear()}).
     *
     * @param colour   a colour texture
     * @param strength a factor ≥ 0
     * @return this builder
     */
    public Material.PrincipledBuilder emission(Texture colour, double strength) {
        emission = Rgb.gray(Surface.nonNegative(strength, "emission strength", name));
        emissionTexture = colour.isConstant() ? null : colour.colour();
        if (colour.isConstant()) {
            emission = colour.constantColour().scale(strength);
        }
        return self();
    }
}
