package dev.strahl.scene;

import dev.strahl.image.Rgb;
import dev.strahl.light.Emission;
import dev.strahl.material.Bsdf;
import dev.strahl.texture.Bitmap;
import dev.strahl.texture.TextureLookup;
import dev.strahl.world.SurfaceMaps;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * What a {@link Material} is inside: its BSDF, its emission (a constant radiance, or a radiance
 * texture times a scale), its tangent-space normal map and its alpha cut-out, and the images its
 * textures read. The public class keeps the factories and their checks; this record is what the
 * world is built from ({@link #emissionTable()}, {@link #maps()}).
 *
 * @param bsdf            the scattering function
 * @param emission        Le for a constant emitter; the scale of {@code emissionTexture} otherwise
 * @param emissionTexture the radiance texture (a colour, linear), or null
 * @param normalMap       linear RGB normal map, or null
 * @param normalScale     glTF's normalTexture.scale
 * @param alpha           the cut-out's scalar texture, or null
 * @param cutoff          the surface is absent where alpha &lt; cutoff
 * @param images          the images of all textures, each once
 */
record Surface(Bsdf bsdf, Rgb emission, TextureLookup emissionTexture, TextureLookup normalMap, double normalScale, TextureLookup alpha, double cutoff,
               List<Bitmap> images) {

    Surface {
        Objects.requireNonNull(bsdf, "bsdf");
        Objects.requireNonNull(emission, "emission");
        images = List.copyOf(images);
    }

    /** A plain surface: a BSDF and a constant emission. */
    static Surface of(Bsdf bsdf, Rgb emission, List<Bitmap> images) {
        return new Surface(bsdf, emission, null, null, 1, null, 0.5, images);
    }

    Surface withEmission(Rgb scale, TextureLookup texture) {
        return new Surface(bsdf, scale, texture, normalMap, normalScale, alpha, cutoff, union(images, texture));
    }

    Surface withNormalMap(TextureLookup map, double scale) {
        return new Surface(bsdf, emission, emissionTexture, map, scale, alpha, cutoff, union(images, map));
    }

    Surface withAlpha(TextureLookup a, double c) {
        return new Surface(bsdf, emission, emissionTexture, normalMap, normalScale, a, c, union(images, a));
    }

    /** Le as the user sees it: the constant, or the scale times the texture's mean. */
    Rgb meanEmission() {
        if (emissionTexture == null) {
            return emission;
        }
        Rgb m = emissionTexture.mean();
        return new Rgb(emission.r() * m.r(), emission.g() * m.g(), emission.b() * m.b());
    }

    /** The world's emission entry: Le(uv), black in the cut-out. */
    Emission emissionTable() {
        return Emission.of(emission, emissionTexture, alpha, cutoff);
    }

    /** The world's normal map and cut-out entry, null if the material has neither. */
    SurfaceMaps maps() {
        return normalMap == null && alpha == null ? null : new SurfaceMaps(normalMap, normalScale, alpha, cutoff);
    }

    /** The images behind some textures, each once (their sRGB-decoded twins where colours are read). */
    static List<Bitmap> images(TextureLookup... textures) {
        return union(List.of(), textures);
    }

    private static List<Bitmap> union(List<Bitmap> known, TextureLookup... textures) {
        List<Bitmap> out = new ArrayList<>(known);
        for (TextureLookup t : textures) {
            Bitmap b = t == null ? null : t.bitmap();
            if (b != null && out.stream().noneMatch(x -> x == b)) {
                out.add(b);
            }
        }
        return out;
    }

    /** Checks a number in [0, 1]. */
    static double unit(double value, String what, String material) {
        if (!(value >= 0 && value <= 1)) {
            throw new IllegalArgumentException(what + " must lie in [0, 1], got " + value + " for material '" + material + "'");
        }
        return value;
    }

    /** Checks a colour with channels in [0, 1]. */
    static Rgb unit(Rgb c, String what, String material) {
        if (c.r() < 0 || c.g() < 0 || c.b() < 0 || c.max() > 1) {
            throw new IllegalArgumentException(what + " must lie in [0, 1], got " + c + " for material '" + material + "'");
        }
        return c;
    }

    /** Checks a colour with channels ≥ 0. */
    static Rgb nonNegative(Rgb c, String what, String material) {
        if (c.r() < 0 || c.g() < 0 || c.b() < 0) {
            throw new IllegalArgumentException(what + " must not be negative, got " + c + " for material '" + material + "'");
        }
        return c;
    }

    /** Checks a finite factor ≥ 0. */
    static double nonNegative(double value, String what, String material) {
        if (!(value >= 0) || !Double.isFinite(value)) {
            throw new IllegalArgumentException(what + " must be >= 0, got " + value + " for material '" + material + "'");
        }
        return value;
    }

    /** A description of the maps for toString (empty if none). */
    String describeMaps() {
        return (emissionTexture != null ? ", emissionTexture=" + emissionTexture : "")
                + (normalMap != null ? ", normalMap=" + normalMap + (normalScale != 1 ? " x " + normalScale : "") : "")
                + (alpha != null ? ", alpha=" + alpha + " >= " + cutoff : "");
    }
}
