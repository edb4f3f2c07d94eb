package dev.strahl.io.gltf;

import dev.strahl.codec.Printable;
import dev.strahl.image.Rgb;
import dev.strahl.scene.Material;
import dev.strahl.scene.SceneException;
import dev.strahl.scene.Texture;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeSet;
import java.util.stream.Collectors;

/**
 * glTF materials as strahl's {@code principled} material (glTF's own BRDF): pbrMetallicRoughness,
 * emission (emissiveFactor × KHR_materials_emissive_strength), KHR_materials_specular,
 * _transmission and _ior; normalTexture as a normal map, alphaMode MASK (and BLEND, as MASK) as an
 * alpha cut-out. Every texture is multiplied by its factor, as the specification says
 * (baseColorFactor × baseColorTexture, roughnessFactor × G and metallicFactor × B of the
 * metallicRoughnessTexture, emissiveFactor × emissiveTexture, transmissionFactor × R of the
 * transmissionTexture, specularFactor × A of the specularTexture, specularColorFactor ×
 * specularColorTexture): {@code Texture.scaled}. Everything is two-sided ({@code doubleSided} makes
 * no difference).
 */
final class GltfMaterials {
    /** glTF's default material (§3.9.6): white, metallic 1, roughness 1. */
    static final Material DEFAULT = Material.principled("glTF default").build();

    /** The textures strahl reads, as (the object holding it: the material, pbrMetallicRoughness or an extension; its key). */
    private static final String[][] SLOTS = {{"pbrMetallicRoughness", "baseColorTexture"}, {"pbrMetallicRoughness", "metallicRoughnessTexture"},
        {null, "normalTexture"}, {null, "emissiveTexture"}, {"KHR_materials_specular", "specularTexture"},
        {"KHR_materials_specular", "specularColorTexture"}, {"KHR_materials_transmission", "transmissionTexture"}};

    private final GltfDocument doc;
    private final GltfTextures textures;
    private final Map<Integer, Material> built = new HashMap<>();
    private final Map<Integer, Integer> uvSets = new HashMap<>();

    GltfMaterials(GltfDocument doc) {
        this.doc = doc;
        this.textures = new GltfTextures(doc);
    }

    /** Material {@code index}, or the default material for -1 (built once). */
    Material material(int index) throws SceneException {
        if (index < 0) {
            return DEFAULT;
        }
        Material done = built.get(index);
        if (done == null) {
            GltfJson m = doc.root.array("materials").get(index);
            try {
                done = build(m, m.string("name", "materials[" + index + "]"));
            } catch (IllegalArgumentException e) {
                throw m.error(Printable.line(e.getMessage()));
            }
            built.put(index, done);
        }
        return done;
    }

    private Material build(GltfJson m, String name) throws SceneException {
        Material.PrincipledBuilder b = Material.principled(name);
        double baseAlpha = 1;
        GltfJson pbr = m.get("pbrMetallicRoughness");
        if (pbr != null) {
            double[] base = pbr.numbers("baseColorFactor", 4, new double[] {1, 1, 1, 1});
            baseAlpha = base[3];
            Rgb baseFactor = new Rgb(unit(pbr, "baseColorFactor", base[0]), unit(pbr, "baseColorFactor", base[1]),
                    unit(pbr, "baseColorFactor", base[2]));
            Texture baseTexture = texture(pbr, "baseColorTexture", name);
            if (baseTexture != null) {
                b.baseColor(baseTexture.scaled(baseFactor));
            } else {
                b.baseColor(baseFactor);
            }
            double metallic = unit(pbr, "metallicFactor", pbr.number("metallicFactor", 1));
            double roughness = unit(pbr, "roughnessFactor", pbr.number("roughnessFactor", 1));
            Texture mr = texture(pbr, "metallicRoughnessTexture", name);
            if (mr != null) {
                b.metallicRoughness(mr.linear().scaled(new Rgb(1, roughness, metallic)));      // G × roughness, B × metallic
            } else {
                b.metallic(metallic).roughness(roughness);
            }
        }
        double[] emissive = m.numbers("emissiveFactor", 3, new double[] {0, 0, 0});
        for (double e : emissive) {
            unit(m, "emissiveFactor", e);
        }
        double strength = 1;
        GltfJson es = GltfTextures.extension(m, "KHR_materials_emissive_strength");
        if (es != null) {
            strength = es.number("emissiveStrength", 1);
            if (!(strength >= 0) || !Double.isFinite(strength)) {
                throw es.error("emissiveStrength must be >= 0, got " + strength);
            }
        }
        Rgb emissiveFactor = new Rgb(emissive[0], emissive[1], emissive[2]);
        Texture emissiveTexture = texture(m, "emissiveTexture", name);
        if (emissiveTexture != null && !emissiveFactor.isBlack()) {
            b.emission(emissiveTexture.scaled(emissiveFactor), strength);
        } else {
            b.emission(emissiveFactor, strength);                   // a black factor (the default) emits nothing, textured or not
        }
        specular(m, b, name);
        GltfJson tr = GltfTextures.extension(m, "KHR_materials_transmission");
        if (tr != null) {
            double factor = unit(tr, "transmissionFactor", tr.number("transmissionFactor", 0));
            Texture t = texture(tr, "transmissionTexture", name);
            if (t != null && factor > 0) {
                b.transmission(t.channel(0).times(factor));            // R × transmissionFactor
            } else {
                b.transmission(factor);
            }
        }
        GltfJson ior = GltfTextures.extension(m, "KHR_materials_ior");
        if (ior != null) {
            double value = ior.number("ior", 1.5);
            if (value == 0) {
                doc.noteOnce(ior.path() + ": ior 0 (a perfect mirror) is not supported: 1.5 used");
            } else if (!(value >= 1) || !Double.isFinite(value)) {
                throw ior.error("ior must be >= 1 (or 0), got " + value);
            } else {
                b.ior(value);
            }
        }
        Material material = b.build();
        GltfJson normal = m.get("normalTexture");
        Texture normalMap = texture(m, "normalTexture", name);
        if (normalMap != null) {
            double scale = normal.number("scale", 1);
            material = material.withNormalMap(normalMap.linear(), scale);
        }
        return alphaCutout(m, material, baseAlpha, name);
    }

