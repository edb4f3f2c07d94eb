package dev.strahl.scene;

import dev.strahl.texture.TextureLookup;
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
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Set;
import java.util.TreeSet;

/**
 * What a surface is made of: how it scatters light, the radiance it emits (black for
 * non-emitters; constant or a texture), and optionally a tangent-space normal map and an alpha
 * cut-out. Emission is one-sided, into the hemisphere of the geometric normal; every material
 * but glass scatters alike on both sides. Immutable; made by the factories below.
 */
public final class Material {
    private final String name;
    private final Surface surface;

    private Material(String name, Bsdf bsdf, Rgb emission) {
        this(name, Surface.of(bsdf, emission, List.of()));
    }

    private Material(String name, Bsdf bsdf, Rgb emission, List<Bitmap> images) {
        this(name, Surface.of(bsdf, emission, images));
    }

    private Material(String name, Surface surface) {
        this.name = Objects.requireNonNull(name, "name");
        this.surface = surface;
        Surface.nonNegative(surface.emission(), "emission", name);
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
     * The emitted radiance Le, linear RGB; for a textured emitter the strength times the
     * texture's mean.
     *
     * @return black for a material that does not emit
     */
    public Rgb emission() {
        return surface.meanEmission();
    }

    Bsdf bsdf() {
        return surface.bsdf();
    }

    /** The internals the world is built from. */
    Surface surface() {
        return surface;
    }

    /** The images the material's textures read, each once. */
    List<Bitmap> images() {
        return surface.images();
    }

    private static List<Bitmap> images(TextureLookup... textures) {
        return Surface.images(textures);
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
        TextureLookup a = albedo.colour();
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
        TextureLookup a = alpha.scalar(Channel.LUMINANCE);
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
        TextureLookup a = alpha.scalar(Channel.LUMINANCE);
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
    public static final class PrincipledBuilder extends PrincipledParameters {
        private PrincipledBuilder(String name) {
            super(name);
        }

        /**
         * The material.
         *
         * @return a new material
         */
        public Material build() {
            Surface s = Surface.of(new Principled(baseColor, metallic, roughness, specular, specularColor, transmission, ior), emission,
                    images(baseColor, metallic, roughness, specular, specularColor, transmission));
            return new Material(name, emissionTexture == null ? s : s.withEmission(emission, emissionTexture));
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
     * An invisible surface (Mitsuba 3's {@code null}): light passes it unchanged. It marks where
     * a participating medium begins and ends ({@link Scene.Builder#mediumBoundary}); only the
     * {@code path} integrator renders scenes that have such surfaces.
     *
     * @param name for messages
     * @return the material
     */
    public static Material nullSurface(String name) {
        return new Material(name, new dev.strahl.material.NullBsdf(), Rgb.BLACK);
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
        return new Material(name, surface.withEmission(radiance, null));
    }

    /**
     * The same surface emitting a texture: Le(u, v) = radiance(u, v) × strength (a one-sided area
     * light; the texture is sRGB-decoded unless {@link Texture#linear()}). Light sampling picks
     * its points by area and weighs the emitter by its mean radiance.
     *
     * @param radiance a colour texture
     * @param strength a factor ≥ 0
     * @return a new material
     */
    public Material withEmission(Texture radiance, double strength) {
        Surface.nonNegative(strength, "emission strength", name);
        if (radiance.isConstant()) {
            return withEmission(radiance.constantColour().scale(strength));
        }
        return new Material(name, surface.withEmission(Rgb.gray(strength), radiance.colour()));
    }

    /**
     * The same surface with a tangent-space normal map (glTF's normalTexture: linear texels,
     * n = 2·rgb − 1 with x along the texture's u direction, y along v, z along the surface
     * normal; tangents from the texture coordinates, MikkTSpace's convention). It tilts the
     * shading normal of every kind of material.
     *
     * @param map   the normal map, read as linear data whether or not it is {@link Texture#linear()}
     * @param scale glTF's normalTexture.scale: multiplies x and y, finite
     * @return a new material
     */
    public Material withNormalMap(Texture map, double scale) {
        if (!Double.isFinite(scale)) {
            throw new IllegalArgumentException("normal map scale must be finite, got " + scale + " for material '" + name + "'");
        }
        return new Material(name, surface.withNormalMap(map.data(), scale));
    }

    /**
     * The same surface with an alpha cut-out: where alpha(u, v) &lt; cutoff the surface is absent
     * (camera, bounce and shadow rays pass through it unchanged; an emitter emits nothing there).
     * The texture's luminance is read, or its alpha channel for {@link Texture#alpha()}.
     *
     * @param alpha  a scalar texture, linear
     * @param cutoff the threshold, in [0, 1]
     * @return a new material
     */
    public Material withAlphaCutout(Texture alpha, double cutoff) {
        Surface.unit(cutoff, "alpha cutoff", name);
        return new Material(name, surface.withAlpha(alpha.scalar(Channel.LUMINANCE), cutoff));
    }

    /**
     * Whether the material emits light.
     *
     * @return true if its emission is not black
     */
    public boolean isEmissive() {
        return !surface.meanEmission().isBlack();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Material m && m.name.equals(name) && m.surface.equals(surface);
    }

    @Override
    public int hashCode() {
        return Objects.hash(name, surface);
    }

    /** The name, the scattering function with all its parameters, the emission and the maps. */
    @Override
    public String toString() {
        return "Material[name=" + name + ", bsdf=" + surface.bsdf() + ", emission=" + surface.emission() + surface.describeMaps() + "]";
    }
}
