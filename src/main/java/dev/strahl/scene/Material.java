package dev.strahl.scene;

import dev.strahl.image.Rgb;
import dev.strahl.material.Bsdf;
import dev.strahl.material.Conductor;
import dev.strahl.material.Dielectric;
import dev.strahl.material.Glossy;
import dev.strahl.material.Lambert;
import dev.strahl.material.Mirror;
import dev.strahl.material.Principled;
import dev.strahl.material.RoughDielectric;
import dev.strahl.texture.Bitmap;
import dev.strahl.texture.Channel;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Set;
import java.util.TreeSet;

/**
 * What a surface is made of: how it scatters light and the radiance it emits (black for
 * non-emitters). Emission is one-sided, into the hemisphere of the geometric normal; every
 * material but glass scatters alike on both sides. Immutable; made by the factories below.
 */
public final class Material {
    private final String name;
    private final Bsdf bsdf;
    private final Rgb emission;
    /** The images its textures read (for memory figures). */
    private final List<Bitmap> images;

    private Material(String name, Bsdf bsdf, Rgb emission) {
        this(name, bsdf, emission, List.of());
    }

    private Material(String name, Bsdf bsdf, Rgb emission, List<Bitmap> images) {
        this.name = Objects.requireNonNull(name, "name");
        this.bsdf = Objects.requireNonNull(bsdf, "bsdf");
        this.emission = Objects.requireNonNull(emission, "emission");
        this.images = List.copyOf(images);
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

    /** The images the material's textures read, each once. */
    List<Bitmap> images() {
        return images;
    }

    /** The images behind some textures (their sRGB-decoded twins where colours are read). */
    private static List<Bitmap> images(dev.strahl.texture.Texture... textures) {
        List<Bitmap> out = new ArrayList<>();
        for (dev.strahl.texture.Texture t : textures) {
            Bitmap b = t.bitmap();
            if (b != null && out.stream().noneMatch(x -> x == b)) {
                out.add(b);
            }
        }
        return out;
    }

    /**
     * A Lambertian diffuse material whose albedo is a texture (a colour, sRGB-decoded unless the
     * texture is {@link Texture#linear()}), as Mitsuba's {@code diffuse} with a {@code bitmap}.
     *
     * @param name   for messages
     * @param albedo reflectance, each channel in [0, 1]
     * @return the material
     */
    public static Material diffuse(String name, Texture albedo) {
        dev.strahl.texture.Texture a = albedo.colour();
        return new Material(name, new Lambert(a, false), Rgb.BLACK, images(a));
    }

    /**
     * The names of the conductor presets of {@link #conductor(String, String, double)}.
     *
     * @return gold, silver, copper, aluminium, sorted
     */
    public static Set<String> conductorPresets() {
        return new TreeSet<>(Conductor.PRESETS.keySet());
    }

    /**
     * A metal: GGX microfacets with the exact conductor Fresnel term of the complex index η + ik per
     * RGB channel (Mitsuba's {@code roughconductor}, GGX, visible-normal sampling); α = 0 is a
     * polished mirror (Mitsuba's {@code conductor}).
     *
     * @param name  for messages
     * @param eta   real part of the index per channel, positive
     * @param k     absorption coefficient per channel, ≥ 0
     * @param alpha GGX roughness α ≥ 0
     * @return the material
     */
    public static Material conductor(String name, Rgb eta, Rgb k, double alpha) {
        return conductor(name, eta, k, Texture.constant(alpha));
    }

    /**
     * A metal with a roughness texture (its luminance, linear); see {@link #conductor(String, Rgb, Rgb, double)}.
     *
     * @param name  for messages
     * @param eta   real part of the index per channel, positive
     * @param k     absorption coefficient per channel, ≥ 0
     * @param alpha GGX roughness α ≥ 0
     * @return the material
     */
    public static Material conductor(String name, Rgb eta, Rgb k, Texture alpha) {
        dev.strahl.texture.Texture a = alpha.scalar(Channel.LUMINANCE);
        return new Material(name, Conductor.of(eta, k, a), Rgb.BLACK, images(a));
    }

    /**
     * A metal from a preset: gold, silver, copper or aluminium, with the RGB η and k that Mitsuba 3
     * uses for Au, Ag, Cu and Al (docs/materials.md).
     *
     * @param name   for messages
     * @param preset one of {@link #conductorPresets()}
     * @param alpha  GGX roughness α ≥ 0
     * @return the material
     * @throws IllegalArgumentException for an unknown preset
     */
    public static Material conductor(String name, String preset, double alpha) {
        return conductor(name, preset, Texture.constant(alpha));
    }

    /**
     * A metal from a preset with a roughness texture (its luminance, linear).
     *
     * @param name   for messages
     * @param preset one of {@link #conductorPresets()}
     * @param alpha  GGX roughness α ≥ 0
     * @return the material
     * @throws IllegalArgumentException for an unknown preset
     */
    public static Material conductor(String name, String preset, Texture alpha) {
        Rgb[] etaK = Conductor.PRESETS.get(preset.toLowerCase(Locale.ROOT));
        if (etaK == null) {
            throw new IllegalArgumentException("unknown conductor preset '" + preset + "' (known: " + String.join(", ", conductorPresets()) + ")");
        }
        return conductor(name, etaK[0], etaK[1], alpha);
    }

    /**
     * Rough glass: GGX reflection and transmission (Walter et al. 2007, Mitsuba's
     * {@code roughdielectric}); α = 0 is smooth glass, as {@link #dielectric(String, double)}.
     *
     * @param name  for messages
     * @param ior   index of refraction inside; 1 outside
     * @param alpha GGX roughness α ≥ 0
     * @return the material
     */
    public static Material dielectric(String name, double ior, double alpha) {
        return dielectric(name, ior, Texture.constant(alpha));
    }

    /**
     * Rough glass with a roughness texture (its luminance, linear).
     *
     * @param name  for messages
     * @param ior   index of refraction inside; 1 outside
     * @param alpha GGX roughness α ≥ 0
     * @return the material
     */
    public static Material dielectric(String name, double ior, Texture alpha) {
        dev.strahl.texture.Texture a = alpha.scalar(Channel.LUMINANCE);
        return new Material(name, RoughDielectric.of(ior, a), Rgb.BLACK, images(a));
    }

    /**
     * Starts a glTF 2.0 metallic–roughness material (the specification's Appendix B BRDF, with
     * KHR_materials_specular, _transmission and _emissive_strength): white base colour,
     * metallic 1 and roughness 1 as glTF's defaults, specular 1, white specular colour, no
     * transmission, ior 1.5, no emission.
     *
     * @param name for messages
     * @return a builder
     */
    public static PrincipledBuilder principled(String name) {
        return new PrincipledBuilder(name);
    }

    /**
     * The parameters of a glTF metallic–roughness material; every one may be a texture. Colours
     * are read sRGB-decoded unless the texture is {@link Texture#linear()}; numbers from the
     * texture's luminance unless a channel is given, as glTF's metallicRoughness texture keeps
     * roughness in G and metallic in B ({@link #metallicRoughness}).
     */
    public static final class PrincipledBuilder {
        private final String name;
        private dev.strahl.texture.Texture baseColor = dev.strahl.texture.Texture.of(Rgb.WHITE);
        private dev.strahl.texture.Texture metallic = dev.strahl.texture.Texture.of(1);
        private dev.strahl.texture.Texture roughness = dev.strahl.texture.Texture.of(1);
        private dev.strahl.texture.Texture specular = dev.strahl.texture.Texture.of(1);
        private dev.strahl.texture.Texture specularColor = dev.strahl.texture.Texture.of(Rgb.WHITE);
        private dev.strahl.texture.Texture transmission = dev.strahl.texture.Texture.of(0);
        private double ior = 1.5;
        private Rgb emission = Rgb.BLACK;

        private PrincipledBuilder(String name) {
            this.name = Objects.requireNonNull(name, "name");
        }

        /**
         * The base colour.
         *
         * @param colour linear RGB, each channel in [0, 1]
         * @return this builder
         */
        public PrincipledBuilder baseColor(Rgb colour) {
            checkUnit(colour, "baseColor");
            baseColor = dev.strahl.texture.Texture.of(colour);
            return this;
        }

        /**
         * The base colour as a texture.
         *
         * @param texture a colour texture
         * @return this builder
         */
        public PrincipledBuilder baseColor(Texture texture) {
            baseColor = texture.colour();
            return this;
        }

        /**
         * Metallic: 0 a dielectric, 1 a metal.
         *
         * @param value in [0, 1]
         * @return this builder
         */
        public PrincipledBuilder metallic(double value) {
            metallic = dev.strahl.texture.Texture.of(unit(value, "metallic"));
            return this;
        }

        /**
         * Metallic as a texture (its luminance).
         *
         * @param texture a linear texture
         * @return this builder
         */
        public PrincipledBuilder metallic(Texture texture) {
            metallic = texture.scalar(Channel.LUMINANCE);
            return this;
        }

        /**
         * Perceptual roughness; GGX α = roughness².
         *
         * @param value in [0, 1]
         * @return this builder
         */
        public PrincipledBuilder roughness(double value) {
            roughness = dev.strahl.texture.Texture.of(unit(value, "roughness"));
            return this;
        }

        /**
         * Roughness as a texture (its luminance).
         *
         * @param texture a linear texture
         * @return this builder
         */
        public PrincipledBuilder roughness(Texture texture) {
            roughness = texture.scalar(Channel.LUMINANCE);
            return this;
        }

        /**
         * glTF's metallicRoughness texture: roughness from its G channel, metallic from its B channel.
         *
         * @param texture a linear texture
         * @return this builder
         */
        public PrincipledBuilder metallicRoughness(Texture texture) {
            roughness = texture.scalar(Channel.G);
            metallic = texture.scalar(Channel.B);
            return this;
        }

        /**
         * KHR_materials_specular's specular factor: the strength of the dielectric's specular layer (0: a pure Lambertian base).
         *
         * @param value in [0, 1]
         * @return this builder
         */
        public PrincipledBuilder specular(double value) {
            specular = dev.strahl.texture.Texture.of(unit(value, "specular"));
            return this;
        }

        /**
         * The specular factor as a texture (its luminance).
         *
         * @param texture a linear texture
         * @return this builder
         */
        public PrincipledBuilder specular(Texture texture) {
            specular = texture.scalar(Channel.LUMINANCE);
            return this;
        }

        /**
         * KHR_materials_specular's specular colour, which tints the dielectric's f0.
         *
         * @param colour linear RGB, each channel ≥ 0
         * @return this builder
         */
        public PrincipledBuilder specularColor(Rgb colour) {
            if (colour.r() < 0 || colour.g() < 0 || colour.b() < 0) {
                throw new IllegalArgumentException("specularColor must not be negative, got " + colour + " for material '" + name + "'");
            }
            specularColor = dev.strahl.texture.Texture.of(colour);
            return this;
        }

        /**
         * The specular colour as a texture.
         *
         * @param texture a colour texture
         * @return this builder
         */
        public PrincipledBuilder specularColor(Texture texture) {
            specularColor = texture.colour();
            return this;
        }

        /**
         * KHR_materials_transmission's factor: the part of the dielectric base that is transmitted (thin-walled).
         *
         * @param value in [0, 1]
         * @return this builder
         */
        public PrincipledBuilder transmission(double value) {
            transmission = dev.strahl.texture.Texture.of(unit(value, "transmission"));
            return this;
        }

        /**
         * The transmission factor as a texture (its luminance).
         *
         * @param texture a linear texture
         * @return this builder
         */
        public PrincipledBuilder transmission(Texture texture) {
            transmission = texture.scalar(Channel.LUMINANCE);
            return this;
        }

        /**
         * The index of refraction, which sets the dielectric's f0 = ((ior − 1)/(ior + 1))².
         *
         * @param value positive
         * @return this builder
         */
        public PrincipledBuilder ior(double value) {
            if (!(value > 0) || !Double.isFinite(value)) {
                throw new IllegalArgumentException("ior must be positive, got " + value + " for material '" + name + "'");
            }
            ior = value;
            return this;
        }

        /**
         * Emitted radiance: colour × strength (glTF's emissiveFactor and KHR_materials_emissive_strength).
         *
         * @param colour   linear RGB, not negative
         * @param strength a factor ≥ 0
         * @return this builder
         */
        public PrincipledBuilder emission(Rgb colour, double strength) {
            if (!(strength >= 0) || !Double.isFinite(strength)) {
                throw new IllegalArgumentException("emission strength must be >= 0, got " + strength + " for material '" + name + "'");
            }
            emission = colour.scale(strength);
            return this;
        }

        /**
         * The material.
         *
         * @return a new material
         */
        public Material build() {
            return new Material(name, new Principled(baseColor, metallic, roughness, specular, specularColor, transmission, ior), emission,
                    images(baseColor, metallic, roughness, specular, specularColor, transmission));
        }

        private double unit(double value, String what) {
            if (!(value >= 0 && value <= 1)) {
                throw new IllegalArgumentException(what + " must lie in [0, 1], got " + value + " for material '" + name + "'");
            }
            return value;
        }

        private void checkUnit(Rgb c, String what) {
            if (c.r() < 0 || c.g() < 0 || c.b() < 0 || c.max() > 1) {
                throw new IllegalArgumentException(what + " must lie in [0, 1], got " + c + " for material '" + name + "'");
            }
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
        return new Material(name, bsdf, radiance, images);
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