    /**
     * alphaMode MASK: absent where baseColorTexture.alpha × baseColorFactor.alpha &lt; alphaCutoff,
     * written as texture.alpha &lt; cutoff / factor; BLEND is treated as MASK at 0.5, with a note.
     */
    private Material alphaCutout(GltfJson m, Material material, double factor, String name) throws SceneException {
        String alpha = m.string("alphaMode", "OPAQUE");
        if (!alpha.equals("OPAQUE") && !alpha.equals("MASK") && !alpha.equals("BLEND")) {
            throw m.get("alphaMode").error("unknown alphaMode " + m.get("alphaMode").quoted() + " (known: OPAQUE, MASK, BLEND)");
        }
        if (alpha.equals("OPAQUE")) {
            return material;
        }
        double cutoff = 0.5;
        if (alpha.equals("BLEND")) {
            doc.noteOnce("alphaMode BLEND is rendered as MASK with alphaCutoff 0.5 (" + m.path() + ")");
        } else {
            cutoff = m.number("alphaCutoff", 0.5);
            if (!(cutoff >= 0) || !Double.isFinite(cutoff)) {
                throw m.get("alphaCutoff").error("must be >= 0, got " + cutoff);
            }
        }
        unit(m, "baseColorFactor", factor);
        GltfJson pbr = m.get("pbrMetallicRoughness");
        Texture base = pbr == null ? null : texture(pbr, "baseColorTexture", name);
        if (cutoff == 0) {
            return material;                             // alpha < 0 nowhere
        }
        if (base == null || !base.hasAlpha()) {
            return material.withAlphaCutout(Texture.constant(factor < cutoff ? 0 : 1), 0.5);
        }
        double scaled = cutoff / factor;                  // alpha × factor < cutoff ⇔ alpha < cutoff / factor
        return scaled > 1 ? material.withAlphaCutout(Texture.constant(0), 0.5) : material.withAlphaCutout(base.alpha(), scaled);
    }

    private void specular(GltfJson m, Material.PrincipledBuilder b, String name) throws SceneException {
        GltfJson sp = GltfTextures.extension(m, "KHR_materials_specular");
        if (sp == null) {
            return;
        }
        Texture t = texture(sp, "specularTexture", name);
        double factor = unit(sp, "specularFactor", sp.number("specularFactor", 1));
        if (t != null && factor > 0) {
            b.specular(t.alpha().times(factor));                      // A × specularFactor
        } else {
            b.specular(factor);
        }
        double[] colour = sp.numbers("specularColorFactor", 3, new double[] {1, 1, 1});
        if (!(colour[0] >= 0 && colour[1] >= 0 && colour[2] >= 0) || !Double.isFinite(colour[0] + colour[1] + colour[2])) {
            throw sp.get("specularColorFactor").error("must be finite and not negative");
        }
        Rgb colourFactor = new Rgb(colour[0], colour[1], colour[2]);
        Texture ct = texture(sp, "specularColorTexture", name);
        if (ct != null) {
            b.specularColor(ct.scaled(colourFactor));
        } else {
            b.specularColor(colourFactor);
        }
    }

    /**
     * The coordinate set (n of TEXCOORD_n) that the primitives of material {@code index} are read
     * with: strahl keeps one set per mesh, and every texture of a material is looked up at it. It is
     * the set the material's textures read (TEXCOORD_0 for the default material and for a material
     * without textures); a material whose textures read different sets gets the first one's (in the
     * order of {@link #SLOTS}: the base colour's if it has one), with a note. occlusionTexture is not
     * read by strahl and does not count.
     */
    int uvSet(int index) throws SceneException {
        if (index < 0) {
            return 0;
        }
        Integer known = uvSets.get(index);
        if (known != null) {
            return known;
        }
        GltfJson m = doc.root.array("materials").get(index);
        TreeSet<Integer> sets = new TreeSet<>();
        int chosen = -1;
        String chosenKey = null;
        for (String[] slot : SLOTS) {
            GltfJson parent = slot[0] == null ? m : slot[0].startsWith("KHR_") ? GltfTextures.extension(m, slot[0]) : m.get(slot[0]);
            GltfJson info = parent == null ? null : parent.get(slot[1]);
            if (info != null) {
                int set = GltfTextures.texCoord(info);
                sets.add(set);
                if (chosen < 0) {
                    chosen = set;
                    chosenKey = slot[1];
                }
            }
        }
        if (sets.size() > 1) {
            doc.noteOnce(m.path() + ": its textures read " + sets.stream().map(s -> "TEXCOORD_" + s).collect(Collectors.joining(" and "))
                    + "; strahl keeps one coordinate set per mesh, so all read TEXCOORD_" + chosen + " (the " + chosenKey + "'s)");
        }
        int set = Math.max(chosen, 0);
        uvSets.put(index, set);
        return set;
    }

    private Texture texture(GltfJson parent, String key, String material) throws SceneException {
        GltfJson info = parent.get(key);
        return info == null ? null : textures.texture(info, material);
    }

    private static double unit(GltfJson parent, String key, double v) throws SceneException {
        if (!(v >= 0 && v <= 1)) {
            throw (parent.get(key) != null ? parent.get(key) : parent).error("must lie in [0, 1], got " + GltfJson.format(v));
        }
        return v;
    }
}
