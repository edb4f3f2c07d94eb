package dev.strahl.io.obj;

import dev.strahl.image.Rgb;
import dev.strahl.scene.Material;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Texture;
import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * One {@code newmtl} block of an MTL file, reduced to the keys strahl renders (DESIGN.md §3 maps
 * them to BSDFs). Keys a file leaves out take the defaults of the MTL specification as most
 * readers apply them:
 * <ul>
 *   <li>{@code Kd} (diffuse reflectance) = (0.8, 0.8, 0.8)</li>
 *   <li>{@code Ks} (specular reflectance) = black</li>
 *   <li>{@code Ke} (emitted radiance) = black, i.e. not a light</li>
 *   <li>{@code Ns} (specular exponent) = 0</li>
 *   <li>{@code Ni} (index of refraction) = 1</li>
 *   <li>{@code illum} (illumination model) = 2</li>
 * </ul>
 *
 * @param name  the name after {@code newmtl}, not empty
 * @param kd    diffuse reflectance, components &ge; 0
 * @param ks    specular reflectance, components &ge; 0
 * @param ke    emitted radiance, components &ge; 0
 * @param ns    specular exponent, finite and &ge; 0
 * @param ni    index of refraction, finite and &gt; 0
 * <p>The PBR extension's {@code Pr} (roughness) and {@code Pm} (metallic), or their maps, make the
 * material a glTF {@code principled} one (base colour Kd or map_Kd, roughness default 1 and
 * metallic default 0 where only one is given).
 *
 * @param illum illumination model of the MTL specification, 0..10
 * @param pr    {@code Pr} in [0, 1], or null
 * @param pm    {@code Pm} in [0, 1], or null
 * @param mapKd {@code map_Kd}, or null
 * @param mapPr {@code map_Pr}, or null
 * @param mapPm {@code map_Pm}, or null
 */
