package dev.strahl.io.obj;

import dev.strahl.image.Rgb;
import dev.strahl.scene.Material;
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
 * @param illum illumination model of the MTL specification, 0..10
 */
public record MtlMaterial(String name, Rgb kd, Rgb ks, Rgb ke, double ns, double ni, int illum) {

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
     * Kd. Ke &gt; 0 makes any of them emit. What cannot be rendered as written is said in
     * {@code notes}.
     */
    public Material toMaterial(Consumer<String> notes) {
        Material m;
        if (illum == 5) {
            m = Material.mirror(name, clampToOne(ks, "Ks", notes));
        } else if (illum == 7) {
            m = Material.dielectric(name, ni);
        } else {
            if (illum > 2) {
                notes.accept("material '" + name + "': illum " + illum + " is not supported; rendering it as illum 2");
            }
            m = ks.isBlack() ? Material.diffuse(name, clampToOne(kd, "Kd", notes)) : Material.glossy(name, kd, ks, ns);
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