public record MtlMaterial(String name, Rgb kd, Rgb ks, Rgb ke, double ns, double ni, int illum, Double pr, Double pm, MapRef mapKd,
                          MapRef mapPr, MapRef mapPm) {

    /**
     * A texture statement: the image file (resolved against the MTL file's folder) and its
     * {@code -s} scale and {@code -o} offset of the texture coordinates (u' = su·u + ou).
     *
     * @param file    the image
     * @param scaleU  su
     * @param scaleV  sv
     * @param offsetU ou
     * @param offsetV ov
     */
    public record MapRef(Path file, double scaleU, double scaleV, double offsetU, double offsetV) {
        /** The texture, or null (with a note) if the file does not exist; an unreadable image is an error naming it. */
        Texture load(String material, String key, Consumer<String> notes) throws SceneException {
            Texture t;
            try {
                t = Texture.image(file);
            } catch (NoSuchFileException e) {
                notes.accept("warning: material '" + material + "': " + key + " texture not found: " + file + " (ignored)");
                return null;
            } catch (IOException e) {
                String m = e.getMessage();
                throw new SceneException(file, "cannot read the " + key + " texture of material '" + material + "': "
                        + (m == null ? e.getClass().getSimpleName() : m.replace(file + ": ", "")), e);
            }
            if (scaleU != 1 || scaleV != 1) {
                t = t.withUvScale(scaleU, scaleV);
            }
            if (offsetU != 0 || offsetV != 0) {
                t = t.withUvOffset(offsetU, offsetV);
            }
            return t;
        }
    }

    /** A material without PBR keys or texture maps. */
    public MtlMaterial(String name, Rgb kd, Rgb ks, Rgb ke, double ns, double ni, int illum) {
        this(name, kd, ks, ke, ns, ni, illum, null, null, null, null, null);
    }

    public static final Rgb DEFAULT_KD = Rgb.gray(0.8);
    static final double DEFAULT_NS = 0;
    static final double DEFAULT_NI = 1;
    static final int DEFAULT_ILLUM = 2;
    static final int MAX_ILLUM = 10;

    public MtlMaterial {
        Objects.requireNonNull(name, "name");
        if (name.isEmpty()) {
            throw new IllegalArgumentException("material name must not be empty");
        }
        requireNonNegative("kd", kd);
        requireNonNegative("ks", ks);
        requireNonNegative("ke", ke);
        if (!(ns >= 0) || !Double.isFinite(ns)) {
            throw new IllegalArgumentException("ns must be finite and >= 0, got " + ns);
        }
        if (!(ni > 0) || !Double.isFinite(ni)) {
            throw new IllegalArgumentException("ni must be finite and > 0, got " + ni);
        }
        if (illum < 0 || illum > MAX_ILLUM) {
            throw new IllegalArgumentException("illum must be 0.." + MAX_ILLUM + ", got " + illum);
        }
        if (pr != null && !(pr >= 0 && pr <= 1) || pm != null && !(pm >= 0 && pm <= 1)) {
            throw new IllegalArgumentException("Pr and Pm must lie in [0, 1], got " + pr + ", " + pm);
        }
    }

    /** Whether the material uses the PBR extension (it becomes a principled material). */
    boolean isPbr() {
        return pr != null || pm != null || mapPr != null || mapPm != null;
    }

    /** A material with the given name and every key at its default (see the class comment). */
    static MtlMaterial withDefaults(String name) {
        return new MtlMaterial(name, DEFAULT_KD, Rgb.BLACK, Rgb.BLACK, DEFAULT_NS, DEFAULT_NI, DEFAULT_ILLUM);
    }

    /**
     * The grey diffuse material, named "default", given to faces that name no material or one that
     * no material library defines.
     */
    static MtlMaterial defaultMaterial() {
        return withDefaults("default");
    }

    /** Whether the material emits light ({@code Ke} &gt; 0 in some channel). */
    boolean isEmissive() {
        return !ke.isBlack();
    }

    /**
     * The material this block describes, following the conventions table (docs/conventions.md):
     * illum 5 is a mirror of reflectance Ks, illum 7 smooth glass of IOR Ni, illum &le; 2 with
     * Ks &gt; 0 Kd·Lambert + Ks·Beckmann (Ns as Phong exponent), otherwise Lambertian with albedo
     * Kd. Ke &gt; 0 makes any of them emit. With {@code map_Kd}, a diffuse material's albedo (or a
     * principled one's base colour) is that image; with the PBR keys the material is principled.
     * What cannot be rendered as written is said in {@code notes}; a missing texture file is a
     * warning there (the material keeps its plain colour).
     *
     * @throws SceneException if a texture file exists but is not a readable PNG or JPEG image
     */
    public Material toMaterial(Consumer<String> notes) throws SceneException {
        Texture kdMap = mapKd == null ? null : mapKd.load(name, "map_Kd", notes);
        Material m;
        if (isPbr()) {
            Texture prMap = mapPr == null ? null : mapPr.load(name, "map_Pr", notes);
            Texture pmMap = mapPm == null ? null : mapPm.load(name, "map_Pm", notes);
            var b = Material.principled(name).baseColor(clampToOne(kd, "Kd", notes))
                    .roughness(pr != null ? pr : 1).metallic(pm != null ? pm : 0);
            if (kdMap != null) {
                b.baseColor(kdMap);
            }
            if (prMap != null) {
                b.roughness(prMap);
            }
            if (pmMap != null) {
                b.metallic(pmMap);
            }
            m = b.build();
        } else if (illum == 5) {
            m = Material.mirror(name, clampToOne(ks, "Ks", notes));
        } else if (illum == 7) {
            m = Material.dielectric(name, ni);
        } else {
            if (illum > 2) {
                notes.accept("material '" + name + "': illum " + illum + " is not supported; rendering it as illum 2");
            }
            if (kdMap != null && ks.isBlack()) {
                m = Material.diffuse(name, kdMap);
            } else {
                if (kdMap != null) {
                    notes.accept("material '" + name + "': map_Kd on a glossy material (Ks > 0) is not supported; using Kd");
                }
                m = ks.isBlack() ? Material.diffuse(name, clampToOne(kd, "Kd", notes)) : Material.glossy(name, kd, ks, ns);
            }
        }
        return m.withEmission(ke);
    }

    private Rgb clampToOne(Rgb c, String key, Consumer<String> notes) {
        if (c.max() <= 1) {
            return c;
        }
        notes.accept("material '" + name + "': " + key + " " + c + " reflects more than it receives; clamped to 1");
        return new Rgb(Math.min(c.r(), 1), Math.min(c.g(), 1), Math.min(c.b(), 1));
    }

    private static void requireNonNegative(String key, Rgb c) {
        Objects.requireNonNull(c, key);
        if (c.r() < 0 || c.g() < 0 || c.b() < 0) {
            throw new IllegalArgumentException(key + " components must be >= 0, got " + c);
        }
    }
}
